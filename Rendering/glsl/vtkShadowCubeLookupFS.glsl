// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Point lights (Gerasimov, GPU Gems ch. 12): visibility from a cube map of
// squared distances to the light, looked up with the light-to-fragment
// direction. Shared by receivers, screen-space passes and techniques.
//
// range: 0 for a float cube map; else the map is RGBA8, each texel packing
// the squared distance over `range` (section 12.3.3, method 1).
// Uses: nothing.

vec4 vtkShadowPackDistance(float v)
{
  vec4 bytes = fract(v * vec4(1.0, 255.0, 65025.0, 16581375.0));
  return bytes - bytes.yzww * vec4(1.0 / 255.0, 1.0 / 255.0, 1.0 / 255.0, 0.0);
}

float vtkShadowCubeStored(samplerCube cube, vec3 direction, float range)
{
  vec4 texel = texture(cube, direction);
  return range > 0.0
    ? dot(texel, vec4(1.0, 1.0 / 255.0, 1.0 / 65025.0, 1.0 / 16581375.0)) * range
    : texel.r;
}

// A cube face's axes for direction v (OpenGL's face layout): s and t
// across the face (texel coordinates grow along them), and the distance
// along its axis.
void vtkShadowCubeFace(vec3 v, out vec3 s, out vec3 t, out float axis)
{
  vec3 a = abs(v);
  if (a.x >= a.y && a.x >= a.z)
  {
    s = vec3(0.0, 0.0, -sign(v.x));
    t = vec3(0.0, -1.0, 0.0);
    axis = a.x;
  }
  else if (a.y >= a.z)
  {
    s = vec3(1.0, 0.0, 0.0);
    t = vec3(0.0, 0.0, sign(v.y));
    axis = a.y;
  }
  else
  {
    s = vec3(sign(v.z), 0.0, 0.0);
    t = vec3(0.0, -1.0, 0.0);
    axis = a.z;
  }
}

// The direction to look up for a point, moved towards the light along its
// ray by `normalBias` texels over cos(theta), as vtkShadowNormalOffset()
// does; `size` returns a texel's world size there (texel: a texel's size
// per unit of distance, 2 / map size).
vec3 vtkShadowCubeDirection(vec3 center, vec4 positionWC, vec3 normalWC, float texel,
  float normalBias, out float size)
{
  vec3 toPoint = positionWC.xyz - center;
  float reach = max(sqrt(dot(toPoint, toPoint)), 1.0e-20);
  float facing = max(abs(dot(normalWC, toPoint)) / reach, 0.25);
  size = texel * max(abs(toPoint.x), max(abs(toPoint.y), abs(toPoint.z)));
  return toPoint * max(1.0 - size * normalBias / (facing * reach), 0.0);
}

// Two unit vectors across `d`, for filter taps.
void vtkShadowCubeBasis(vec3 d, out vec3 u, out vec3 v)
{
  vec3 w = normalize(d);
  u = normalize(cross(w, abs(w.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0)));
  v = cross(w, u);
}

// One tap, or (radius > 0) section 12.4's 4-tap PCF with the taps `radius`
// texels apart. distanceBias multiplies the squared distance (12.3.7: "works
// best in practice").
float vtkShadowCubeLookup(samplerCube cube, vec3 center, vec4 positionWC, vec3 normalWC,
  float texel, float normalBias, float distanceBias, float range, int radius)
{
  float size;
  vec3 d = vtkShadowCubeDirection(center, positionWC, normalWC, texel, normalBias, size);
  float reference = dot(d, d) * distanceBias;
  if (radius == 0)
  {
    return reference <= vtkShadowCubeStored(cube, d, range) ? 1.0 : 0.0;
  }
  vec3 u, v;
  vtkShadowCubeBasis(d, u, v);
  float step = 0.5 * float(radius) * size;
  float lit = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    vec2 o = vec2((i & 1) == 0 ? -1.0 : 1.0, (i & 2) == 0 ? -1.0 : 1.0) * step;
    lit += reference <= vtkShadowCubeStored(cube, d + o.x * u + o.y * v, range) ? 0.25 : 0.0;
  }
  return lit;
}
