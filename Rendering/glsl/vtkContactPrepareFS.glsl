// Between passes 2 and 4: the umbra early-out (section 5: D = 0 where the
// whole neighbourhood is shadowed) and the optional dilation of D (pass 3).
// Writes the same texel to both ping-pong buffers, and a depth that lets
// multi-pass blur k (drawn at depth 1 - k / 256) through only where D > k - 1:
// the ceil(D) passes that blur the pixel and one more that copies its final
// value into the other buffer. Elsewhere depth 1: no blur touches it.
uniform bool earlyOut;
uniform int earlyOutRadius;
uniform bool dilation;
uniform float dilationSize;
uniform vec3 taps[64]; // Poisson offsets in [-1,1]^2 and Gaussian weights
uniform int tapCount;

// Every Poisson tap over the early-out kernel is shadowed: a sampled test of
// the section 5 neighbourhood, at the cost of one blur.
bool vtkContactDeepUmbra(ivec2 pixel)
{
  for (int i = 1; i < tapCount; ++i)
  {
    if (vtkContactFetch(pixel + ivec2(round(taps[i].xy * float(earlyOutRadius)))).r < 1.0)
    {
      return false;
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
    // Every lit pixel pays for this, and D varies slowly: 8 taps are enough.
    float sum = 0.0;
    float weights = 0.0;
    for (int i = 0; i < min(tapCount, 8); ++i)
    {
      vec4 t = vtkContactFetch(pixel + ivec2(round(taps[i].xy * 0.5 * dilationSize)));
      if (t.r > 0.0 && vtkContactSameSurface(c, t))
      {
        sum += taps[i].z * t.g;
        weights += taps[i].z;
      }
    }
    d = weights > 0.0 ? sum / weights : 0.0;
  }
  // Below one (a pass, a pixel) a blur changes nothing worth the pixel's
  // sharper full-resolution hard shadow in the receivers.
  d = d >= 1.0 ? d : 0.0;
  vec4 result = vec4(c.r, d, c.b, d > 0.0 ? 1.0 : 0.0);
  gl_FragData[0] = result;
  gl_FragData[1] = result;
  gl_FragDepth = d > 0.0 ? 1.0 - (min(ceil(d), 254.0) + 1.0) / 256.0 : 1.0;
}
