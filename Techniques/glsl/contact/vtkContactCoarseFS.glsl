// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Before pass 4, PCF variant: the coarse level its widest discs tap
// (vtkContactPCFFS.glsl), a texel per 2x2 block of the distance map's
// texels (their visibility and distance, which the early-out and the
// dilation leave as they are). Of the block's texels on its farthest
// surface (within the same-surface tolerance of the farthest camera
// distance): the sum of their visibilities and their count, both over 4,
// and their mean camera distance.
// A block across a silhouette so keeps the receiver behind it, where an
// occluder's shadow meets its outline in the view, and drops the occluder's
// texels (their discs find few other texels near them either); the
// background (distance 0) is never the farthest surface.
// Uses: vtkShadowScreenCommonFS.glsl, vtkContactCommonFS.glsl.
void main()
{
  ivec2 blocks = (textureSize(contactMap, 0) + 1) / 2;
  ivec2 first = 2 * ivec2(texCoord * vec2(blocks));
  vec4 a = vtkContactFetch(first);
  vec4 b = vtkContactFetch(first + ivec2(1, 0));
  vec4 c = vtkContactFetch(first + ivec2(0, 1));
  vec4 d = vtkContactFetch(first + ivec2(1, 1));
  vec4 distances = vec4(a.b, b.b, c.b, d.b);
  float farthest = max(max(a.b, b.b), max(c.b, d.b));
  vec4 kept = vec4(lessThanEqual(farthest - distances, vec4(contactDepthTolerance * farthest)));
  kept *= farthest > 0.0 ? 0.25 : 0.0;
  float count = dot(kept, vec4(1.0));
  gl_FragData[0] = vec4(dot(kept, vec4(a.r, b.r, c.r, d.r)),
    count > 0.0 ? dot(kept, distances) / count : 0.0, count, 0.0);
}
