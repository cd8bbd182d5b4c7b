//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
// Pass 2's fragments (Valient & Bujnak, section 2.1.1): keep only the thick
// silhouette, and write the signed distance to its nearest point (texels,
// positive on the face's side) and that point's depth. The paper's
// LESS-EQUAL depth and distance tests become one depth test on a key: the
// silhouette nearest in the map wins, and of two as near the nearer to the
// light. (Depth first lets a silhouette nearer the light take texels that
// lie closer to another, which wide soft-shadow bands make common: on a
// fence, a picket's band covers its neighbours'.)
// Uses: vtkSilhouetteEdgesVS.glsl or, with SILHOUETTE_BANDS,
// vtkSilhouetteBandsGS.glsl (their outputs).

#ifdef SILHOUETTE_BANDS
flat in vec3 silhouetteEdgeA; // the edge's ends and the face's third corner:
flat in vec3 silhouetteEdgeB; // texel x, y and depth in [0, 1]
flat in vec3 silhouetteOpposite;
#else
flat in vec3 silhouetteCorner[3];
flat in int silhouetteEdges;
#endif
flat in float silhouetteReach; // this face's w_sc
uniform float silhouetteHalfWidth;  // the widest w_sc, texels: the map's distance range
#ifndef SILHOUETTE_CUBE_FACE
uniform sampler2D silhouetteDepths; // pass 1's depths, raw
#endif

out vec4 fragOutput0; // r: signed distance (texels), g: the silhouette point's depth

float silhouetteCross(vec2 a, vec2 b, vec2 p)
{
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Edge ab of a face whose third corner is c, seen from texel p: if nearer
// than `nearest`, that distance, the depth of its nearest point, whether
// that point is an end, and the side of the edge's line p is on (1 the
// face's, -1 the other, 0 for a face seen edge-on).
void silhouetteNearest(vec2 p, vec3 a, vec3 b, vec3 c, inout float nearest, inout float depth,
  inout bool corner, inout float side)
{
  vec2 ab = b.xy - a.xy;
  float t = dot(p - a.xy, ab) / max(dot(ab, ab), 1.0e-12);
  float d = distance(p, a.xy + clamp(t, 0.0, 1.0) * ab);
  if (d < nearest)
  {
    nearest = d;
    depth = mix(a.z, b.z, clamp(t, 0.0, 1.0)); // depth is affine along a projected line
    corner = t <= 0.0 || t >= 1.0;
    // Inside is the side of the edge's line the face lies on: the face
    // may be far narrower than the thick silhouette.
    float face = silhouetteCross(a.xy, b.xy, c.xy);
    side = abs(face) < 1.0e-6 ? 0.0 : (silhouetteCross(a.xy, b.xy, p) * face >= 0.0 ? 1.0 : -1.0);
  }
}

void main()
{
  vec2 p = gl_FragCoord.xy;
  float nearest = 1.0e30;
  float depth = 1.0;
  float side = 0.0;
  bool corner = false;
#ifdef SILHOUETTE_BANDS
  // A rectangle around one edge (vtkSilhouetteBandsGS.glsl).
  silhouetteNearest(p, silhouetteEdgeA, silhouetteEdgeB, silhouetteOpposite, nearest, depth,
    corner, side);
#else
  for (int k = 0; k < 3; ++k)
  {
    if ((silhouetteEdges & (1 << k)) != 0)
    {
      silhouetteNearest(p, silhouetteCorner[k], silhouetteCorner[(k + 1) % 3],
        silhouetteCorner[(k + 2) % 3], nearest, depth, corner, side);
    }
  }
#endif
  if (nearest > silhouetteReach)
  {
    discard; // outside the thick silhouette
  }
#ifndef SILHOUETTE_CUBE_FACE
  if (corner || side == 0.0)
  {
    // Nearest to a corner of the silhouette, one edge's side is not the
    // silhouette's (beside a sharp convex corner it says inside), and a face
    // seen edge-on has no side: there the depth map tells, at this texel's
    // centre as it was rasterized: covered by a surface not behind the
    // silhouette is inside.
    side = depth <= texture(silhouetteDepths, p / vec2(textureSize(silhouetteDepths, 0))).r ? -1.0 : 1.0;
  }
#else
  // A cube face: its map holds squared distances, not this face's depth;
  // the face's own side decides, and a face seen edge-on leaves the texel
  // to its neighbour.
  if (side == 0.0)
  {
    discard;
  }
#endif
  fragOutput0 = vec4(side > 0.0 ? nearest : -nearest, depth, 0.0, 1.0);
  gl_FragDepth = 0.99 * nearest / silhouetteHalfWidth + 0.01 * clamp(depth, 0.0, 1.0);
}
