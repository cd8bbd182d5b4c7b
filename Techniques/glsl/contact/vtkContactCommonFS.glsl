// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Shared by the contact-hardening passes (after vtkShadowScreenCommonFS).
// Every map holds the framework's visibility layout
// (vtkShadowScreenBuffers::GetVisibility()), which vtkShadowPackTexel()
// codes for the receivers: r = visibility 1 - S, g = 0 where no blur touches
// the pixel (receivers keep their own full-resolution hard shadow there),
// else 1 + the flags of vtkShadowPackTexel() (the receivers' guide: the
// pixel's hard side, its penumbra's width; vtkShadowScreenVisibility()),
// b = the surface's camera distance (0 on background), a = D (<= 0: not
// blurred).
// The passes' settings are constants compiled in before this file
// (vtkContactHardeningShadowPass::ScreenPassConstants()), as llvmpipe loads
// a uniform for every fragment and use: contactDepthTolerance (relative, of
// a camera distance), contactDebugView, contactMaximumKernel (the widest
// kernel, pixels), contactTileSize, contactEarlyOut and contactEarlyOutTiles,
// contactDilation and contactDilationTiles (how many tiles their
// neighbourhoods reach), contactSmallestD, contactCountsPasses,
// CONTACT_WIDTHS, CONTACT_PARALLEL_CAMERA (a buffer pixel's world size is
// one length), and the dilation's CONTACT_DILATION_TAPS taps
// contactDilationTaps (offsets in whole pixels, and weights).
// Uses: vtkShadowScreenCodeFS.glsl (vtkShadowPackTexel).
uniform sampler2D contactMap;

vec4 vtkContactFetch(ivec2 pixel)
{
  ivec2 last = textureSize(contactMap, 0) - 1;
  return texelFetch(contactMap, clamp(pixel, ivec2(0), last), 0);
}

// Beyond the paper: taps on another surface (a depth discontinuity in the
// view) do not count, so shadows do not bleed across silhouettes.
bool vtkContactSameSurface(vec4 center, vec4 tap)
{
  return tap.b > 0.0 && abs(tap.b - center.b) <= contactDepthTolerance * center.b;
}

// Beyond the paper: kernels lie on the receiver, not on the screen. A tap
// `offset` pixels away is this far from the centre along the surface, in
// pixels (squared): the offset, and the change of camera distance in
// pixels' world size there. On a floor seen at elevation e a pixel up the
// screen moves 1 / sin(e) along it, and the distance by cot(e): the kernel
// is foreshortened along the slope and whole along the level lines, as the
// penumbra is.
// A buffer pixel's world size: itself with a parallel camera
// (CONTACT_PARALLEL_CAMERA), else per unit of camera distance.
uniform float contactPixelSize;

// `perPixel`: 1 / a pixel's world size at the centre (vtkContactPixelsPerLength()).
float vtkContactSurfaceDistance2(vec4 center, vec4 tap, vec2 offset, float perPixel)
{
  float along = (tap.b - center.b) * perPixel;
  return dot(offset, offset) + along * along;
}

float vtkContactPixelsPerLength(vec4 center)
{
#if CONTACT_PARALLEL_CAMERA
  return 1.0 / contactPixelSize;
#else
  return 1.0 / (contactPixelSize * center.b);
#endif
}

// The change of camera distance a pixel across, in pixels' world size, on
// each axis: from the neighbour right and above where it lies on the same
// surface, else 0 (the bounds this gives then are the whole disc's).
vec2 vtkContactSurfaceSlope(vec4 center, ivec2 pixel, float perPixel)
{
  vec4 right = vtkContactFetch(pixel + ivec2(1, 0));
  vec4 up = vtkContactFetch(pixel + ivec2(0, 1));
  float x = vtkContactSameSurface(center, right) ? right.b - center.b : 0.0;
  float y = vtkContactSameSurface(center, up) ? up.b - center.b : 0.0;
  return vec2(x, y) * perPixel;
}

// Pass 5: the receivers' code (vtkShadowPackTexel()) of a filtering texel
// `c` with its filtered visibility `v`, or of the debug view of the paper's
// figure 4 (lit 1, umbra 0.5, penumbra a dark 0.1) on every surface.
vec4 vtkContactOutput(vec4 c, float v)
{
  vec4 texel = vec4(v, c.g, c.b, 0.0);
  if (contactDebugView)
  {
    float marked = v >= 0.999 ? 1.0 : (v <= 0.001 ? 0.5 : 0.1);
    // The marks keep the hard side but no width: no receiver refines them.
    float g = c.g > 0.5 ? 1.0 + mod(c.g - 1.0, 2.0) : 1.0;
    texel = vec4(marked, c.b > 0.0 ? g : 0.0, c.b, 0.0);
  }
  return vec4(vtkShadowPackTexel(texel));
}
