// Tile classification, step 2: spread step 1's tiles (contactMap here) over
// the reach of the prepare pass's neighbourhoods. A pixel of tile t reaches
// r pixels no further than tiles t +- ceil(r / tile size), so
//   x: least S over the early-out's reach: 1 where all of it is shadowed,
//   y: greatest S over the dilation's reach: 0 where none of it is.
// Both err on the safe side: a pixel near a tile's middle sees farther.
uniform int earlyOutTiles;
uniform int dilationTiles;

void main()
{
  ivec2 tile = ivec2(texCoord * vec2(textureSize(contactMap, 0)));
  float least = 1.0;
  for (int y = -earlyOutTiles; y <= earlyOutTiles; ++y)
  {
    for (int x = -earlyOutTiles; x <= earlyOutTiles; ++x)
    {
      least = min(least, vtkContactFetch(tile + ivec2(x, y)).r);
    }
  }
  float greatest = 0.0;
  for (int y = -dilationTiles; y <= dilationTiles; ++y)
  {
    for (int x = -dilationTiles; x <= dilationTiles; ++x)
    {
      greatest = max(greatest, vtkContactFetch(tile + ivec2(x, y)).g);
    }
  }
  gl_FragData[0] = vec4(least, greatest, 0.0, 0.0);
}
