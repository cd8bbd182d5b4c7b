// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Pass 4, multi-pass variant: one Poisson-disk Gaussian blur of the
// visibility over a kernel of `kernelSize` pixels (sigma = size / 3, weights
// normalised), for pixels whose D is still positive, the kernel shrunk where
// D < 1; D drops by one. Only
// pixels the prepare pass selected for this pass are drawn (depth mask):
// those still blurring, and those whose D ran out in the pass before, copied
// so that both ping-pong buffers agree on them from then on. Each also
// writes its code into the receivers' texture.
// Uses: vtkShadowScreenCommonFS.glsl, vtkShadowScreenCodeFS.glsl,
// vtkContactCommonFS.glsl.
uniform vec3 contactTaps[64]; // offsets in pixels (not rounded) for this pass's kernel, and weights
uniform int contactTapCount;
uniform float contactKernelSize; // this pass's, in pixels

void main()
{
  ivec2 pixel = vtkShadowScreenPixel();
  vec4 c = vtkContactFetch(pixel);
  vec4 texel = c;
  if (c.a > 0.0)
  {
    // The last pass of a fractional D < 1 shrinks its kernel by sqrt(D),
    // so that it adds D times its variance: blending the whole blur in by D
    // instead would keep 1 - D of the sharp edge.
    float scale = sqrt(min(c.a, 1.0));
    // Taps weigh by their distance along the receiver too
    // (vtkContactSurfaceDistance2): the Gaussian's weight for the part the
    // screen offset leaves out.
    float size = contactKernelSize * scale;
    float falloff = -4.5 / max(size * size, 1.0e-6);
    float perPixel = vtkContactPixelsPerLength(c);
    // Tap 0 lies at the origin: this pixel.
    float sum = contactTaps[0].z * c.r;
    float weights = contactTaps[0].z;
    for (int i = 1; i < contactTapCount; ++i)
    {
      ivec2 offset = ivec2(floor(contactTaps[i].xy * scale + 0.5));
      vec4 t = vtkContactFetch(pixel + offset);
      if (vtkContactSameSurface(c, t))
      {
        vec2 o = vec2(offset);
        float w = contactTaps[i].z *
          exp(falloff * (vtkContactSurfaceDistance2(c, t, o, perPixel) - dot(o, o)));
        sum += w * t.r;
        weights += w;
      }
    }
    texel = vec4(sum / weights, c.g, c.b, max(c.a - 1.0, 0.0));
  }
  gl_FragData[0] = texel;
  // The pixel's code for the receivers: its last pass leaves the final one.
  gl_FragData[1] = vec4(vtkShadowPackTexel(texel));
}
