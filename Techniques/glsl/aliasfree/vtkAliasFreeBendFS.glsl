// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Bent normals for receivers' fragments (Sintorn et al., section 6): a
// light's diffuse cosine l_f (VTK's `df`, from the interpolated normal)
// becomes alpha l_f + (1 - alpha) l_bend, alpha = min(1, max(c l_bend, 0)),
// c = 3, l_bend interpolated from the vertices (vtkAliasFreeBendVS.glsl).
// Where every face around lies towards the light (l_bend >= 1/3) Phong is
// kept; towards a face that turns away it fades to l_bend <= 0, black, as
// the exact shadow of that face is. Returned as a factor on the light's
// Phong terms, never above 1: bending only removes light.
// Uses: ALIASFREE_BEND_LIGHTS.

in vec2 aliasfreeBendVSOutput[ALIASFREE_BEND_LIGHTS];

float aliasfreeBentScale(float df, vec2 range)
{
  // Two-sided lighting flips the normal on back faces: their faces' normals
  // are flipped too, and min dot(l, -n_F) = -max dot(l, n_F).
  float bend = gl_FrontFacing ? range.x : -range.y;
  float alpha = clamp(3.0 * bend, 0.0, 1.0);
  float bent = max(alpha * df + (1.0 - alpha) * bend, 0.0);
  return df > 0.0 ? min(bent / df, 1.0) : 1.0;
}
