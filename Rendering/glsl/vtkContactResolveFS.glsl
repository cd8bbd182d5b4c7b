// Pass 5 of the multi-pass variant in the debug view: the last blur's
// visibility marked as in the paper's figure 4. (Otherwise the last blur
// writes the receivers' texture itself.)
void main()
{
  vec4 c = vtkContactFetch(vtkScreenPixel());
  gl_FragData[0] = vtkContactOutput(c, c.r);
}
