// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Reference technique: adds one light sample's binary visibility, weighted
// 1/N, to the light's visibility texture (additive blending). The sample is
// a 2D depth map, or, when ACCUMULATE_CUBE is defined, a point light's cube
// map of squared distances.
// Uses: vtkShadowScreenCommonFS.glsl, vtkShadowNormalOffsetFS.glsl, vtkShadowCubeLookupFS.glsl.
uniform sampler2D referenceNormals; // the camera pass's face normals
uniform float referenceNormalBias;
uniform float referenceWeight;
#ifdef ACCUMULATE_CUBE
uniform samplerCube referenceCube;
uniform vec3 referenceCubeCenter;
uniform float referenceCubeTexel;
uniform float referenceDistanceBias;
uniform float referenceCubeRange;
#else
uniform sampler2DShadow referenceMap;
uniform mat4 referenceWorldToMap;
uniform vec4 referenceEye;
uniform vec3 referenceAxis;
uniform vec2 referenceFootprint;
#endif

void main()
{
  float depth;
  if (!vtkShadowScreenHasSurface(depth))
  {
    discard;
  }
  vec3 position = vtkShadowScreenPositionWC(texCoord, depth);
  // The face normal the camera pass wrote, right at silhouettes too. Where it
  // wrote none (points, lines, unlit fragments) the texel stays invalid: the
  // receivers keep their own hard shadow there.
  vec4 face = texelFetch(referenceNormals, vtkShadowScreenPixel(), 0);
  if (face.w < 0.5)
  {
    discard;
  }
  vec3 normal = face.xyz;
#ifdef ACCUMULATE_CUBE
  float lit = vtkShadowCubeLookup(referenceCube, referenceCubeCenter, vec4(position, 1.0), normal, referenceCubeTexel,
    referenceNormalBias, referenceDistanceBias, referenceCubeRange, 0);
#else
  vec4 receiver = vtkShadowNormalOffset(
    vec4(position, 1.0), normal, referenceEye, referenceAxis, referenceFootprint, referenceNormalBias);
  vec3 p;
  float lit = vtkShadowInMap(referenceWorldToMap, receiver, p) ? texture(referenceMap, p) : 1.0;
#endif
  // Summed over samples whose weights add up to 1: the visibility, valid,
  // and the surface's camera distance (vtkShadowScreenBuffers::BeginVisibility).
  float cameraDistance = distance(position, vtkShadowCameraPosition);
  gl_FragData[0] = vec4(lit, 1.0, cameraDistance, 0.0) * referenceWeight;
}
