// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// The lookup table of sample-based visibility (Sintorn et al., section 4.2):
// for a plane, the bitmask of the light samples on its positive side. A
// plane is its unit normal n in the light's frame (its direction) and its
// distance d: light sample s (in the light's shape scaled to the unit ball;
// for directional lights, on the unit disc their cone of directions crosses
// at unit distance) is set when dot(n, s) > d.
// Only the hemisphere n.z >= 0 is stored: the opposite plane (-n, -d) reads
// the same cell and complements it, so that the two sides of an edge shared
// by two triangles split the samples exactly, with no crack between them.
// The mask of a cell is that of the plane at its centre.
// Used by vtkAliasFreeLookupBuildCS.glsl, vtkAliasFreeCastersFS.glsl and
// vtkAliasFreeListsCS.glsl (its resolve).
// Uses: nothing.

// The hemisphere's normals by their octahedral coordinates (no
// trigonometry): n / (|x| + |y| + z) is a point of the diamond
// |u| + |v| <= 1, turned by 45 degrees onto a square of 64 x 64 cells (about
// 2 degrees each); distances over [-1, 1] in 64 cells.
const int aliasfreeLookupSide = 64;
const int aliasfreeLookupDistances = 64;
uniform int aliasfreeWords; // 32-bit words a mask: light samples / 32

// The plane at the centre of `cell`.
void aliasfreeCellPlane(int cell, out vec3 n, out float d)
{
  int column = cell % aliasfreeLookupSide;
  int row = (cell / aliasfreeLookupSide) % aliasfreeLookupSide;
  int distance = cell / (aliasfreeLookupSide * aliasfreeLookupSide);
  vec2 square = (vec2(column, row) + 0.5) / float(aliasfreeLookupSide) * 2.0 - 1.0;
  vec2 diamond = 0.5 * vec2(square.x + square.y, square.x - square.y);
  n = normalize(vec3(diamond, 1.0 - abs(diamond.x) - abs(diamond.y)));
  d = (float(distance) + 0.5) / float(aliasfreeLookupDistances) * 2.0 - 1.0;
}

// Where the mask of plane (n, d) comes from: `cell` (-1: every word is
// `fill`), complemented by XOR with `flip`.
struct aliasfreePlaneMask
{
  int cell;
  uint fill;
  uint flip;
};

aliasfreePlaneMask aliasfreeFindCell(vec3 n, float d)
{
  aliasfreePlaneMask m;
  m.flip = 0u;
  if (n.z < 0.0)
  {
    n = -n;
    d = -d;
    m.flip = 0xffffffffu;
  }
  m.fill = d >= 1.0 ? 0u : 0xffffffffu; // every sample behind, or none
  m.cell = -1;
  if (abs(d) < 1.0)
  {
    vec2 diamond = n.xy / (abs(n.x) + abs(n.y) + n.z);
    vec2 square = vec2(diamond.x + diamond.y, diamond.x - diamond.y);
    ivec2 at = clamp(ivec2((square * 0.5 + 0.5) * float(aliasfreeLookupSide)), ivec2(0),
      ivec2(aliasfreeLookupSide - 1));
    int distance =
      clamp(int((d + 1.0) * 0.5 * float(aliasfreeLookupDistances)), 0, aliasfreeLookupDistances - 1);
    m.cell = at.x + aliasfreeLookupSide * (at.y + aliasfreeLookupSide * distance);
  }
  return m;
}

// World normals to the light's frame, scaled by the light's size and shape
// (spot lights: radius times the shape's scale; directional lights: the
// tangent of the angular radius across the axis, nothing along it).
uniform mat3 aliasfreeToLight;

// The light samples x with dot(m, x - q) > 0: x = c + T s for a spot light
// of centre c (`light`, w = 1), x - q = l + T s for directional lights (l
// towards the light, w = 0; T s across it), T the light's frame and size
// (aliasfreeToLight transposed), s a sample of the table.
aliasfreePlaneMask aliasfreeSide(vec3 m, vec3 q, vec4 light)
{
  vec3 n = aliasfreeToLight * m;
  float length = max(sqrt(dot(n, n)), 1.0e-30);
  vec3 centre = light.w > 0.5 ? light.xyz - q : light.xyz;
  return aliasfreeFindCell(n / length, -dot(m, centre) / length);
}

#ifndef ALIASFREE_LOOKUP_BUILD
layout(std430, binding = 6) readonly buffer aliasfreeLookupBuffer { uint aliasfreeLookup[]; };

bool aliasfreeEmpty(aliasfreePlaneMask m)
{
  return m.cell < 0 && (m.fill ^ m.flip) == 0u;
}

bool aliasfreeFull(aliasfreePlaneMask m)
{
  return m.cell < 0 && (m.fill ^ m.flip) == 0xffffffffu;
}

uint aliasfreeWord(aliasfreePlaneMask m, int word)
{
  return (m.cell < 0 ? m.fill : aliasfreeLookup[m.cell * aliasfreeWords + word]) ^ m.flip;
}
#endif
