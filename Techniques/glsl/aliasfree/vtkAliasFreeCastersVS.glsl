// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Caster triangles for the alias-free map: world positions for the
// geometry shader (vtkAliasFreeCastersGS.glsl), which does the projecting;
// with ALIASFREE_EDGES, edges and their faces' normals.
// Uses: nothing.

in vec3 vtkShadowVertexMC;
uniform mat4 vtkShadowModelToWorld;
out vec3 aliasfreeWorldIn;
#ifdef ALIASFREE_EDGES
in vec4 aliasfreeFace0;
in vec3 aliasfreeFace1;
out vec4 aliasfreeFace0In;
out vec3 aliasfreeFace1In;
#endif

void main()
{
  aliasfreeWorldIn = (vtkShadowModelToWorld * vec4(vtkShadowVertexMC, 1.0)).xyz;
  gl_Position = vec4(aliasfreeWorldIn, 1.0);
#ifdef ALIASFREE_EDGES
  aliasfreeFace0In = aliasfreeFace0;
  aliasfreeFace1In = aliasfreeFace1;
#endif
}
