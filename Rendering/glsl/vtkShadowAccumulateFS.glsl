// Reference technique: adds one light sample's binary visibility, weighted
// 1/N, to the light's visibility texture (additive blending).
uniform sampler2DShadow sampleMap;
uniform mat4 sampleWorldToMap;
uniform vec4 sampleEye;
uniform vec3 sampleAxis;
uniform vec2 sampleFootprint;
uniform float sampleNormalBias;
uniform float sampleWeight;

void main()
{
  float depth;
  if (!vtkScreenHasSurface(depth))
  {
    discard;
  }
  vec3 position = vtkScreenPositionWC(texCoord, depth);
  vec3 normal = vtkScreenNormalWC(depth, position);
  vec4 receiver = vtkShadowNormalOffset(
    vec4(position, 1.0), normal, sampleEye, sampleAxis, sampleFootprint, sampleNormalBias);
  vec4 p = sampleWorldToMap * receiver;
  p.xyz /= p.w;
  float lit = 1.0;
  if (p.w > 0.0 && all(greaterThanEqual(p.xyz, vec3(0.0))) && all(lessThanEqual(p.xyz, vec3(1.0))))
  {
    lit = texture(sampleMap, p.xyz);
  }
  gl_FragData[0] = vec4(lit * sampleWeight);
}
