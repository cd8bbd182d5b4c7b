// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Tile classification, step 2: spread step 1's tiles (contactMap here) over
// the reach of the prepare pass's neighbourhoods. A pixel of tile t reaches
// r pixels no further than tiles t +- ceil(r / tile size), so
//   x: least S over the early-out's reach: 1 where all of it is shadowed,
//   y: greatest S over the dilation's reach: 0 where none of it is.
// Both err on the safe side: a pixel near a tile's middle sees farther.
//   a: 1 where the prepare pass has work in the tile, 0 where it would write
//      what the camera pass wrote already: all lit (no D, nothing to
//      dilate) or, with the early-out, all umbra (D dropped).
// Uses: vtkShadowScreenCommonFS.glsl, vtkContactCommonFS.glsl.

void main()
{
  ivec2 tile = ivec2(texCoord * vec2(textureSize(contactMap, 0)));
  // One loop over both reaches: each tile is fetched once.
  int reach = max(contactEarlyOutTiles, contactDilationTiles);
  float least = 1.0;
  float greatest = 0.0;
  for (int y = -reach; y <= reach; ++y)
  {
    for (int x = -reach; x <= reach; ++x)
    {
      vec2 t = vtkContactFetch(tile + ivec2(x, y)).rg;
      int apart = max(abs(x), abs(y));
      least = apart <= contactEarlyOutTiles ? min(least, t.x) : least;
      greatest = apart <= contactDilationTiles ? max(greatest, t.y) : greatest;
    }
  }
  bool settled = greatest <= 0.0 || (contactEarlyOut && least >= 1.0);
  gl_FragData[0] = vec4(least, greatest, 0.0, settled ? 0.0 : 1.0);
}
