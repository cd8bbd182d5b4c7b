// Pass 5's input for the multi-pass variant: visibility from the last blur.
void main()
{
  vec4 c = vtkContactFetch(vtkScreenPixel());
  gl_FragData[0] = vtkContactOutput(c, c.r);
}
