// Reference technique, point lights: adds one light sample's binary
// visibility from its cube map, weighted 1/N, to the light's visibility
// texture (additive blending).
uniform samplerCube sampleCube;
uniform vec3 sampleEye;
uniform float sampleTexel;
uniform float sampleNormalBias;
uniform float sampleDistanceBias;
uniform float sampleRange;
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
  float lit = vtkShadowCubeLookup(sampleCube, sampleEye, vec4(position, 1.0), normal, sampleTexel,
    sampleNormalBias, sampleDistanceBias, sampleRange, 0);
  gl_FragData[0] = vec4(lit * sampleWeight);
}
