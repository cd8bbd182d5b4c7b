// Pass 4, PCF variant: the mean of S over a square kernel of D pixels
// (clamped to the maximum), then pass 5's visibility.
uniform int maximumKernel;

void main()
{
  ivec2 pixel = vtkScreenPixel();
  vec4 c = vtkContactFetch(pixel);
  float s = c.r;
  if (c.g > 0.0)
  {
    int radius = int(min(c.g, float(maximumKernel)) * 0.5);
    float sum = 0.0;
    float count = 0.0;
    for (int y = -radius; y <= radius; ++y)
    {
      for (int x = -radius; x <= radius; ++x)
      {
        vec4 t = vtkContactFetch(pixel + ivec2(x, y));
        if (vtkContactSameSurface(c, t))
        {
          sum += t.r;
          count += 1.0;
        }
      }
    }
    s = sum / count;
  }
  gl_FragData[0] = vtkContactOutput(c, s);
}
