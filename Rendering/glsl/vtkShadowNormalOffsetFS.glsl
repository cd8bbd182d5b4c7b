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

// The map coordinates ([0,1]^3) of a point (world or view coordinates,
// `toMap` from them), and whether the point lies in the map's frustum (in
// front of its eye, inside its bounds): what lies outside is lit.
bool vtkShadowInMap(mat4 toMap, vec4 position, out vec3 map)
{
  vec4 p = toMap * position;
  map = p.xyz / p.w;
  return p.w > 0.0 && all(greaterThanEqual(map, vec3(0.0))) && all(lessThanEqual(map, vec3(1.0)));
}

// vtkShadowNormalOffset() then vtkShadowInMap(), on a point in the camera's
// view coordinates, as the receivers' fragments have them: no transform to
// the world and back, no branch on the light's type, and what is constant
// per light folded into its uniforms (docs/benchmarks.md).
// light: towards the light, the map's eye (w = 1) or the direction to a
// parallel map's light (w = 0); offset: the offset before its
// 1 / cos(theta) is dot(positionVC, xyz) + w (`texels` times a texel's size
// there).
bool vtkShadowOffsetInMap(mat4 viewToMap, vec4 light, vec4 offset, vec3 positionVC,
  vec3 normalVC, out vec3 map)
{
  vec3 toLight = light.xyz - positionVC * light.w; // not unit for a spot light
  // offset / max(cos(theta), 1/4), over |toLight| for moving along it.
  float along = (dot(positionVC, offset.xyz) + offset.w) /
    max(abs(dot(normalVC, toLight)), 0.25 * sqrt(dot(toLight, toLight)));
  return vtkShadowInMap(viewToMap, vec4(positionVC + along * toLight, 1.0), map);
}

// The same for a parallel map, where light.w = 0, offset.xyz = 0 and the
// matrix's last row is (0, 0, 0, 1): the same result, reading only the
// uniform components that vary (llvmpipe loads each component read, for
// every fragment). toLight: light.xyz; offset: offset.w.
bool vtkShadowParallelOffsetInMap(
  mat4 viewToMap, vec3 toLight, float offset, vec3 positionVC, vec3 normalVC, out vec3 map)
{
  float along = offset / max(abs(dot(normalVC, toLight)), 0.25 * sqrt(dot(toLight, toLight)));
  map = (viewToMap * vec4(positionVC + along * toLight, 1.0)).xyz;
  return all(greaterThanEqual(map, vec3(0.0))) && all(lessThanEqual(map, vec3(1.0)));
}
