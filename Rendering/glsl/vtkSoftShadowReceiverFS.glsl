// Shadow term of the receivers' fragment shaders, shared by every technique.
// Inserted by vtkSoftShadowPass after VTK_SHADOW_LIGHTS (number of shadowed
// lights), VTK_SHADOW_MAPS and VTK_SHADOW_CUBES (how many of them have a 2D
// map, a cube map) and, for screen-space techniques, VTK_SHADOW_SCREEN_SPACE
// are defined. Sampler arrays are indexed with constants only (GLSL 1.50).

uniform mat4 vtkShadowViewToWorld;
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
  vec4 p = worldToMap * positionWC;
  if (p.w <= 0.0)
  {
    return 1.0;
  }
  p.xyz /= p.w;
  if (any(lessThan(p.xyz, vec3(0.0))) || any(greaterThan(p.xyz, vec3(1.0))))
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
// Point lights (Gerasimov, GPU Gems ch. 12): cube maps of squared distances
// to the light, looked up with the light-to-fragment direction.
uniform samplerCube vtkShadowCube[VTK_SHADOW_CUBES];
uniform vec3 vtkShadowCubeCenter[VTK_SHADOW_CUBES];
uniform float vtkShadowCubeTexel;   // a texel's world size per unit of distance
uniform float vtkShadowDistanceBias; // multiplicative, on squared distances

float vtkShadowCubeLookup(samplerCube cube, vec3 center, vec4 positionWC, vec3 normalWC,
  int radius)
{
  vec3 toPoint = positionWC.xyz - center;
  // Normal offset by vtkShadowNormalBias texels, towards the light.
  vec3 n = dot(normalWC, toPoint) > 0.0 ? -normalWC : normalWC;
  float axis = max(abs(toPoint.x), max(abs(toPoint.y), abs(toPoint.z)));
  float texel = vtkShadowCubeTexel * axis;
  vec3 d = toPoint + n * (texel * vtkShadowNormalBias);
  // Section 12.3.7: the multiplicative bias "works best in practice".
  float reference = dot(d, d) * vtkShadowDistanceBias;
  if (radius == 0)
  {
    return reference <= texture(cube, d).r ? 1.0 : 0.0;
  }
  // Section 12.4: 4-tap PCF, the taps `radius` texels apart across d.
  vec3 u = normalize(cross(d, abs(d.x) < 0.9 * length(d) ? vec3(1.0, 0.0, 0.0)
                                                          : vec3(0.0, 1.0, 0.0)));
  vec3 v = cross(normalize(d), u);
  float step = 0.5 * float(radius) * texel;
  float lit = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    vec2 o = vec2((i & 1) == 0 ? -1.0 : 1.0, (i & 2) == 0 ? -1.0 : 1.0) * step;
    lit += reference <= texture(cube, d + o.x * u + o.y * v).r ? 0.25 : 0.0;
  }
  return lit;
}
#endif

#ifdef VTK_SHADOW_SCREEN_SPACE
uniform sampler2D vtkShadowScreen[VTK_SHADOW_LIGHTS];
uniform sampler2D vtkShadowCameraDepth;
uniform vec2 vtkShadowViewportOrigin;

// Screen-space visibility belongs to the nearest opaque surface, which the
// camera depth pre-pass saw. Other fragments (translucent ones) take the
// hard shadow of the light's own map.
float vtkShadowScreenVisibility(
  sampler2D screen, sampler2DShadow map, mat4 worldToMap, vec4 receiverWC)
{
  ivec2 pixel = ivec2(gl_FragCoord.xy - vtkShadowViewportOrigin);
  float depth = texelFetch(vtkShadowCameraDepth, pixel, 0).r;
  if (abs(depth - gl_FragCoord.z) <= 1.0e-5)
  {
    return texelFetch(screen, pixel, 0).r;
  }
  return vtkShadowLookup(map, worldToMap, receiverWC, 0);
}
#endif
