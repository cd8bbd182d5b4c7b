// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Smoothie receivers (Volokh, section 4): at each of the four texels nearest
// to the receiver's point in the light's maps, with its linear depth d, the
// shadow map's d_s and the smoothie buffer's depth d_m and alpha',
//   0 if d > d_s,  alpha' if d > d_m,  1 otherwise,
// and the four weighted bilinearly. The point is the framework's receiver
// point (moved towards the light, vtkShadowNormalOffsetFS.glsl), so lit
// surfaces pass d <= d_s without a depth bias.
// Uses: vtkShadowNormalOffsetFS.glsl (vtkShadowInMap) and
// vtkShadowCubeLookupFS.glsl (vtkShadowCubeDirection, vtkShadowCubeFace), which
// the receivers' shader (vtkSoftShadowReceiverFS.glsl) declares before it.

uniform float smoothieMapSize;

// The four texels' shadows, weighted: the shadow map's texels compared
// with `stored` (the receiver's depth in the map's units), the smoothies'
// with `d`. The smoothies are fetched only outside the umbra, and their
// alphas only where a smoothie lies in front of the receiver: most
// receivers read one or two gathers, not three.
float smoothieTexels(vec4 lit, vec4 behind, vec4 alpha, vec4 weights)
{
  return dot(lit * mix(vec4(1.0), alpha, behind), weights);
}

#if VTK_SHADOW_MAPS > 0
float smoothieGather(sampler2D depths, sampler2D smoothies, vec2 at, float stored, float d,
  vec4 weights)
{
  vec4 lit = vec4(lessThanEqual(vec4(stored), textureGather(depths, at, 0)));
  if (dot(lit, lit) == 0.0)
  {
    return 0.0; // the umbra
  }
  vec4 behind = vec4(greaterThan(vec4(d), textureGather(smoothies, at, 0)));
  return dot(behind, behind) > 0.0 ? smoothieTexels(lit, behind, textureGather(smoothies, at, 1),
                                       weights)
                                   : dot(lit, weights);
}
#endif

#if VTK_SHADOW_CUBES > 0
float smoothieGather(samplerCube depths, samplerCube smoothies, vec3 at, float stored, float d,
  vec4 weights)
{
  vec4 lit = vec4(lessThanEqual(vec4(stored), textureGather(depths, at, 0)));
  if (dot(lit, lit) == 0.0)
  {
    return 0.0; // the umbra
  }
  vec4 behind = vec4(greaterThan(vec4(d), textureGather(smoothies, at, 0)));
  return dot(behind, behind) > 0.0 ? smoothieTexels(lit, behind, textureGather(smoothies, at, 1),
                                       weights)
                                   : dot(lit, weights);
}
#endif

// textureGather's order (upper left, upper right, lower right, lower left
// of the four texels around the point) weighted by f, the point's place
// between their centres.
vec4 smoothieWeights(vec2 f)
{
  return vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
}

#if VTK_SHADOW_MAPS > 0
// A spot or directional light: `depths` its linear shadow map, `smoothies`
// its smoothie buffer, `eye` and `axis` its frustum's.
float smoothieVisibility(sampler2D depths, sampler2D smoothies, mat4 worldToMap,
  vec4 receiverWC, vec4 eye, vec3 axis)
{
  vec3 p;
  if (!vtkShadowInMap(worldToMap, receiverWC, p))
  {
    return 1.0;
  }
  float d = dot(receiverWC.xyz - eye.xyz, axis);
  vec2 st = p.xy * smoothieMapSize - 0.5;
  vec2 at = (floor(st) + 1.0) / smoothieMapSize; // the four texels' shared corner
  return smoothieGather(depths, smoothies, at, d, d, smoothieWeights(fract(st)));
}
#endif

#if VTK_SHADOW_CUBES > 0
// A point light: the framework's cube of squared distances and the smoothie
// cube, distances from the light (`center`).
float smoothieCubeVisibility(samplerCube distances, samplerCube smoothies, vec3 center,
  vec4 positionWC, vec3 normalWC)
{
  float size;
  vec3 v = vtkShadowCubeDirection(
    center, positionWC, normalWC, vtkShadowCubeTexel, vtkShadowNormalBias, size);
  vec3 s, t;
  float axis;
  vtkShadowCubeFace(v, s, t, axis);
  vec2 st = (vec2(dot(v, s), dot(v, t)) / axis * 0.5 + 0.5) * smoothieMapSize - 0.5;
  // The four texels' shared corner, as a direction on the face.
  vec2 at = (floor(st) + 1.0) / smoothieMapSize * 2.0 - 1.0;
  vec3 corner = axis * (at.x * s + at.y * t) + (v - dot(v, s) * s - dot(v, t) * t);
  // The cube holds squared distances.
  float stored = dot(v, v) * vtkShadowDistanceBias;
  return smoothieGather(
    distances, smoothies, corner, stored, sqrt(stored), smoothieWeights(fract(st)));
}
#endif
