// Pass 4, multi-pass variant: one Poisson-disk Gaussian blur of the
// visibility over a kernel of `kernelSize` pixels (sigma = size / 3, weights
// normalised), for pixels whose D is still positive; D drops by one. Only
// pixels the prepare pass selected for this pass are drawn (depth mask):
// those still blurring, and those whose D ran out in the pass before, copied
// so that both ping-pong buffers agree on them from then on.
uniform vec3 taps[64];
uniform int tapCount;
uniform float kernelSize;

void main()
{
  ivec2 pixel = vtkScreenPixel();
  vec4 c = vtkContactFetch(pixel);
  if (c.a <= 0.0)
  {
    gl_FragData[0] = c;
    return;
  }
  float sum = 0.0;
  float weights = 0.0;
  for (int i = 0; i < tapCount; ++i)
  {
    vec4 t = vtkContactFetch(pixel + ivec2(round(taps[i].xy * 0.5 * kernelSize)));
    if (vtkContactSameSurface(c, t))
    {
      sum += taps[i].z * t.r;
      weights += taps[i].z;
    }
  }
  gl_FragData[0] = vec4(sum / weights, c.g, c.b, max(c.a - 1.0, 0.0));
}
