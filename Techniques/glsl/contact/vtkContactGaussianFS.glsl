// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Pass 4, single Gaussian variant: a separable Gaussian blur of the
// visibility over D pixels on the receiver (clamped to the maximum; sigma =
// size / 3), run once along x, then along y writing pass 5's visibility.
// The texel just beyond D / 2 counts in part, so the result changes
// smoothly with D.
// Uses: vtkShadowScreenCommonFS.glsl, vtkContactCommonFS.glsl.
uniform ivec2 contactDirection;
uniform bool contactLastPass;

void main()
{
  ivec2 pixel = vtkShadowScreenPixel();
  vec4 c = vtkContactFetch(pixel);
  float v = c.r;
  if (c.a > 0.0)
  {
    float size = min(c.a, float(contactMaximumKernel));
    float reach = size * 0.5;
    int radius = int(reach) + 1;
    float sigma = max(size / 3.0, 0.5);
    float perPixel = vtkContactPixelsPerLength(c);
    float sum = 0.0;
    float weights = 0.0;
    for (int i = -radius; i <= radius; ++i)
    {
      vec4 t = vtkContactFetch(pixel + i * contactDirection);
      if (vtkContactSameSurface(c, t))
      {
        // Along the receiver (vtkContactSurfaceDistance2), not the screen.
        float d2 = vtkContactSurfaceDistance2(c, t, vec2(float(i), 0.0), perPixel);
        float w = exp(-0.5 * d2 / (sigma * sigma)) * clamp(reach + 1.0 - sqrt(d2), 0.0, 1.0);
        sum += w * t.r;
        weights += w;
      }
    }
    v = sum / weights;
  }
  gl_FragData[0] = contactLastPass ? vtkContactOutput(c, v) : vec4(v, c.gba);
}
