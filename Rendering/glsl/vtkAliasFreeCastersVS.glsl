// Caster triangles for the alias-free map: world positions for the
// geometry shader (vtkAliasFreeCastersGS.glsl), which does the projecting.

in vec3 vtkShadowVertexMC;
uniform mat4 vtkShadowModelToWorld;
out vec3 aliasfreeWorldIn;

void main()
{
  aliasfreeWorldIn = (vtkShadowModelToWorld * vec4(vtkShadowVertexMC, 1.0)).xyz;
  gl_Position = vec4(aliasfreeWorldIn, 1.0);
}
