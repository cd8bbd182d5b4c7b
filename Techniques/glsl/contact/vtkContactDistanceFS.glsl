// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Pass 2 (section 3.2): the distance map, run on every fragment of the
// camera depth pass (vtkSoftShadowPass::RenderCameraDepth()) for each of its
// CONTACT_LIGHTS lights: S from the hard shadow test, D from the occluder
// distance: (distance)^Dp * Dm, or, with the light's size, the penumbra
// width w = (d_receiver - d_blocker) * w_light / d_blocker (section 6) in
// pixels, as a kernel size (PCF, Gaussian) or a number of blur passes
// (multi-pass). Written in the filtering layout (vtkContactCommonFS.glsl),
// so that the map serves as one of the ping-pong buffers: r = 1 - S, g = 0
// (not blurred yet), b = the camera distance, a = D; the background stays
// as the pass clears it: lit, no surface (1, 0, 0, 0).
// Spot and directional lights: their map's raw depth (CONTACT_MAPS samplers
// without comparison); point lights: their cube map of squared distances
// (CONTACT_CUBES).
//
// The pass's choices are compiled in, not uniforms: CONTACT_LIGHT_SIZE (D
// from the light's size), CONTACT_COUNT_PASSES (D counts multi-pass blurs,
// at most CONTACT_PASS_LIMIT), CONTACT_CODES (the pass also writes the
// receivers' codes of settled pixels), CONTACT_PARALLEL_CAMERA (a pixel's
// world size is one length), and per light whether its map is a
// perspective one. A software rasterizer runs both arms of a branch, even
// on a uniform, and this code runs on every fragment the camera draws.
// Uses: vtkShadowNormalOffsetFS.glsl, vtkShadowCubeLookupFS.glsl,
// vtkShadowScreenCodeFS.glsl (with CONTACT_CODES).
#if CONTACT_MAPS > 0
uniform sampler2D contactLightDepth[CONTACT_MAPS];
#endif
#if CONTACT_CUBES > 0
uniform samplerCube contactLightCube[CONTACT_CUBES];
#endif
// Spot and directional maps from view coordinates (vtkShadowOffsetInMap).
uniform mat4 contactViewToMap[CONTACT_LIGHTS];
uniform vec4 contactLightVC[CONTACT_LIGHTS];
uniform vec4 contactOffsetVC[CONTACT_LIGHTS];
uniform vec2 contactDepthRange[CONTACT_LIGHTS]; // near, far
// Parallel maps: a unit of depth in world lengths (far - near), and that
// times the light's size (a depth difference to the penumbra's width).
uniform vec2 contactParallelScale[CONTACT_LIGHTS];
uniform vec3 contactCubeCenter[CONTACT_LIGHTS];
uniform float contactCubeRange[CONTACT_LIGHTS];
uniform float contactLightSize[CONTACT_LIGHTS]; // spot, point: diameter; directional: 2 tan(angular radius)
uniform float contactCubeTexel;
uniform float contactDistanceBias;
uniform float contactNormalBias;

#if CONTACT_LIGHT_SIZE
// A buffer pixel's world size: itself with a parallel camera
// (CONTACT_PARALLEL_CAMERA), else per unit of camera distance.
uniform float contactPixelSize;
#else
uniform float contactDistancePower;
uniform float contactDistanceMultiplier;
uniform float contactResolutionDivisor; // viewport pixels per pixel of the buffers
#endif

// Distance along a perspective map's axis for its depth in [0,1].
float vtkContactLightDistance(int k, float depth)
{
  float n = contactDepthRange[k].x;
  float f = contactDepthRange[k].y;
  return n * f / (f - depth * (f - n));
}

#if CONTACT_LIGHT_SIZE && CONTACT_COUNT_PASSES
// contactPassStarts[CONTACT_PASS_LIMIT] and
// contactPassInverseVariances[CONTACT_PASS_LIMIT], declared before this file
// as constants (llvmpipe reloads a uniform at every use; immediates cost a
// sixth as much): the variance (pixels^2) before pass k, and 1 / pass k's.

// The blur passes whose summed variance (blur variances add) equals that of
// a Gaussian of full width `width` (about 4 sigma, 2% to 98%), a fraction
// counting for the last: a pass blended in by t adds t times its variance
// (vtkContactMultiPassFS.glsl), so that D follows the width smoothly.
// None for edges under a pixel and a half: there the receivers' own
// full-resolution hard edge is closer than any blur of these buffers.
// Counted without a branch.
float vtkContactPassesFor(float width)
{
  float target = 0.0625 * width * width;
  float passes = 0.0;
  for (int k = 0; k < CONTACT_PASS_LIMIT; ++k)
  {
    passes += clamp((target - contactPassStarts[k]) * contactPassInverseVariances[k], 0.0, 1.0);
  }
  return width >= 1.5 ? passes : 0.0;
}
#endif

// What every light's texel shares, set once a fragment by
// vtkContactCameraSetup(): the camera distance, and the screen pixels a world
// length on the surface spans.
float contactCameraDistance;
float contactPixelsPerLength;

void vtkContactCameraSetup(vec3 positionVC)
{
  contactCameraDistance = length(positionVC); // the camera is the view's origin
#if CONTACT_LIGHT_SIZE
  // The penumbra's width in pixels where it lies across the view; the
  // filters lay their kernels on the receiver (vtkContactSurfaceDistance2),
  // which foreshortens them along its slope.
#if CONTACT_PARALLEL_CAMERA
  contactPixelsPerLength = 1.0 / contactPixelSize;
#else
  contactPixelsPerLength = 1.0 / (contactPixelSize * contactCameraDistance);
#endif
#endif
}

// The texel for a shadowed fragment: from the occluder's distance, or with
// the light's size from the penumbra's world width.
vec4 vtkContactShadowed(float occluderDistance, float width)
{
#if CONTACT_LIGHT_SIZE
  float d = width * contactPixelsPerLength;
#if CONTACT_COUNT_PASSES
  d = vtkContactPassesFor(d);
#endif
#else
  // Dp and Dm are tuned in full-resolution pixels: a kernel
  // `contactResolutionDivisor` times smaller covers as much, and a blur pass
  // spreads as far as divisor^2 full-resolution ones (variances add).
  float d = pow(occluderDistance, contactDistancePower) * contactDistanceMultiplier /
    (CONTACT_COUNT_PASSES > 0 ? contactResolutionDivisor * contactResolutionDivisor : contactResolutionDivisor);
#endif
  return vec4(0.0, 0.0, contactCameraDistance, d);
}

// Light `k`'s texel for a shadowed fragment, from the receiver's and the
// blocker's distances along the light's axis (or to a point light).
vec4 vtkContactShadowed(int k, float receiverDistance, float blockerDistance)
{
  float occluderDistance = max(receiverDistance - blockerDistance, 0.0);
  return vtkContactShadowed(
    occluderDistance, occluderDistance * contactLightSize[k] / blockerDistance);
}

vec4 vtkContactLit()
{
  return vec4(1.0, 0.0, contactCameraDistance, 0.0);
}

#if CONTACT_CODES
// The receivers' code of texel `t` where the PCF pass has no work (a tile
// all lit, or all umbra with the early-out; vtkContactTileSpreadFS.glsl):
// not blurred, D dropped, as that pass would settle it. Written here so
// that the PCF pass draws only the other tiles.
float vtkContactSettledCode(vec4 t)
{
  return vtkShadowPackTexel(vec4(t.r, 0.0, t.b, 0.0));
}
#endif

#if CONTACT_MAPS > 0
vec4 vtkContactDistance(sampler2D map, int k, bool perspective, vec3 positionVC, vec3 normalVC)
{
  vec3 p;
  bool inMap = perspective
    ? vtkShadowOffsetInMap(
        contactViewToMap[k], contactLightVC[k], contactOffsetVC[k], positionVC, normalVC, p)
    : vtkShadowParallelOffsetInMap(
        contactViewToMap[k], contactLightVC[k].xyz, contactOffsetVC[k].w, positionVC, normalVC, p);
  if (!inMap)
  {
    return vtkContactLit();
  }
  float blockerDepth = texture(map, p.xy).r;
  if (p.z <= blockerDepth)
  {
    return vtkContactLit();
  }
  if (!perspective)
  {
    // Depth is linear in distance: near cancels, and the rest folds into
    // one uniform a use.
    float depth = max(p.z - blockerDepth, 0.0);
    return vtkContactShadowed(
      depth * contactParallelScale[k].x, depth * contactParallelScale[k].y);
  }
  return vtkContactShadowed(k, vtkContactLightDistance(k, p.z),
    vtkContactLightDistance(k, blockerDepth));
}
#endif

#if CONTACT_CUBES > 0
vec4 vtkContactDistance(samplerCube cube, int k, vec4 positionWC, vec3 normal)
{
  float size;
  vec3 direction = vtkShadowCubeDirection(
    contactCubeCenter[k], positionWC, normal, contactCubeTexel, contactNormalBias, size);
  float stored = vtkShadowCubeStored(cube, direction, contactCubeRange[k]);
  if (dot(direction, direction) * contactDistanceBias <= stored)
  {
    return vtkContactLit();
  }
  return vtkContactShadowed(k, length(direction), sqrt(stored));
}
#endif
