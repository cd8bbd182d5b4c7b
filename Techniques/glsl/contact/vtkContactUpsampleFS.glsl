// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Contact's receivers: the screen-space visibility upsampled, guided by the
// fragment's own full-resolution hard shadow, and (CONTACT_REFINE) refined
// in light space where the buffer could not resolve a penumbra. Inserted in
// the receivers' fragment shaders after the framework's receiver code.
// Uses: vtkSoftShadowReceiverFS.glsl (vtkShadowScreenCodes, vtkShadowScreenDecode,
// vtkShadowScreenBlend, vtkShadowScreenCameraDistance, vtkShadowLookup, vtkShadowReceiver),
// vtkShadowCubeLookupFS.glsl.

#if CONTACT_REFINE
float vtkContactTexelSize;    // a screen texel's world size at the fragment
float vtkContactLongestStep2; // squared: the surface's longest step from a texel to the next
float vtkContactUnresolved;   // share of the last lookup to refine, 0 to 1
float vtkContactRadius;       // the penumbra's half width there, world

// Once a fragment, after vtkShadowScreenSetup().
void vtkContactScreenSetup(vec3 positionVC)
{
  vtkContactTexelSize =
    vtkShadowTexelFootprint.x + vtkShadowTexelFootprint.y * vtkShadowScreenCameraDistance;
  vec3 stepX = dFdx(positionVC) * vtkShadowScreenPixels.x;
  vec3 stepY = dFdy(positionVC) * vtkShadowScreenPixels.y;
  vtkContactLongestStep2 = max(dot(stepX, stepX), dot(stepY, stepY));
}
#endif

// Valid texels say on which side of their own hard edge they lie (the
// sign of their code). Where a penumbra is narrower on the screen than a
// texel (a floor seen nearly edge-on foreshortens it), the texels either
// side of the edge keep nearly their hard values, and interpolating between
// them would smear the edge over two texels; a texel across the edge from
// the fragment then counts by how far the filtering moved it from its hard
// value (fully from half the way). With CONTACT_REFINE what that leaves
// out, which the buffer could not resolve, is filtered again in light
// space over the penumbra's width the texels also carry
// (vtkContactRefine()).
float vtkContactScreenVisibility(sampler2D screen, float hard)
{
  vec4 codes = vtkShadowScreenCodes(screen);
  vec4 lit = vec4(lessThan(codes, vec4(0.0)));
  codes = abs(codes);
#if CONTACT_REFINE
  vec4 code = floor(codes / 524288.0); // the penumbra's width
  codes -= code * 524288.0;
#endif
  vec4 weights, values, valid;
  vtkShadowScreenDecode(codes, hard, weights, values, valid);
  // An invalid texel (its value `hard`, from the fragment's side of 0.5)
  // across the edge keeps all: only valid ones need the test.
  vec4 across = abs(lit - (hard >= 0.5 ? 1.0 : 0.0));
  vec4 keep = mix(vec4(1.0), min(abs(values - lit) * 2.0, 1.0), across);
#if CONTACT_REFINE
  // The texels' penumbra width (vtkShadowWidthCode()) where they have one;
  // exp2 of the mean code, one exp2 rather than four.
  vec4 widths = weights * valid * vec4(greaterThan(code, vec4(0.0)));
  float wide = dot(widths, vec4(1.0));
  vtkContactRadius =
    wide > 0.0 ? 0.5 * vtkContactTexelSize * exp2(0.5 * dot(widths, code) / wide) : 0.0;
  vtkContactUnresolved = 1.0 - min(min(keep.x, keep.y), min(keep.z, keep.w));
#endif
  // None kept (the fragment alone on its side): the unguided lookup.
  weights *= dot(weights, keep) > 0.0 ? keep : vec4(1.0);
  return vtkShadowScreenBlend(weights, values, hard);
}

#if CONTACT_REFINE
// The n-th of 16 taps on a disc of the penumbra's half width on the
// receiver's plane: a golden-angle spiral, turned per pixel (within the
// viewport, so the same wherever it lies) against banding; an orthonormal
// basis across the normal without a square root (Duff et al. 2017) and
// interleaved gradient noise (Jimenez 2014) for the turn.
vec4 vtkContactTap(vec4 positionWC, vec3 normalWC, int n)
{
  vec3 v = normalWC;
  float s = v.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + v.z);
  float b = v.x * v.y * a;
  vec3 t1 = vec3(1.0 + s * v.x * v.x * a, s * b, -s * v.x);
  vec3 t2 = vec3(b, s + v.y * v.y * a, -v.y);
  vec2 pixel = floor(gl_FragCoord.xy - vtkShadowScreenOrigin);
  float angle = 2.3999632 * float(n) +
    6.2831853 * fract(52.982919 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
  float radius = vtkContactRadius * sqrt((float(n) + 0.5) / 16.0);
  return positionWC + vec4(radius * (cos(angle) * t1 + sin(angle) * t2), 0.0);
}

// How many taps vtkContactRefine() takes: 16 where the screen-space lookup
// left something out and the penumbra spans less than two texel steps along
// the surface's most foreshortened screen axis, else none. (A software
// rasterizer still runs one masked iteration of a loop no pixel of a group
// enters: on llvmpipe every fragment pays about one tap.)
int vtkContactRefineTaps()
{
  return vtkContactUnresolved > 0.0 && vtkContactRadius > 0.0 &&
      vtkContactRadius * vtkContactRadius < vtkContactLongestStep2
    ? 16
    : 0;
}

// Where the screen-space lookup could not resolve a penumbra, the mean of
// light `i`'s hard shadow over a disc of the penumbra's width on the
// receiver (the light's own shape, as the PCF filter takes it on the
// screen), blended in by the share left out.
#if VTK_SHADOW_MAPS > 0
float vtkContactRefine(float visibility, sampler2DShadow map, int i, vec4 positionWC, vec3 normalWC)
{
  int taps = vtkContactRefineTaps();
  float sum = 0.0;
  for (int n = 0; n < taps; ++n)
  {
    vec4 tap = vtkContactTap(positionWC, normalWC, n);
    sum += vtkShadowLookup(map, vtkShadowWorldToMap[i], vtkShadowReceiver(i, tap, normalWC), 0);
  }
  return taps > 0 ? mix(visibility, sum / 16.0, vtkContactUnresolved) : visibility;
}
#endif

#if VTK_SHADOW_CUBES > 0
float vtkContactRefine(float visibility, samplerCube cube, vec3 center, float range,
  vec4 positionWC, vec3 normalWC)
{
  int taps = vtkContactRefineTaps();
  float sum = 0.0;
  for (int n = 0; n < taps; ++n)
  {
    vec4 tap = vtkContactTap(positionWC, normalWC, n);
    sum += vtkShadowCubeLookup(cube, center, tap, normalWC, vtkShadowCubeTexel,
      vtkShadowNormalBias, vtkShadowDistanceBias, range, 0);
  }
  return taps > 0 ? mix(visibility, sum / 16.0, vtkContactUnresolved) : visibility;
}
#endif
#endif
