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
// Point lights: cube maps of squared distances (vtkShadowCubeLookupFS.glsl).
uniform samplerCube vtkShadowCube[VTK_SHADOW_CUBES];
uniform vec3 vtkShadowCubeCenter[VTK_SHADOW_CUBES];
uniform float vtkShadowCubeRange[VTK_SHADOW_CUBES]; // 0: float map; else RGBA8 range
uniform float vtkShadowCubeTexel;   // a texel's world size per unit of distance
uniform float vtkShadowDistanceBias; // multiplicative, on squared distances
#endif

#ifdef VTK_SHADOW_SCREEN_SPACE
uniform sampler2D vtkShadowScreen[VTK_SHADOW_LIGHTS];
uniform sampler2D vtkShadowCameraDepth;
uniform vec2 vtkShadowViewportOrigin;

// Screen-space visibility belongs to the nearest opaque surface, the one the
// camera depth pre-pass saw; other fragments (translucent ones) take the hard
// shadow of the light's own map instead.
bool vtkShadowOnScreenSurface()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy - vtkShadowViewportOrigin);
  return abs(texelFetch(vtkShadowCameraDepth, pixel, 0).r - gl_FragCoord.z) <= 1.0e-5;
}

float vtkShadowScreenValue(sampler2D screen)
{
  return texelFetch(screen, ivec2(gl_FragCoord.xy - vtkShadowViewportOrigin), 0).r;
}
#endif
