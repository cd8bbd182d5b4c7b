//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Screen-space passes drawn tile by tile (vtkShadowScreenBuffers::DrawTiles()):
// a point the tile's size a tile (gl_VertexID), centred on it, which a
// software rasterizer covers in whole blocks where two triangles would
// shade the blocks along their shared diagonal twice. A tile its texel does
// not select lies outside the clip volume and draws nothing. Points lose
// what lies past the viewport with their centre: one that would has its
// centre moved in, and covers some of the previous tile again.
// VTK's quad helper binds ndCoordIn and texCoordIn to its quad's vertices;
// a tiled draw binds no arrays, so they read their defaults, (0, 0, 0, 1)
// and (0, 0), and serve only to keep both in use.
// Uses: nothing.
in vec4 ndCoordIn;
in vec2 texCoordIn;
uniform sampler2D vtkShadowTiles; // a texel a tile, drawn where a > 0
uniform int vtkShadowTileSize;    // pixels on a tile's side
uniform vec2 vtkShadowTileTargetSize;

void main()
{
  int columns = textureSize(vtkShadowTiles, 0).x;
  ivec2 tile = ivec2(gl_VertexID % columns, gl_VertexID / columns);
  float size = float(vtkShadowTileSize);
  vec2 centre = min(vec2(tile) * size + 0.5 * size, vtkShadowTileTargetSize - 0.5);
  bool drawn = texelFetch(vtkShadowTiles, tile, 0).a > 0.0;
  gl_Position = drawn ? vec4(centre / vtkShadowTileTargetSize * 2.0 - 1.0, 0.0, 1.0)
                      : vec4(4.0 * ndCoordIn.w, 0.0, 0.0, 1.0);
  gl_PointSize = drawn ? size : texCoordIn.x;
}
