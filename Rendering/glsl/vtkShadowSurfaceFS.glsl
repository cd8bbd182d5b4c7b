// The surface a mapper's fragment lies on, for the camera pass and the
// receivers (vtkSoftShadowPass): its world position and geometric normal,
// from the mapper's view-space position (vertexVCVSOutput).
uniform mat4 vtkShadowViewToWorld; // the camera's view to world matrix

// The normal from derivatives of the triangle's own interpolants: the
// face's true orientation, which the normal offset needs (interpolated
// normals lie on coarse meshes), and right at silhouettes too, unlike a
// depth buffer's.
void vtkShadowSurface(vec3 positionVC, out vec4 positionWC, out vec3 normalWC)
{
  positionWC = vtkShadowViewToWorld * vec4(positionVC, 1.0);
  normalWC = normalize(mat3(vtkShadowViewToWorld) * cross(dFdx(positionVC), dFdy(positionVC)));
}
