// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Codes a light's visibility texture for the receivers
// (vtkShadowPackTexel(), vtkShadowScreenCodeFS.glsl), for techniques that
// draw visibility textures rather than the codes themselves.
// Uses: vtkShadowScreenCommonFS.glsl, vtkShadowScreenCodeFS.glsl.
uniform sampler2D vtkShadowVisibility;

void main()
{
  gl_FragData[0] =
    vec4(vtkShadowPackTexel(texelFetch(vtkShadowVisibility, vtkShadowScreenPixel(), 0)), 0.0, 0.0, 0.0);
}
