// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Tile classification for the prepare pass, step 1: per tile of
// contactTileSize^2 pixels of the distance map (contactMap, read through a
// bilinear sampler), the least and the greatest S (1 - r; the background
// reads lit, so a surface beside it has nothing to dilate there). S is 0 or
// 1 there, so a bilinear tap on a texel
// corner, the mean of four, is 1 only if all four are and 0 only if none
// is: a quarter of the fetches.
// Uses: vtkShadowScreenCommonFS.glsl, vtkContactCommonFS.glsl.

void main()
{
  ivec2 size = textureSize(contactMap, 0);
  ivec2 tiles = (size + contactTileSize - 1) / contactTileSize;
  ivec2 first = ivec2(texCoord * vec2(tiles)) * contactTileSize;
  float least = 1.0;
  float greatest = 0.0;
  for (int y = 1; y < contactTileSize; y += 2)
  {
    for (int x = 1; x < contactTileSize; x += 2)
    {
      float s = 1.0 - texture(contactMap, vec2(first + ivec2(x, y)) / vec2(size)).r;
      least = min(least, s);
      greatest = max(greatest, s);
    }
  }
  gl_FragData[0] = vec4(least, greatest, 0.0, 0.0);
}
