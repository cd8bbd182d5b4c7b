// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Pass 5 of the multi-pass variant in the debug view: the last blur's
// visibility marked as in the paper's figure 4. (Otherwise the prepare pass
// and the blurs write the receivers' codes themselves.)
// Uses: vtkShadowScreenCommonFS.glsl, vtkContactCommonFS.glsl.
void main()
{
  vec4 c = vtkContactFetch(vtkShadowScreenPixel());
  gl_FragData[0] = vtkContactOutput(c, c.r);
}
