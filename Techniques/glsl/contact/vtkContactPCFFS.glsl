// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Pass 4, PCF variant: the mean visibility over a disc of D pixels across
// on the receiver (clamped to the maximum; vtkContactSurfaceDistance2): the
// light's own shape, whose shadow of an edge the penumbra is. Then pass 5's
// visibility. Texels count by how much of them the disc covers, so the
// result changes smoothly with D.
// Reads the distance map (contactMap) and settles each pixel's D itself
// (vtkContactPrepareTexelFS.glsl): one pass, drawn only over the tiles where
// there is anything to settle or blur; the camera pass wrote the other
// tiles' codes (vtkContactHardeningShadowPass::RenderScreenSpace()).
// Discs reaching at least contactCoarseReach texels from their centre along
// both screen axes tap the coarse level (vtkContactCoarseFS.glsl) instead: a
// quarter of the taps, for the edge blurred over two texels instead of one
// (the RMSE against the ray-cast truth stays as it was on the quality scenes;
// docs/benchmarks.md).
// Uses: vtkShadowScreenCommonFS.glsl, vtkContactCommonFS.glsl,
// vtkContactPrepareTexelFS.glsl.
uniform sampler2D contactCoarse;
const float contactCoarseReach = 4.0;

// How much of a tap `offset` texels from the centre `c`, at camera distance
// `b`, the disc covers: (R^2 - d^2) / 2R ~ R - d at its edge, no root
// (halfInverseEdge: 1 / 2R per texel of the tap's width).
float vtkContactCoverage(vec4 c, vec2 offset, float b, float perPixel, float edge2,
  float halfInverseEdge)
{
  float d2 = vtkContactSurfaceDistance2(c, vec4(0.0, 0.0, b, 0.0), offset, perPixel);
  return clamp((edge2 - d2) * halfInverseEdge + 0.5, 0.0, 1.0);
}

void main()
{
  ivec2 pixel = vtkShadowScreenPixel();
  vec4 c = vtkContactPrepareTexel(pixel);
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
    // Coarse where the ellipse is wide along both axes: a foreshortened
    // disc's short axis keeps its texels.
    bool coarse = min(extent.x, extent.y) >= contactCoarseReach;
    vec2 sum = vec2(0.0);
    // A software rasterizer runs a loop no fragment of a group enters once,
    // masked, where a branch would run both arms' taps.
    ivec2 fine = coarse ? ivec2(-1) : radius;
    for (int y = -fine.y; y <= fine.y; ++y)
    {
      for (int x = -fine.x; x <= fine.x; ++x)
      {
        vec4 t = vtkContactFetch(pixel + ivec2(x, y));
        if (vtkContactSameSurface(c, t))
        {
          float w = vtkContactCoverage(c, vec2(x, y), t.b, perPixel, edge2, halfInverseEdge);
          sum += w * vec2(t.r, 1.0);
        }
      }
    }
    // Blocks b cover texels 2b and 2b + 1; their centres lie 2b + 1/2 - pixel
    // from this texel's. Each adds its texels' visibilities and count.
    ivec2 first = coarse ? (pixel - radius) >> 1 : ivec2(0);
    ivec2 last = coarse ? (pixel + radius) >> 1 : ivec2(-1);
    ivec2 lastBlock = textureSize(contactCoarse, 0) - 1;
    for (int y = first.y; y <= last.y; ++y)
    {
      for (int x = first.x; x <= last.x; ++x)
      {
        ivec2 block = ivec2(x, y);
        vec4 t = texelFetch(contactCoarse, clamp(block, ivec2(0), lastBlock), 0);
        if (vtkContactSameSurface(c, vec4(0.0, 0.0, t.y, 0.0)))
        {
          vec2 offset = vec2(2 * block - pixel) + 0.5;
          float w = vtkContactCoverage(c, offset, t.y, perPixel, edge2, 0.5 * halfInverseEdge);
          sum += w * t.xz;
        }
      }
    }
    v = sum.y > 0.0 ? sum.x / sum.y : c.r;
  }
  gl_FragData[0] = vtkContactOutput(c, v);
}
