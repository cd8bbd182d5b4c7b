// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Shadow term of the receivers' fragment shaders, shared by every technique.
// Inserted by vtkSoftShadowPass after VTK_SHADOW_LIGHTS (number of shadowed
// lights), VTK_SHADOW_PARALLEL (bool[](...), whether each has a parallel
// map), VTK_SHADOW_MAPS and VTK_SHADOW_CUBES (how many of them have a 2D
// map, a cube map), VTK_SHADOW_PCF_RADIUS and VTK_SHADOW_PCF_BILINEAR (the
// hard lookup's kernel) and, for screen-space techniques,
// VTK_SHADOW_SCREEN_SPACE are defined. Sampler arrays are indexed with
// constants (GLSL 1.50), but for vtkShadowCubeLookupAll(), which needs
// GL_ARB_gpu_shader5.
// Uses: vtkShadowSurfaceFS.glsl, vtkShadowNormalOffsetFS.glsl, vtkShadowCubeLookupFS.glsl.

uniform mat4 vtkShadowWorldToMap[VTK_SHADOW_LIGHTS];
uniform float vtkShadowAttenuation[VTK_SHADOW_LIGHTS];
uniform vec4 vtkShadowEye[VTK_SHADOW_LIGHTS];
uniform vec3 vtkShadowAxis[VTK_SHADOW_LIGHTS];
uniform vec2 vtkShadowFootprint[VTK_SHADOW_LIGHTS];
// The same in the camera's view coordinates (vtkShadowOffsetInMap()).
uniform mat4 vtkShadowViewToMap[VTK_SHADOW_LIGHTS];
uniform vec4 vtkShadowLightVC[VTK_SHADOW_LIGHTS];
uniform vec4 vtkShadowOffsetVC[VTK_SHADOW_LIGHTS];
uniform float vtkShadowMapTexel;
uniform float vtkShadowNormalBias;
// Constants, not uniforms: llvmpipe runs a loop's body once with every lane
// masked off even when it has no iteration to do, so a PCF loop the
// compiler cannot remove cost `hard` 10% of its frame at radius 0.
const int vtkShadowPCFRadius = VTK_SHADOW_PCF_RADIUS;
const bool vtkShadowPCFBilinear = VTK_SHADOW_PCF_BILINEAR != 0;

// The point light `i`'s map is looked up at (see vtkShadowNormalOffset).
vec4 vtkShadowReceiver(int i, vec4 positionWC, vec3 normalWC)
{
  return vtkShadowNormalOffset(positionWC, normalWC, vtkShadowEye[i], vtkShadowAxis[i],
    vtkShadowFootprint[i], vtkShadowNormalBias);
}

// Which lights have a parallel map (directional lights), compiled in
// (VTK_SHADOW_PARALLEL): with the index a constant, each lookup keeps only
// its own kind's code, and a parallel one reads 8 uniform components fewer.
const bool vtkShadowParallel[VTK_SHADOW_LIGHTS] = VTK_SHADOW_PARALLEL;

// Light i's map coordinates where a receiver at a view-space point looks
// its map up (vtkShadowReceiver(), then the map's projection), and whether
// they lie in the map.
bool vtkShadowReceiverInMap(int i, vec3 positionVC, vec3 normalVC, out vec3 map)
{
  return vtkShadowParallel[i]
    ? vtkShadowParallelOffsetInMap(vtkShadowViewToMap[i], vtkShadowLightVC[i].xyz,
        vtkShadowOffsetVC[i].w, positionVC, normalVC, map)
    : vtkShadowOffsetInMap(vtkShadowViewToMap[i], vtkShadowLightVC[i], vtkShadowOffsetVC[i],
        positionVC, normalVC, map);
}

// Hard shadow: the fraction of depth comparisons that pass around the
// point's projection p in the light's map, over a (2r+1)^2-texel footprint.
// With bilinear comparison (vtkShadowPCFBilinear) the taps sit on texel
// corners, (2r)^2 of them, each averaging 2x2 texels: the same footprint
// with tent weights for fewer taps.
#if VTK_SHADOW_MAPS > 0
uniform sampler2DShadow vtkShadowMap[VTK_SHADOW_MAPS];
#endif

float vtkShadowCompare(sampler2DShadow map, vec3 p, int radius)
{
  if (radius == 0)
  {
    return texture(map, p.xyz);
  }
  int taps = vtkShadowPCFBilinear ? 2 * radius : 2 * radius + 1;
  float first = vtkShadowPCFBilinear ? 0.5 - float(radius) : -float(radius);
  float lit = 0.0;
  for (int y = 0; y < taps; ++y)
  {
    for (int x = 0; x < taps; ++x)
    {
      vec2 offset = (vec2(x, y) + first) * vtkShadowMapTexel;
      lit += texture(map, vec3(p.xy + offset, p.z));
    }
  }
  return lit / float(taps * taps);
}

// The hard shadow at a world point (already offset); outside the map is lit.
float vtkShadowLookup(sampler2DShadow map, mat4 worldToMap, vec4 positionWC, int radius)
{
  vec3 p;
  return vtkShadowInMap(worldToMap, positionWC, p) ? vtkShadowCompare(map, p, radius) : 1.0;
}

// Light i's hard shadow at a receiver's view-space point and unit normal.
float vtkShadowReceiverLookup(sampler2DShadow map, int i, vec3 positionVC, vec3 normalVC, int radius)
{
  vec3 p;
  return vtkShadowReceiverInMap(i, positionVC, normalVC, p) ? vtkShadowCompare(map, p, radius) : 1.0;
}

#if VTK_SHADOW_CUBES > 0
// Point lights: cube maps of squared distances (vtkShadowCubeLookupFS.glsl).
uniform samplerCube vtkShadowCube[VTK_SHADOW_CUBES];
uniform vec3 vtkShadowCubeCenter[VTK_SHADOW_CUBES];
uniform float vtkShadowCubeRange[VTK_SHADOW_CUBES]; // 0: float map; else RGBA8 range
uniform float vtkShadowCubeTexel;   // a texel's world size per unit of distance
uniform float vtkShadowDistanceBias; // multiplicative, on squared distances

// The hard lookup of cube map c: vtkShadowCubeHardAll() for the first point
// light, vtkShadowCubeHardOf() for the others. With GL_ARB_gpu_shader5
// (sampler arrays indexed by a loop counter) the first fills every cube's
// visibility in one loop, so the shader holds one copy of the lookup
// whatever the number of point lights (written once per light, llvmpipe
// took 6 s to compile 16); without it each light has its own copy.
#ifdef GL_ARB_gpu_shader5
float vtkShadowCubeVisibility[VTK_SHADOW_CUBES];
float vtkShadowCubeLookupAll(vec4 positionWC, vec3 normalWC, int wanted)
{
  for (int c = 0; c < VTK_SHADOW_CUBES; ++c)
  {
    vtkShadowCubeVisibility[c] = vtkShadowCubeLookup(vtkShadowCube[c], vtkShadowCubeCenter[c],
      positionWC, normalWC, vtkShadowCubeTexel, vtkShadowNormalBias, vtkShadowDistanceBias,
      vtkShadowCubeRange[c], vtkShadowPCFRadius);
  }
  return vtkShadowCubeVisibility[wanted];
}
#define vtkShadowCubeHardAll(p, n, c) vtkShadowCubeLookupAll(p, n, c)
#define vtkShadowCubeHardOf(p, n, c) vtkShadowCubeVisibility[c]
#else
#define vtkShadowCubeHardAll(p, n, c)                                                             \
  vtkShadowCubeLookup(vtkShadowCube[c], vtkShadowCubeCenter[c], p, n, vtkShadowCubeTexel,         \
    vtkShadowNormalBias, vtkShadowDistanceBias, vtkShadowCubeRange[c], vtkShadowPCFRadius)
#define vtkShadowCubeHardOf(p, n, c) vtkShadowCubeHardAll(p, n, c)
#endif
#endif

#ifdef VTK_SHADOW_SCREEN_SPACE
uniform sampler2D vtkShadowScreen[VTK_SHADOW_LIGHTS];
uniform vec2 vtkShadowViewportOrigin;
uniform vec2 vtkShadowScreenScale; // viewport pixels to screen-space texels
uniform float vtkShadowLogNear;    // see vtkShadowPackTexel(), vtkShadowScreenCodeFS.glsl
uniform float vtkShadowCodesPerLog;

// What the lookups of all lights share (their textures have one size): the
// gather point, the bilinear weights, the fragment's camera distance, its
// code and how far from it a texel on its surface may lie, set once a
// fragment by vtkShadowScreenSetup().
vec2 vtkShadowScreenCorner;
vec4 vtkShadowScreenWeights; // lower left, lower right, upper left, upper right
float vtkShadowScreenCameraDistance;
float vtkShadowScreenFragment;
float vtkShadowScreenTolerance;
vec2 vtkShadowScreenCodeRange; // the least and the greatest code on its surface
uniform vec2 vtkShadowTexelFootprint; // a texel's world size: x + y * camera distance
// The viewport's origin and its pixels per texel: compiled in where the
// buffers divide the viewport exactly
// (vtkShadowScreenBuffers::GetLayoutDeclarations()), as llvmpipe loads a
// uniform for every fragment (a few instructions a component).
#ifdef VTK_SHADOW_SCREEN_DIVISOR
const vec2 vtkShadowScreenOrigin = VTK_SHADOW_SCREEN_ORIGIN;
const vec2 vtkShadowScreenPixels = vec2(VTK_SHADOW_SCREEN_DIVISOR);
const vec2 vtkShadowScreenTexels = vec2(1.0 / VTK_SHADOW_SCREEN_DIVISOR);
#else
#define vtkShadowScreenOrigin vtkShadowViewportOrigin
#define vtkShadowScreenPixels (1.0 / vtkShadowScreenScale)
#define vtkShadowScreenTexels vtkShadowScreenScale
#endif

void vtkShadowScreenSetup(vec3 positionVC)
{
  // Clamped to the texel centres at the edges, as bilinear filtering clamps.
  vec2 size = vec2(textureSize(vtkShadowScreen[0], 0));
  vec2 p = clamp((gl_FragCoord.xy - vtkShadowScreenOrigin) * vtkShadowScreenTexels - 0.5,
    vec2(0.0), size - 1.0);
  vec2 f = fract(p);
  vtkShadowScreenCorner = (floor(p) + 1.0) / size;
  vtkShadowScreenWeights =
    vec4(1.0 - f.x, f.x, 1.0 - f.x, f.x) * vec4(1.0 - f.y, 1.0 - f.y, f.y, f.y) + 1.0e-4;
  // The camera sits at the view-space origin.
  vtkShadowScreenCameraDistance = length(positionVC);
  vtkShadowScreenFragment =
    (log2(vtkShadowScreenCameraDistance) - vtkShadowLogNear) * vtkShadowCodesPerLog + 1.0;
  // 2% (log2(1.02)) and rounding, plus the change of distance over a texel
  // on this fragment's own plane: on a floor seen nearly edge-on it exceeds
  // 2% from one texel to the next. (The derivatives are the primitive's
  // own, so they never cross a silhouette.)
  vec2 slope = vec2(dFdx(vtkShadowScreenFragment), dFdy(vtkShadowScreenFragment));
  vtkShadowScreenTolerance =
    0.0286 * vtkShadowCodesPerLog + 0.5 + dot(abs(slope), vtkShadowScreenPixels);
  // As the codes a texel may have, 0 (the background) excluded: one range
  // for all lights.
  vtkShadowScreenCodeRange = vec2(max(vtkShadowScreenFragment - vtkShadowScreenTolerance, 0.5),
    vtkShadowScreenFragment + vtkShadowScreenTolerance);
}

// A screen-space visibility texture (vtkShadowScreenBuffers::BeginVisibility:
// visibility, whether it is valid, and the surface's camera distance),
// possibly smaller than the viewport, read coded (vtkShadowPackTexel(),
// vtkShadowScreenCommonFS.glsl: one float a texel): the codes of the four
// texels around the fragment, gathered in one fetch at their shared corner
// as upper left, upper right, lower right, lower left and reordered to lower
// left, lower right, upper left, upper right.
vec4 vtkShadowScreenCodes(sampler2D screen)
{
  return textureGather(screen, vtkShadowScreenCorner).wzxy;
}

// Codes without flags (sign and width) decoded: each texel's bilinear
// weight, zero unless it lies on this fragment's surface (its camera
// distance within 2% of what the fragment's plane gives there), its
// visibility where valid and `hard` where not, and whether it is valid.
void vtkShadowScreenDecode(vec4 codes, float hard, out vec4 weights, out vec4 values, out vec4 valid)
{
  vec4 visibility = floor(codes / 2048.0);
  vec4 distances = codes - 2048.0 * visibility;
  valid = vec4(notEqual(visibility, vec4(255.0)));
  weights = vtkShadowScreenWeights *
    vec4(greaterThanEqual(distances, vec4(vtkShadowScreenCodeRange.x))) *
    vec4(lessThanEqual(distances, vec4(vtkShadowScreenCodeRange.y)));
  values = mix(vec4(hard), visibility / 254.0, valid);
}

// The weighted mean of the texels' values; fragments no texel belongs to
// (silhouettes the buffer missed, translucent surfaces not within 2% of an
// opaque one) keep their own full-resolution `hard` visibility.
float vtkShadowScreenBlend(vec4 weights, vec4 values, float hard)
{
  float total = dot(weights, vec4(1.0));
  return total > 0.0 ? dot(weights, values) / total : hard;
}

// The screen-space visibility at the fragment given to
// vtkShadowScreenSetup(), bilinear over the texels on its surface.
float vtkShadowScreenVisibility(sampler2D screen, float hard)
{
  vec4 weights, values, valid;
  vtkShadowScreenDecode(vtkShadowScreenCodes(screen), hard, weights, values, valid);
  return vtkShadowScreenBlend(weights, values, hard);
}
#endif
