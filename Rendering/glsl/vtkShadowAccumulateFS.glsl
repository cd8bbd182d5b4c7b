// Reference technique: adds one light sample's binary visibility, weighted
// 1/N, to the light's visibility texture (additive blending).
uniform sampler2DShadow sampleMap;
uniform mat4 sampleWorldToMap;
uniform float sampleWeight;

void main()
{
  float depth;
  if (!vtkScreenHasSurface(depth))
  {
    discard;
  }
  vec4 p = sampleWorldToMap * vtkScreenPositionWC(depth);
  p.xyz /= p.w;
  float lit = 1.0;
  if (p.w > 0.0 && all(greaterThanEqual(p.xyz, vec3(0.0))) && all(lessThanEqual(p.xyz, vec3(1.0))))
  {
    lit = texture(sampleMap, p.xyz);
  }
  gl_FragData[0] = vec4(lit * sampleWeight);
}
