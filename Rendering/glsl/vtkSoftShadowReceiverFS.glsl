// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Shadow term of the receivers' fragment shaders, shared by every technique.
// Inserted by vtkSoftShadowPass after VTK_SHADOW_LIGHTS (number of shadowed
// lights), VTK_SHADOW_MAPS and VTK_SHADOW_CUBES (how many of them have a 2D
// map, a cube map) and, for screen-space techniques, VTK_SHADOW_SCREEN_SPACE
// are defined. Sampler arrays are indexed with constants (GLSL 1.50), but
// for vtkShadowCubeLookupAll(), which needs GL_ARB_gpu_shader5.
// Uses: vtkShadowSurfaceFS.glsl, vtkShadowNormalOffsetFS.glsl, vtkShadowCubeLookupFS.glsl.

uniform mat4 vtkShadowWorldToMap[VTK_SHADOW_LIGHTS];
uniform float vtkShadowAttenuation[VTK_SHADOW_LIGHTS];
uniform vec4 vtkShadowEye[VTK_SHADOW_LIGHTS];
uniform vec3 vtkShadowAxis[VTK_SHADOW_LIGHTS];
uniform vec2 vtkShadowFootprint[VTK_SHADOW_LIGHTS];
uniform float vtkShadowMapTexel;
uniform float vtkShadowNormalBias;
uniform int vtkShadowPCFRadius;

// The point light `i`'s map is looked up at (see vtkShadowNormalOffset).
vec4 vtkShadowReceiver(int i, vec4 positionWC, vec3 normalWC)
{
  return vtkShadowNormalOffset(positionWC, normalWC, vtkShadowEye[i], vtkShadowAxis[i],
    vtkShadowFootprint[i], vtkShadowNormalBias);
}

// Hard shadow: the fraction of depth comparisons that pass around the
// point's projection in the light's map, over a (2r+1)^2-texel footprint.
// With bilinear comparison (vtkShadowPCFBilinear) the taps sit on texel
// corners, (2r)^2 of them, each averaging 2x2 texels: the same footprint
// with tent weights for fewer taps. Outside the map is lit.
uniform bool vtkShadowPCFBilinear;
#if VTK_SHADOW_MAPS > 0
uniform sampler2DShadow vtkShadowMap[VTK_SHADOW_MAPS];
#endif

float vtkShadowLookup(sampler2DShadow map, mat4 worldToMap, vec4 positionWC, int radius)
{
  vec3 p;
  if (!vtkShadowInMap(worldToMap, positionWC, p))
  {
    return 1.0;
  }
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
uniform float vtkShadowLogNear;    // see vtkShadowPackTexel(), vtkShadowScreenCommonFS.glsl
uniform float vtkShadowCodesPerLog;

// What the lookups of all lights share (their textures have one size): the
// gather point, the bilinear weights, the fragment's distance code and how
// far from it a texel on its surface may lie, set once a fragment by
// vtkShadowScreenSetup().
vec2 vtkShadowScreenCorner;
vec4 vtkShadowScreenWeights; // lower left, lower right, upper left, upper right
float vtkShadowScreenFragment;
float vtkShadowScreenTolerance;
#ifdef VTK_SHADOW_SCREEN_REFINE
uniform vec2 vtkShadowTexelFootprint; // a texel's world size: x + y * camera distance
float vtkShadowScreenTexelSize;       // a texel's world size at the fragment
float vtkShadowScreenLongestStep2;    // squared: the surface's longest step from a texel to the next
#endif

void vtkShadowScreenSetup(vec4 positionWC)
{
  // Clamped to the texel centres at the edges, as bilinear filtering clamps.
  vec2 size = vec2(textureSize(vtkShadowScreen[0], 0));
  vec2 p = clamp((gl_FragCoord.xy - vtkShadowViewportOrigin) * vtkShadowScreenScale - 0.5,
    vec2(0.0), size - 1.0);
  vec2 f = fract(p);
  vtkShadowScreenCorner = (floor(p) + 1.0) / size;
  vtkShadowScreenWeights =
    vec4(1.0 - f.x, f.x, 1.0 - f.x, f.x) * vec4(1.0 - f.y, 1.0 - f.y, f.y, f.y) + 1.0e-4;
  // The camera sits at the view-space origin.
  float cameraDistance = distance(positionWC.xyz, vtkShadowViewToWorld[3].xyz);
  vtkShadowScreenFragment = (log2(cameraDistance) - vtkShadowLogNear) * vtkShadowCodesPerLog + 1.0;
  // 2% (log2(1.02)) and rounding, plus the change of distance over a texel
  // on this fragment's own plane: on a floor seen nearly edge-on it exceeds
  // 2% from one texel to the next. (The derivatives are the primitive's
  // own, so they never cross a silhouette.)
  vec2 slope = vec2(dFdx(vtkShadowScreenFragment), dFdy(vtkShadowScreenFragment));
  vtkShadowScreenTolerance =
    0.0286 * vtkShadowCodesPerLog + 0.5 + dot(abs(slope), 1.0 / vtkShadowScreenScale);
#ifdef VTK_SHADOW_SCREEN_REFINE
  vtkShadowScreenTexelSize = vtkShadowTexelFootprint.x + vtkShadowTexelFootprint.y * cameraDistance;
  vec3 stepX = dFdx(positionWC.xyz) / vtkShadowScreenScale.x;
  vec3 stepY = dFdy(positionWC.xyz) / vtkShadowScreenScale.y;
  vtkShadowScreenLongestStep2 = max(dot(stepX, stepX), dot(stepY, stepY));
#endif
}

// A screen-space visibility texture (vtkShadowScreenBuffers::BeginVisibility:
// visibility, whether it is valid, and the surface's camera distance),
// possibly smaller than the viewport, read coded (vtkShadowPackFS.glsl: one
// float a texel, the four around the fragment gathered in one fetch):
// bilinear over the four texels that lie on this fragment's surface (at the
// position given to vtkShadowScreenSetup(); camera distances within 2% of
// what its plane gives there), each giving its visibility where valid and
// the fragment's own full-resolution `hard` one where not. Fragments no
// texel belongs to (silhouettes the buffer missed, translucent surfaces not
// within 2% of an opaque one) keep `hard`.
//
// Guided (VTK_SHADOW_SCREEN_GUIDED): valid texels say on which side of
// their own hard edge they lie. Where a penumbra is narrower on the screen
// than a texel (a floor seen nearly edge-on foreshortens it), the texels
// either side of the edge keep nearly their hard values, and interpolating
// between them would smear the edge over two texels; a texel across the
// edge from the fragment then counts by how far the filtering moved it from
// its hard value (fully from half the way). With VTK_SHADOW_SCREEN_REFINE
// what that leaves out, which the buffer could not resolve, is filtered
// again in light space over the penumbra's width the texels also carry
// (vtkShadowScreenRefine()).
#ifdef VTK_SHADOW_SCREEN_REFINE
float vtkShadowScreenUnresolved; // share of the lookup to refine, 0 to 1
float vtkShadowScreenRadius;     // the penumbra's half width there, world
#endif

float vtkShadowScreenVisibility(sampler2D screen, float hard)
{
  // Gathered at the four texels' shared corner as upper left, upper right,
  // lower right, lower left; reordered to lower left, lower right, upper
  // left, upper right.
  vec4 codes = textureGather(screen, vtkShadowScreenCorner).wzxy;
#ifdef VTK_SHADOW_SCREEN_GUIDED
  vec4 lit = vec4(lessThan(codes, vec4(0.0)));
  codes = abs(codes);
#endif
#ifdef VTK_SHADOW_SCREEN_REFINE
  vec4 code = floor(codes / 524288.0); // the penumbra's width
  codes -= code * 524288.0;
#endif
  vec4 visibility = floor(codes / 2048.0);
  vec4 distances = codes - 2048.0 * visibility;
  vec4 valid = vec4(notEqual(visibility, vec4(255.0)));
  vec4 weights = vtkShadowScreenWeights *
    vec4(lessThanEqual(abs(distances - vtkShadowScreenFragment), vec4(vtkShadowScreenTolerance))) *
    vec4(greaterThan(distances, vec4(0.0)));
  vec4 values = mix(vec4(hard), visibility / 254.0, valid);
#ifdef VTK_SHADOW_SCREEN_GUIDED
  vec4 across = abs(lit - (hard >= 0.5 ? 1.0 : 0.0)) * valid;
  vec4 keep = 1.0 - across * (1.0 - clamp(abs(values - lit) * 2.0, 0.0, 1.0));
#ifdef VTK_SHADOW_SCREEN_REFINE
  // The texels' penumbra width (vtkShadowWidthCode()) where they have one;
  // exp2 of the mean code, one exp2 rather than four.
  vec4 widths = weights * valid * vec4(greaterThan(code, vec4(0.0)));
  float wide = dot(widths, vec4(1.0));
  vtkShadowScreenRadius =
    wide > 0.0 ? 0.5 * vtkShadowScreenTexelSize * exp2(0.5 * dot(widths, code) / wide) : 0.0;
  vtkShadowScreenUnresolved = 1.0 - min(min(keep.x, keep.y), min(keep.z, keep.w));
#endif
  // None kept (the fragment alone on its side): the unguided lookup.
  weights *= dot(weights, keep) > 0.0 ? keep : vec4(1.0);
#endif
  float total = dot(weights, vec4(1.0));
  return total > 0.0 ? dot(weights, values) / total : hard;
}

#ifdef VTK_SHADOW_SCREEN_REFINE
// The n-th of 16 taps on a disc of the penumbra's half width on the
// receiver's plane: a golden-angle spiral, turned per pixel (within the
// viewport, so the same wherever it lies) against banding; an orthonormal
// basis across the normal without a square root (Duff et al. 2017) and
// interleaved gradient noise (Jimenez 2014) for the turn.
vec4 vtkShadowScreenTap(vec4 positionWC, vec3 normalWC, int n)
{
  vec3 v = normalWC;
  float s = v.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + v.z);
  float b = v.x * v.y * a;
  vec3 t1 = vec3(1.0 + s * v.x * v.x * a, s * b, -s * v.x);
  vec3 t2 = vec3(b, s + v.y * v.y * a, -v.y);
  vec2 pixel = floor(gl_FragCoord.xy - vtkShadowViewportOrigin);
  float angle = 2.3999632 * float(n) +
    6.2831853 * fract(52.982919 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
  float radius = vtkShadowScreenRadius * sqrt((float(n) + 0.5) / 16.0);
  return positionWC + vec4(radius * (cos(angle) * t1 + sin(angle) * t2), 0.0);
}

// How many taps vtkShadowScreenRefine() takes: 16 where the screen-space
// lookup left something out and the penumbra spans less than two texel
// steps along the surface's most foreshortened screen axis, else none. (A
// software rasterizer still runs one masked iteration of a loop no pixel of
// a group enters: on llvmpipe every fragment pays about one tap.)
int vtkShadowScreenRefineTaps()
{
  return vtkShadowScreenUnresolved > 0.0 && vtkShadowScreenRadius > 0.0 &&
      vtkShadowScreenRadius * vtkShadowScreenRadius < vtkShadowScreenLongestStep2
    ? 16
    : 0;
}

// Where the screen-space lookup could not resolve a penumbra, the mean of
// light `i`'s hard shadow over a disc of the penumbra's width on the
// receiver (the light's own shape, as the PCF filter takes it on the
// screen), blended in by the share left out.
#if VTK_SHADOW_MAPS > 0
float vtkShadowScreenRefine(float visibility, sampler2DShadow map, int i, vec4 positionWC, vec3 normalWC)
{
  int taps = vtkShadowScreenRefineTaps();
  float sum = 0.0;
  for (int n = 0; n < taps; ++n)
  {
    vec4 tap = vtkShadowScreenTap(positionWC, normalWC, n);
    sum += vtkShadowLookup(map, vtkShadowWorldToMap[i], vtkShadowReceiver(i, tap, normalWC), 0);
  }
  return taps > 0 ? mix(visibility, sum / 16.0, vtkShadowScreenUnresolved) : visibility;
}
#endif

#if VTK_SHADOW_CUBES > 0
float vtkShadowScreenRefine(float visibility, samplerCube cube, vec3 center, float range,
  vec4 positionWC, vec3 normalWC)
{
  int taps = vtkShadowScreenRefineTaps();
  float sum = 0.0;
  for (int n = 0; n < taps; ++n)
  {
    vec4 tap = vtkShadowScreenTap(positionWC, normalWC, n);
    sum += vtkShadowCubeLookup(cube, center, tap, normalWC, vtkShadowCubeTexel,
      vtkShadowNormalBias, vtkShadowDistanceBias, range, 0);
  }
  return taps > 0 ? mix(visibility, sum / 16.0, vtkShadowScreenUnresolved) : visibility;
}
#endif
#endif
#endif
