// Shadow term of the receivers' fragment shaders, shared by every technique.
// Inserted by vtkSoftShadowPass after VTK_SHADOW_LIGHTS (number of shadowed
// lights), VTK_SHADOW_MAPS and VTK_SHADOW_CUBES (how many of them have a 2D
// map, a cube map) and, for screen-space techniques, VTK_SHADOW_SCREEN_SPACE
// are defined. Sampler arrays are indexed with constants only (GLSL 1.50).
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
  vtkShadowScreenFragment = (log2(distance(positionWC.xyz, vtkShadowViewToWorld[3].xyz)) -
                              vtkShadowLogNear) * vtkShadowCodesPerLog + 1.0;
  // 2% (log2(1.02)) and rounding, plus the change of distance over a texel
  // on this fragment's own plane: on a floor seen nearly edge-on it exceeds
  // 2% from one texel to the next. (The derivatives are the primitive's
  // own, so they never cross a silhouette.)
  vec2 slope = vec2(dFdx(vtkShadowScreenFragment), dFdy(vtkShadowScreenFragment));
  vtkShadowScreenTolerance =
    0.0286 * vtkShadowCodesPerLog + 0.5 + dot(abs(slope), 1.0 / vtkShadowScreenScale);
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
// its hard value (fully from half the way), and the fragment's own
// full-resolution hard edge places the penumbra.
float vtkShadowScreenVisibility(sampler2D screen, float hard)
{
  // Gathered at the four texels' shared corner as upper left, upper right,
  // lower right, lower left; reordered to lower left, lower right, upper
  // left, upper right.
  vec4 codes = textureGather(screen, vtkShadowScreenCorner).wzxy;
  vec4 lit = vec4(greaterThanEqual(codes, vec4(8388608.0)));
  codes -= lit * 8388608.0;
  vec4 visibility = floor(codes / 2048.0);
  vec4 distances = codes - 2048.0 * visibility;
  vec4 valid = vec4(notEqual(visibility, vec4(4095.0)));
  vec4 weights = vtkShadowScreenWeights *
    vec4(lessThanEqual(abs(distances - vtkShadowScreenFragment), vec4(vtkShadowScreenTolerance))) *
    vec4(greaterThan(distances, vec4(0.0)));
  vec4 values = mix(vec4(hard), visibility / 4094.0, valid);
#ifdef VTK_SHADOW_SCREEN_GUIDED
  vec4 across = abs(lit - (hard >= 0.5 ? 1.0 : 0.0)) * valid;
  vec4 keep = 1.0 - across * (1.0 - clamp(abs(values - lit) * 2.0, 0.0, 1.0));
  // None kept (the fragment alone on its side): the unguided lookup.
  weights *= dot(weights, keep) > 0.0 ? keep : vec4(1.0);
#endif
  float total = dot(weights, vec4(1.0));
  return total > 0.0 ? dot(weights, values) / total : hard;
}
#endif
