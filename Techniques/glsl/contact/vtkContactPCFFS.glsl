// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Pass 4, PCF variant: the mean visibility over a disc of D pixels across
// on the receiver (clamped to the maximum; vtkContactSurfaceDistance2): the
// light's own shape, whose shadow of an edge the penumbra is. Then pass 5's
// visibility. Texels count by how much of them the disc covers, so the
// result changes smoothly with D.
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
    // The disc on the receiver is an ellipse on the screen: loop over its
    // bounding box only. With g the change of camera distance (in pixels'
    // world size) a pixel across, a tap lies sqrt(o.o + (g.o)^2) away, and
    // the ellipse reaches (reach + 1/2) sqrt(1 - g_i^2 / (1 + g.g)) along i.
    float perPixel = vtkContactPixelsPerLength(c);
    vec2 g = vtkContactSurfaceSlope(c, pixel, perPixel);
    vec2 extent = (reach + 0.5) * sqrt(max(1.0 - g * g / (1.0 + dot(g, g)), 0.0));
    ivec2 radius = ivec2(ceil(extent - 1.0));
    float edge2 = reach * reach;
    float halfInverseEdge = 0.5 / max(reach, 0.5);
    float sum = 0.0;
    float count = 0.0;
    for (int y = -radius.y; y <= radius.y; ++y)
    {
      for (int x = -radius.x; x <= radius.x; ++x)
      {
        vec4 t = vtkContactFetch(pixel + ivec2(x, y));
        if (vtkContactSameSurface(c, t))
        {
          // Coverage by the disc's edge, (R^2 - d^2) / 2R ~ R - d there: no root.
          float d2 = vtkContactSurfaceDistance2(c, t, vec2(x, y), perPixel);
          float w = clamp((edge2 - d2) * halfInverseEdge + 0.5, 0.0, 1.0);
          sum += w * t.r;
          count += w;
        }
      }
    }
    v = sum / count;
  }
  gl_FragData[0] = vtkContactOutput(c, v);
}
