// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Bent normals for receivers' vertices (Sintorn et al., section 6): per
// shadowed light, l_bend = min over the faces around this vertex of
// dot(l, n_F), l the unit vector towards the light's centre. Also the
// maximum, whose negation is l_bend of the faces' back sides (two-sided
// lighting flips the normal there). Both go to the fragment shader
// (vtkAliasFreeBendFS.glsl), interpolated.
// Uses: ALIASFREE_BEND_LIGHTS (the pass defines it), gl_VertexID as the
// input's point id (vtkOpenGLPolyDataMapper's vertex buffer holds the points
// in order).

uniform int aliasfreeBendReady;               // 0: no adjacency for this prop
uniform isamplerBuffer aliasfreeBendOffsets;  // per point: its first entry; one more at the end
uniform samplerBuffer aliasfreeBendNormals;   // the entries: adjacent faces' unit normals (model)
uniform mat4 aliasfreeBendModelToWorld;
uniform mat3 aliasfreeBendNormalToWorld;
uniform vec4 aliasfreeBendLights[ALIASFREE_BEND_LIGHTS]; // position (w = 1), or direction towards it (w = 0)
out vec2 aliasfreeBendVSOutput[ALIASFREE_BEND_LIGHTS];   // (min, max) of dot(l, n_F)

void aliasfreeBend(vec4 vertex)
{
  int first = 0, last = 0;
  if (aliasfreeBendReady == 1)
  {
    first = texelFetch(aliasfreeBendOffsets, gl_VertexID).r;
    last = texelFetch(aliasfreeBendOffsets, gl_VertexID + 1).r;
  }
  vec4 world = aliasfreeBendModelToWorld * vertex;
  vec3 p = world.xyz / world.w;
  vec3 towards[ALIASFREE_BEND_LIGHTS];
  for (int i = 0; i < ALIASFREE_BEND_LIGHTS; ++i)
  {
    vec4 light = aliasfreeBendLights[i];
    towards[i] = normalize(light.w > 0.5 ? light.xyz - p : light.xyz);
    // No faces (points, lines): nothing bends, (1, -1) leaves Phong alone.
    aliasfreeBendVSOutput[i] = vec2(1.0, -1.0);
  }
  // Each face's normal into the world once, against every light.
  for (int k = first; k < last; ++k)
  {
    vec3 n = normalize(aliasfreeBendNormalToWorld * texelFetch(aliasfreeBendNormals, k).xyz);
    for (int i = 0; i < ALIASFREE_BEND_LIGHTS; ++i)
    {
      float d = dot(towards[i], n);
      vec2 range = aliasfreeBendVSOutput[i];
      aliasfreeBendVSOutput[i] = k == first ? vec2(d) : vec2(min(range.x, d), max(range.y, d));
    }
  }
}
