// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Writing the receivers' texture: every screen-space pass gets this after
// vtkShadowScreenCommonFS.glsl, and a camera pass that writes codes itself
// declares it (uniforms: vtkShadowScreenBuffers::SetCodeUniforms()).
// Uses: nothing.

// The receivers' code of a visibility texel (r = visibility, g = 1 where r is
// valid, b = camera distance; vtkShadowScreenBuffers::BeginVisibility()):
// one float, an integer below 2^24, exact: the camera distance on a log
// scale in [1, 2047] (0: no surface), plus 2048 * visibility in [0, 254]
// (255: not valid), plus 2^19 times its penumbra's width
// (vtkShadowWidthCode()), negative where the texel's own hard shadow is lit:
// techniques whose receivers are guided by their own hard shadow
// (contact: vtkContactUpsampleFS.glsl) give them as
// g = 1 + lit + 2 * width on valid texels. A receiver's bilinear lookup then
// gathers the four codes around it in one fetch (textureGather) instead of
// fetching four texels, and tells the sides apart with one comparison.
uniform float vtkShadowLogNear;     // log2 of the smallest camera distance coded
uniform float vtkShadowCodesPerLog; // distance codes per unit of log2

float vtkShadowPackTexel(vec4 t)
{
  bool valid = t.g > 0.5;
  float visibility = valid ? floor(clamp(t.r, 0.0, 1.0) * 254.0 + 0.5) : 255.0;
  float flags = valid ? clamp(floor(t.g - 0.5), 0.0, 31.0) : 0.0;
  float width = floor(flags * 0.5);
  float distance = t.b > 0.0
    ? clamp(floor((log2(t.b) - vtkShadowLogNear) * vtkShadowCodesPerLog + 1.5), 1.0, 2047.0)
    : 0.0;
  float code = width * 524288.0 + visibility * 2048.0 + distance;
  return flags - 2.0 * width > 0.5 ? -code : code;
}

// A penumbra `width` buffer pixels wide on its receiver, in 4 bits: 0 for
// none (under a pixel and a half), else k in [1, 15] for 2^(k/2) pixels.
float vtkShadowWidthCode(float width)
{
  return width >= 1.5 ? clamp(floor(2.0 * log2(width) + 0.5), 1.0, 15.0) : 0.0;
}
