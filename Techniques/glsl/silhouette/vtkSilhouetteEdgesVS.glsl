//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Pass 2 of silhouette-distance shadow maps (Valient & Bujnak, section
// 2.1.1), over a topology aware mesh (vtkTopologyAwareMeshFilter): each
// vertex finds its face's silhouette edges from the light, collapses faces
// without one, and grows the face about its incenter so that it covers the
// thick silhouette around its edges. Everything after the edge test is in
// the map's texel space (the viewport is the map).
// Uses: vtkSilhouetteCommon.glsl (put after the version line by the pass).

in vec3 FacePositions0; // V1, V2, V3: the face's corners, model space
in vec3 FacePositions1;
in vec3 FacePositions2;
in vec3 AdjacentNormals0; // across V1V2, V2V3, V3V1; -n_f at a border
in vec3 AdjacentNormals1;
in vec3 AdjacentNormals2;

uniform mat4 vtkShadowModelToClip;
uniform vec4 silhouetteLightMC;  // w = 1: the light's position; w = 0: towards the light
uniform float silhouetteMapSize; // texels across the map
uniform float silhouetteHalfWidth; // w_sc: half the minimum silhouette width, texels
// Sizing w_sc from the light (silhouetteDepthRange.w > 0): near, far, 1 if
// parallel, K as the receivers' (vtkSilhouetteLookupFS.glsl); the widest
// penumbra half-width kept; w_sc is then the widest penumbra behind this
// face (a receiver at the far plane) plus a texel diagonal.
uniform vec4 silhouetteDepthRange;
uniform float silhouetteWidest;
#ifndef SILHOUETTE_CUBE_FACE
// Pass 1's depths, raw (a sampler object without comparison): what lies
// just past each silhouette edge is the receiver its penumbra falls on.
uniform sampler2D silhouetteDepths;
#endif

#ifdef SILHOUETTE_BANDS
// To the geometry shader (vtkSilhouetteBandsGS.glsl), once a face.
out vec3 silhouetteFaceCorner0; // the face's corners: texel x, y and depth in [0, 1]
out vec3 silhouetteFaceCorner1;
out vec3 silhouetteFaceCorner2;
flat out int silhouetteFaceEdges; // bit k: edge V(k)V(k+1) is a silhouette; 0: draw nothing
out float silhouetteFaceReach; // this face's w_sc
#else
flat out vec3 silhouetteCorner[3]; // the face's corners: texel x, y and depth in [0, 1]
flat out int silhouetteEdges;      // bit k: edge V(k)V(k+1) is a silhouette
flat out float silhouetteReach;    // this face's w_sc
#endif

// Eq. 1: an edge is a silhouette when the face and its neighbour face the
// light differently, both seen from the edge's midpoint (so that the two
// faces of an edge agree). Both faces would draw the same thick silhouette:
// only the one facing the light does, which halves the pass's fill; a border
// (or non-manifold) edge, stored with -n_f, has no other face to draw it.
bool silhouetteEdge(vec3 a, vec3 b, vec3 face, vec3 neighbour)
{
  vec3 v = silhouetteLightMC.w > 0.0 ? silhouetteLightMC.xyz - 0.5 * (a + b) : silhouetteLightMC.xyz;
  bool facing = dot(face, v) > 0.0;
  bool border = dot(face, neighbour) < -0.9999 * length(face);
  return facing != (dot(neighbour, v) > 0.0) && (facing || border);
}

// The face's silhouette edges (bits), its corners in texel space (x, y,
// map depth) and its w_sc; false for a face through the light's eye plane.
bool silhouetteFace(out int edges, out vec3 corners[3], out float reach)
{
  vec3 p[3] = vec3[3](FacePositions0, FacePositions1, FacePositions2);
  vec3 face = cross(p[1] - p[0], p[2] - p[0]);
  edges = (silhouetteEdge(p[0], p[1], face, AdjacentNormals0) ? 1 : 0) |
    (silhouetteEdge(p[1], p[2], face, AdjacentNormals1) ? 2 : 0) |
    (silhouetteEdge(p[2], p[0], face, AdjacentNormals2) ? 4 : 0);

  vec2 t[3];
  bool behind = false;
  float nearest = 1.0e30; // the face's distance along the light's axis
  vec4 range = silhouetteDepthRange;
  for (int k = 0; k < 3; ++k)
  {
    vec4 clip = vtkShadowModelToClip * vec4(p[k], 1.0);
    behind = behind || clip.w <= 0.0;
    vec3 ndc = clip.xyz / clip.w;
    nearest = min(nearest, range.z > 0.0 ? mix(range.x, range.y, 0.5 * ndc.z + 0.5) : clip.w);
    t[k] = (0.5 * ndc.xy + 0.5) * silhouetteMapSize;
    corners[k] = vec3(t[k], 0.5 * ndc.z + 0.5);
  }
  // Eq. 2's w_sc: the expected width's half plus a texel diagonal (the
  // expected width is twice the widest penumbra behind the face when sized
  // from the light: K (r - e) or K (1/e - 1/r) for the farthest receiver r).
  reach = silhouetteHalfWidth;
  if (range.w > 0.0)
  {
    // The farthest receiver: the far plane, or, with a 2D depth map, the
    // deepest of what lies 2 and 12 texels past each silhouette edge's ends
    // and middle (nothing there: the far plane).
    float farthest = range.y;
#ifndef SILHOUETTE_CUBE_FACE
    float deepest = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      if ((edges & (1 << k)) == 0)
      {
        continue;
      }
      vec2 a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      vec2 out2 = normalize(vec2(a.y - b.y, b.x - a.x) + vec2(1.0e-12, 0.0));
      out2 *= dot(out2, c - a) > 0.0 ? -1.0 : 1.0;
      for (int j = 0; j < 6; ++j)
      {
        vec2 at = mix(a, b, 0.5 * float(j % 3)) + out2 * (j < 3 ? 2.0 : 12.0);
        deepest = max(deepest, textureLod(silhouetteDepths, at / silhouetteMapSize, 0.0).r);
      }
    }
    farthest = deepest < 1.0 ? silhouetteLinearDepth(range, deepest) : range.y;
#endif
    float e = max(nearest, range.x);
    float r = max(farthest, e);
    float widest = range.z > 0.0 ? range.w * (r - e) : range.w * (1.0 / e - 1.0 / r);
    reach = min(max(widest, 1.0), silhouetteWidest) + 1.41421356;
  }
  return !behind;
}

#ifdef SILHOUETTE_BANDS
void main()
{
  vec3 corners[3];
  int edges;
  float reach;
  bool drawn = silhouetteFace(edges, corners, reach);
  silhouetteFaceCorner0 = corners[0];
  silhouetteFaceCorner1 = corners[1];
  silhouetteFaceCorner2 = corners[2];
  silhouetteFaceEdges = drawn ? edges : 0;
  silhouetteFaceReach = reach;
  gl_Position = vec4(0.0, 0.0, 0.0, 1.0); // the geometry shader places the bands
}
#else
void main()
{
  vec3 corners[3];
  int edges;
  float reach;
  bool drawn = silhouetteFace(edges, corners, reach);
  silhouetteCorner = corners;
  silhouetteEdges = edges;
  silhouetteReach = reach;
  vec2 t[3] = vec2[3](corners[0].xy, corners[1].xy, corners[2].xy);
  // The corner this vertex is: the TAM's vertices (or an instance's) come
  // in face order.
  int corner = gl_VertexID % 3;
  if (edges == 0 || !drawn)
  {
    // No silhouette (or a face through the light's eye plane): one point in
    // front of the near plane, rejected before rasterization.
    gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
    return;
  }

  // Degenerate after projection (inradius under half a texel diagonal):
  // move the corner opposite the longest edge away from it, against that
  // edge's outward normal, until the face is a texel diagonal high. Before
  // the incenter and the scaling.
  const float halfDiagonal = 0.70710678;
  float len[3] = float[3](distance(t[1], t[2]), distance(t[2], t[0]), distance(t[0], t[1]));
  float perimeter = len[0] + len[1] + len[2];
  float area2 = abs((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y));
  if (area2 < halfDiagonal * perimeter) // inradius = area2 / perimeter
  {
    int o = len[0] >= len[1] && len[0] >= len[2] ? 0 : (len[1] >= len[2] ? 1 : 2);
    vec2 a = t[(o + 1) % 3], b = t[(o + 2) % 3];
    vec2 along = len[o] > 1.0e-6 ? (b - a) / len[o] : vec2(1.0, 0.0);
    vec2 away = vec2(-along.y, along.x);
    float side = dot(t[o] - a, away);
    away *= side < 0.0 ? -1.0 : 1.0;
    // Height 2 * halfDiagonal * 2: inradius of about a half diagonal for
    // the thin triangle (height / 2 for a sliver).
    t[o] += away * max(4.0 * halfDiagonal - abs(side), 0.0);
    if (len[o] < 1.0e-6)
    {
      // A face collapsed to a point: give it a base as well.
      t[(o + 1) % 3] -= along * 2.0 * halfDiagonal;
      t[(o + 2) % 3] += along * 2.0 * halfDiagonal;
    }
    len = float[3](distance(t[1], t[2]), distance(t[2], t[0]), distance(t[0], t[1]));
    perimeter = len[0] + len[1] + len[2];
    area2 = abs((t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y));
  }

  // Eq. 2: scale about the incenter by f = (w_o + w_sc) / w_o, which moves
  // every edge out by w_sc.
  vec2 incenter = (len[0] * t[0] + len[1] * t[1] + len[2] * t[2]) / perimeter;
  float inradius = area2 / perimeter;
  float f = (inradius + reach) / inradius;
  vec2 grown = incenter + f * (t[corner] - incenter);
  gl_Position = vec4(grown / silhouetteMapSize * 2.0 - 1.0, 0.0, 1.0);
}
#endif
