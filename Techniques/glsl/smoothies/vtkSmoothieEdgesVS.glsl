//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Smoothies (Chan & Durand 2003, as Volokh's report implements them): each
// silhouette vertex goes on, in model space, to the geometry shader that
// builds the smoothie edges and corners in the light's screen space.
// Uses: vtkSmoothieEdgesGS.glsl (its inputs).

in vec3 vtkShadowVertexMC;
in vec4 smoothieNormalMC; // the edge's two face normals summed; w: 1 if a corner follows

out vec3 smoothieVertex;
out vec4 smoothieNormal;

void main()
{
  smoothieVertex = vtkShadowVertexMC;
  smoothieNormal = smoothieNormalMC;
  gl_Position = vec4(vtkShadowVertexMC, 1.0);
}
