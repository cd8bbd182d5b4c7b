// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Between passes 2 and 4, multi-pass and Gaussian variants: every pixel's
// texel with D settled (vtkContactPrepareTexelFS.glsl), into the other
// ping-pong buffer (the distance map holds the final value of pixels left
// unblurred); its code in the receivers' texture (final unless a blur
// follows); and a depth that lets multi-pass blur k (drawn at depth
// 1 - k / 256) through only where D > k - 1: the ceil(D) passes that blur the
// pixel and one more that copies its final value into the other buffer.
// Elsewhere depth 1: no blur touches it.
// Uses: vtkShadowScreenCommonFS.glsl, vtkShadowScreenCodeFS.glsl,
// vtkContactCommonFS.glsl, vtkContactPrepareTexelFS.glsl.
void main()
{
  vec4 texel = vtkContactPrepareTexel(vtkShadowScreenPixel());
  float d = texel.a;
  gl_FragData[0] = texel;
  gl_FragData[1] = vec4(vtkShadowPackTexel(texel));
  gl_FragDepth = d > 0.0 ? 1.0 - (min(ceil(d), 254.0) + 1.0) / 256.0 : 1.0;
}
