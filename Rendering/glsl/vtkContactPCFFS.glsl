// Pass 4, PCF variant: the mean visibility over a square kernel of D pixels
// (clamped to the maximum), then pass 5's visibility. Texels count by how
// much of them the kernel covers, so the result changes smoothly with D
// (a kernel of whole texels makes steps where D crosses an odd number).
// Uses: vtkShadowScreenCommonFS.glsl, vtkContactCommonFS.glsl.
uniform int contactMaximumKernel;

void main()
{
  ivec2 pixel = vtkShadowScreenPixel();
  vec4 c = vtkContactFetch(pixel);
  float v = c.r;
  if (c.a > 0.0)
  {
    float reach = min(c.a, float(contactMaximumKernel)) * 0.5;
    int radius = int(ceil(reach - 0.5));
    float sum = 0.0;
    float count = 0.0;
    for (int y = -radius; y <= radius; ++y)
    {
      for (int x = -radius; x <= radius; ++x)
      {
        vec4 t = vtkContactFetch(pixel + ivec2(x, y));
        if (vtkContactSameSurface(c, t))
        {
          vec2 cover = clamp(vec2(reach + 0.5) - abs(vec2(x, y)), 0.0, 1.0);
          float w = cover.x * cover.y;
          sum += w * t.r;
          count += w;
        }
      }
    }
    v = sum / count;
  }
  gl_FragData[0] = vtkContactOutput(c, v);
}
