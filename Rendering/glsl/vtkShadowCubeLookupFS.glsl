// Point lights (Gerasimov, GPU Gems ch. 12): visibility from a cube map of
// squared distances to the light, looked up with the light-to-fragment
// direction. Shared by receivers and screen-space passes.
//
// texel: a cube texel's world size per unit of distance (2 / size);
// normalBias: the normal offset in texels; distanceBias: the multiplicative
// bias on squared distances; radius: 0 for one tap, else 4-tap PCF with the
// taps `radius` texels apart.
float vtkShadowCubeLookup(samplerCube cube, vec3 center, vec4 positionWC, vec3 normalWC,
  float texel, float normalBias, float distanceBias, int radius)
{
  vec3 toPoint = positionWC.xyz - center;
  // Normal offset, towards the light.
  vec3 n = dot(normalWC, toPoint) > 0.0 ? -normalWC : normalWC;
  float axis = max(abs(toPoint.x), max(abs(toPoint.y), abs(toPoint.z)));
  float size = texel * axis;
  vec3 d = toPoint + n * (size * normalBias);
  // Section 12.3.7: the multiplicative bias "works best in practice".
  float reference = dot(d, d) * distanceBias;
  if (radius == 0)
  {
    return reference <= texture(cube, d).r ? 1.0 : 0.0;
  }
  // Section 12.4: 4-tap PCF across the direction.
  vec3 u = normalize(cross(d, abs(d.x) < 0.9 * length(d) ? vec3(1.0, 0.0, 0.0)
                                                          : vec3(0.0, 1.0, 0.0)));
  vec3 v = cross(normalize(d), u);
  float step = 0.5 * float(radius) * size;
  float lit = 0.0;
  for (int i = 0; i < 4; ++i)
  {
    vec2 o = vec2((i & 1) == 0 ? -1.0 : 1.0, (i & 2) == 0 ? -1.0 : 1.0) * step;
    lit += reference <= texture(cube, d + o.x * u + o.y * v).r ? 0.25 : 0.0;
  }
  return lit;
}
