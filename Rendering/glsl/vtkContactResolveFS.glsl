// Pass 5's input for the multi-pass variant: visibility from the last blur.
void main()
{
  gl_FragData[0] = vec4(vtkContactVisibility(vtkContactFetch(vtkScreenPixel()).r));
}
