// Reference technique: adds one light sample's binary visibility, weighted
// 1/N, to the light's visibility texture (additive blending). The sample is
// a 2D depth map, or, when ACCUMULATE_CUBE is defined, a point light's cube
// map of squared distances.
uniform float sampleNormalBias;
uniform float sampleWeight;
#ifdef ACCUMULATE_CUBE
uniform samplerCube sampleCube;
uniform vec3 sampleEye;
uniform float sampleTexel;
uniform float sampleDistanceBias;
uniform float sampleRange;
#else
uniform sampler2DShadow sampleMap;
uniform mat4 sampleWorldToMap;
uniform vec4 sampleEye;
uniform vec3 sampleAxis;
uniform vec2 sampleFootprint;
#endif

void main()
{
  float depth;
  if (!vtkScreenHasSurface(depth))
  {
    discard;
  }
  vec3 position = vtkScreenPositionWC(texCoord, depth);
  vec3 normal = vtkScreenNormalWC(depth, position);
#ifdef ACCUMULATE_CUBE
  float lit = vtkShadowCubeLookup(sampleCube, sampleEye, vec4(position, 1.0), normal, sampleTexel,
    sampleNormalBias, sampleDistanceBias, sampleRange, 0);
#else
  vec4 receiver = vtkShadowNormalOffset(
    vec4(position, 1.0), normal, sampleEye, sampleAxis, sampleFootprint, sampleNormalBias);
  vec4 p = sampleWorldToMap * receiver;
  p.xyz /= p.w;
  float lit = 1.0;
  if (p.w > 0.0 && all(greaterThanEqual(p.xyz, vec3(0.0))) && all(lessThanEqual(p.xyz, vec3(1.0))))
  {
    lit = texture(sampleMap, p.xyz);
  }
#endif
  // Summed over samples whose weights add up to 1: the visibility, valid,
  // and the surface's camera distance (vtkShadowScreenBuffers::BeginVisibility).
  float cameraDistance = distance(position, vtkScreenCameraPosition);
  gl_FragData[0] = vec4(lit, 1.0, cameraDistance, 0.0) * sampleWeight;
}
