// Shadow term of the receivers' fragment shaders, shared by every technique.
// Inserted by vtkSoftShadowPass after VTK_SHADOW_LIGHTS (number of shadowed
// lights) and, for screen-space techniques, VTK_SHADOW_SCREEN_SPACE are
// defined. Arrays are indexed with constants only (GLSL 1.50 samplers).

uniform mat4 vtkShadowViewToWorld;
uniform mat4 vtkShadowWorldToMap[VTK_SHADOW_LIGHTS];
uniform float vtkShadowAttenuation[VTK_SHADOW_LIGHTS];
uniform sampler2DShadow vtkShadowMap[VTK_SHADOW_LIGHTS];
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
