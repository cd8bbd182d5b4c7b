//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Smoothie edges and corners built on the CPU for one frustum (the pass's
// BuildOnGPU off): each vertex is its silhouette vertex, in model space,
// moved in screen space by its offset at the same depth, as
// vtkSmoothieEdgesGS.glsl moves them.
// Uses: vtkSmoothieEdgesFS.glsl (these outputs).

in vec3 vtkShadowVertexMC;
in vec2 smoothieOffsetIn; // screen units (2 across the map)
in vec4 smoothieShapeIn;  // as vtkSmoothieEdgesGS.glsl's smoothieShape
in float smoothieWidthIn;

uniform mat4 vtkShadowModelToClip;
uniform mat4 smoothieClipToWorld;

out vec3 smoothieWorld;
flat out vec4 smoothieShape;
flat out float smoothieWidth;

void main()
{
  vec4 c = vtkShadowModelToClip * vec4(vtkShadowVertexMC, 1.0);
  c.xy += smoothieOffsetIn * c.w;
  vec4 world = smoothieClipToWorld * c;
  smoothieWorld = world.xyz / world.w;
  smoothieShape = smoothieShapeIn;
  smoothieWidth = smoothieWidthIn;
  gl_Position = c;
}
