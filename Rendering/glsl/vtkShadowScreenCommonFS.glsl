//VTK::System::Dec
//VTK::Output::Dec

// Shared by every screen-space shadow pass: the camera depth pre-pass and
// the matrix taking its clip coordinates back to world coordinates.
in vec2 texCoord;
uniform sampler2D vtkScreenDepth;
uniform mat4 vtkScreenClipToWorld;

ivec2 vtkScreenPixel()
{
  return ivec2(gl_FragCoord.xy);
}

// Depth 1.0 is background: no surface, nothing to shadow.
bool vtkScreenHasSurface(out float depth)
{
  depth = texelFetch(vtkScreenDepth, vtkScreenPixel(), 0).r;
  return depth < 1.0;
}

vec4 vtkScreenPositionWC(float depth)
{
  vec4 clip = vec4(texCoord * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  vec4 world = vtkScreenClipToWorld * clip;
  return vec4(world.xyz / world.w, 1.0);
}
