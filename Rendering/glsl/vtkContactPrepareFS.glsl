// Between passes 2 and 4: the umbra early-out (section 5: D = 0 where the
// whole neighbourhood is shadowed) and the optional dilation of D (pass 3).
// Writes the same texel to both ping-pong buffers, with D = -1 wherever no
// blur will touch it.
uniform bool earlyOut;
uniform int earlyOutRadius;
uniform bool dilation;
uniform float dilationSize;
uniform vec3 taps[64]; // Poisson offsets in [-1,1]^2 and Gaussian weights
uniform int tapCount;

// Every texel on a 9 x 9 grid spanning the early-out kernel is shadowed.
bool vtkContactDeepUmbra(ivec2 pixel)
{
  int stride = max(1, earlyOutRadius / 4);
  for (int y = -earlyOutRadius; y <= earlyOutRadius; y += stride)
  {
    for (int x = -earlyOutRadius; x <= earlyOutRadius; x += stride)
    {
      if (vtkContactFetch(pixel + ivec2(x, y)).r < 1.0)
      {
        return false;
      }
    }
  }
  return true;
}

void main()
{
  ivec2 pixel = vtkScreenPixel();
  vec4 c = vtkContactFetch(pixel);
  float d = c.g;
  if (d > 0.0 && earlyOut && vtkContactDeepUmbra(pixel))
  {
    d = 0.0;
  }
  else if (c.r == 0.0 && c.b > 0.0 && dilation)
  {
    // Lit pixels near a shadow take the weighted mean D of the shadowed taps.
    float sum = 0.0;
    float weights = 0.0;
    for (int i = 0; i < tapCount; ++i)
    {
      vec4 t = vtkContactFetch(pixel + ivec2(round(taps[i].xy * 0.5 * dilationSize)));
      if (t.g > 0.0 && vtkContactSameSurface(c, t))
      {
        sum += taps[i].z * t.g;
        weights += taps[i].z;
      }
    }
    d = weights > 0.0 ? sum / weights : 0.0;
  }
  vec4 result = vec4(c.r, d > 0.0 ? d : -1.0, c.b, 0.0);
  gl_FragData[0] = result;
  gl_FragData[1] = result;
}
