// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// The surface a mapper's fragment lies on, for the camera pass and the
// receivers (vtkSoftShadowPass): its geometric normal from the mapper's
// view-space position (vertexVC: imposters ray-cast it in the fragment
// shader); vtkShadowShaderSources::GetSurfaceCode() gives both, in view and
// world coordinates.
// Uses: nothing but the mapper's shader (vertexVC, normalVC).
uniform mat4 vtkShadowViewToWorld; // the camera's view to world matrix
// The normal from derivatives of the fragment's own position: the face's
// true orientation, which the normal offset needs (interpolated normals lie
// on coarse meshes), and right at silhouettes too, unlike a depth buffer's.
// Where it is undefined, the mapper's shading normal `normalVC`: points and
// lines (their position does not vary across them), and imposters' edges
// (a neighbour in the pixel quad was discarded), points drawn as spheres and
// lines as tubes (`flatQuad`: they move only their depth, see vtkShadowDepthStage,
// so their position's derivatives are those of the flat sprite or quad).
// faceVC is not unit. Returns whether the face was defined.
bool vtkShadowFace(vec3 positionVC, vec3 normalVC, bool flatQuad, out vec3 faceVC)
{
  vec3 face = cross(dFdx(positionVC), dFdy(positionVC));
  float size = dot(face, face);
  bool defined = !flatQuad && size > 0.0 && size < 1.0e30; // false for NaN too
  faceVC = defined ? face : normalVC;
  return defined;
}
