// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Builds the lookup table (vtkAliasFreeLookup.glsl): one invocation per
// 32-bit word of a cell's mask.
// Uses: vtkAliasFreeLookup.glsl (prepended by the pass, with
// ALIASFREE_LOOKUP_BUILD defined: this shader writes the table).

layout(local_size_x = 256) in;

layout(std430, binding = 4) readonly buffer aliasfreeLightSamplesBuffer
{
  vec4 aliasfreeLightSamples[]; // xyz: in the light's frame, unit ball or unit directions
};
layout(std430, binding = 6) writeonly buffer aliasfreeLookupBuffer
{
  uint aliasfreeLookup[];
};
uniform int aliasfreeCells;

void main()
{
  // Work groups in rows of at most 65535 (the dispatch's guaranteed limit).
  int index = int((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 256u +
    gl_LocalInvocationID.x);
  if (index >= aliasfreeCells * aliasfreeWords)
  {
    return;
  }
  int cell = index / aliasfreeWords;
  int word = index % aliasfreeWords;
  vec3 n;
  float d;
  aliasfreeCellPlane(cell, n, d);
  uint bits = 0u;
  for (int b = 0; b < 32; ++b)
  {
    if (dot(n, aliasfreeLightSamples[32 * word + b].xyz) > d)
    {
      bits |= 1u << uint(b);
    }
  }
  aliasfreeLookup[index] = bits;
}
