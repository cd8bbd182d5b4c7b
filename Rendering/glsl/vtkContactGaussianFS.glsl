// Pass 4, single Gaussian variant: a separable Gaussian blur of S over D
// pixels (clamped to the maximum; sigma = size / 3), run once along x, then
// along y writing pass 5's visibility.
uniform int maximumKernel;
uniform ivec2 direction;
uniform bool lastPass;

void main()
{
  ivec2 pixel = vtkScreenPixel();
  vec4 c = vtkContactFetch(pixel);
  float s = c.r;
  if (c.g > 0.0)
  {
    float size = min(c.g, float(maximumKernel));
    int radius = int(size * 0.5);
    float sigma = max(size / 3.0, 0.5);
    float sum = 0.0;
    float weights = 0.0;
    for (int i = -radius; i <= radius; ++i)
    {
      vec4 t = vtkContactFetch(pixel + i * direction);
      if (vtkContactSameSurface(c, t))
      {
        float w = exp(-0.5 * float(i * i) / (sigma * sigma));
        sum += w * t.r;
        weights += w;
      }
    }
    s = sum / weights;
  }
  gl_FragData[0] = lastPass ? vtkContactOutput(c, s) : vec4(s, c.gba);
}
