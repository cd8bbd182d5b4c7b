// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Between passes 2 and 4, per pixel: the umbra early-out (section 5: D = 0
// where the whole neighbourhood is shadowed) and the optional dilation of D
// (pass 3), which the prepare pass (vtkContactPrepareFS.glsl) writes for the
// multi-pass and Gaussian blurs, and the PCF pass computes itself.
// Both neighbourhood questions are answered by the tile classification
// (vtkContactTileSpreadFS.glsl) with one fetch: a software rasterizer shades
// both arms of a branch, but a loop ends once no pixel of a group runs it.
// Uses: vtkShadowScreenCodeFS.glsl, vtkContactCommonFS.glsl.
uniform sampler2D contactTiles;

#if CONTACT_WIDTHS
// Compiled in for receivers that refine (vtkContactRefine(), vtkContactUpsampleFS.glsl): the
// penumbra's width in pixels on the receiver for a D, coded with the
// pixel. A kernel's (clamped to the maximum), or, counting multi-pass
// blurs, 4 sigma of their summed variances (contactPassVariances[k]: that
// of k passes).
uniform float contactPassVariances[65];

float vtkContactWidth(float d)
{
  if (contactCountsPasses)
  {
    int k = int(min(d, 63.0));
    return 4.0 * sqrt(mix(contactPassVariances[k], contactPassVariances[k + 1], d - float(k)));
  }
  return min(d, float(contactMaximumKernel));
}
#endif

// The prepare pass's texel of `pixel` (read from the distance map,
// contactMap): D settled by the umbra early-out and the dilation, and g the
// flags of the receivers' guided lookup. The PCF variant's one pass
// (vtkContactPCFFS.glsl) computes it in place of a prepare pass.
vec4 vtkContactPrepareTexel(ivec2 pixel)
{
  vec4 c = vtkContactFetch(pixel);
  float d = c.a;
  vec2 tiles = texelFetch(contactTiles, pixel / contactTileSize, 0).xy;
  if (d > 0.0 && contactEarlyOut && tiles.x >= 1.0)
  {
    d = 0.0;
  }
  else if (c.r == 1.0 && c.b > 0.0 && contactDilation)
  {
    // Lit pixels near a shadow take the weighted mean D of the shadowed taps.
    // D varies slowly: 8 taps are enough (tap 0, this lit pixel, never
    // counts). None without a shadow in reach.
    float sum = 0.0;
    float weights = 0.0;
    int count = tiles.y > 0.0 ? CONTACT_DILATION_TAPS : 0;
    for (int i = 1; i < count; ++i)
    {
      vec3 tap = contactDilationTaps[i];
      vec4 t = vtkContactFetch(pixel + ivec2(tap.xy));
      if (t.r < 1.0 && vtkContactSameSurface(c, t))
      {
        sum += tap.z * t.a;
        weights += tap.z;
      }
    }
    d = weights > 0.0 ? sum / weights : 0.0;
  }
  // Below contactSmallestD (a pixel for kernels, a tenth of a pass) a blur
  // changes nothing worth the pixel's sharper full-resolution hard shadow in
  // the receivers.
  d = d >= contactSmallestD ? d : 0.0;
  // g: blurred, with the flags of the receivers' guided lookup: on which
  // side of its hard edge the pixel lies, and its penumbra's width.
#if CONTACT_WIDTHS
  float flags = c.r + 2.0 * vtkShadowWidthCode(vtkContactWidth(d));
#else
  float flags = c.r;
#endif
  return vec4(c.r, d > 0.0 ? 1.0 + flags : 0.0, c.b, d);
}
