// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Receiver-side offset, shared by mapper shaders and screen-space passes:
// the looked-up point moves towards the light along its own ray by `texels`
// shadow-map texels over cos(theta) (theta between the surface's geometric
// normal and the light, the bound at 1/4), which puts it as far in front of
// the surface's plane along that ray as an offset of `texels` along the
// normal (normal offset) does, but on the same texel: without the normal
// offset's sideways shift of texels * tan(theta), which moved every shadow
// edge and hid self-shadowing on curved surfaces (docs/quality.md). Unlike a
// depth bias it does not depend on how depth is stored, so surfaces facing
// the light head-on (zero depth slope) and positions rebuilt from a depth
// buffer stay free of acne.
// Uses: nothing.
//
// eye: the map's eye, w = 1 for a perspective (spot) map, 0 for a parallel
// one; axis: unit view direction of the map; footprint: world size of one
// texel, x + y * (distance along the axis).
vec4 vtkShadowNormalOffset(
  vec4 positionWC, vec3 normalWC, vec4 eye, vec3 axis, vec2 footprint, float texels)
{
  vec3 toLight = eye.w > 0.0 ? normalize(eye.xyz - positionWC.xyz) : -axis;
  float facing = max(abs(dot(normalWC, toLight)), 0.25);
  float distance = eye.w > 0.0 ? dot(positionWC.xyz - eye.xyz, axis) : 0.0;
  float texel = footprint.x + footprint.y * distance;
  return vec4(positionWC.xyz + toLight * (texel * texels / facing), 1.0);
}

// The map coordinates ([0,1]^3) of a world point in `map`, and whether the
// point lies in the map's frustum (in front of its eye, inside its bounds):
// what lies outside is lit.
bool vtkShadowInMap(mat4 worldToMap, vec4 positionWC, out vec3 map)
{
  vec4 p = worldToMap * positionWC;
  map = p.xyz / p.w;
  return p.w > 0.0 && all(greaterThanEqual(map, vec3(0.0))) && all(lessThanEqual(map, vec3(1.0)));
}
