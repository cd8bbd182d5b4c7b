//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Pass 2's bands drawn edge by edge (vtkSilhouetteShadowPass::EdgeRectangles),
// instead of each face grown about its incenter (eq. 2): a rectangle around
// each silhouette edge, w_sc from the edge on every side. It holds every
// point within w_sc of the edge, which is all the fragment shader keeps of
// a grown face, and no more than the band: a thin or large face grown by
// eq. 2 covers far more. A face arrives as one point (the TAM's per-face
// layout); nothing degenerates, since a rectangle of an edge seen end-on
// is still 2 w_sc wide.
// Uses: vtkSilhouetteEdgesVS.glsl with SILHOUETTE_BANDS (its outputs).

layout(points) in;
layout(triangle_strip, max_vertices = 12) out;

in vec3 silhouetteFaceCorner0[];
in vec3 silhouetteFaceCorner1[];
in vec3 silhouetteFaceCorner2[];
flat in int silhouetteFaceEdges[];
in float silhouetteFaceReach[];

uniform float silhouetteMapSize; // texels across the map

// For vtkSilhouetteEdgesFS.glsl with SILHOUETTE_BANDS: the one edge the
// rectangle is for, and the face's third corner.
flat out vec3 silhouetteEdgeA;
flat out vec3 silhouetteEdgeB;
flat out vec3 silhouetteOpposite;
flat out float silhouetteReach;

void main()
{
  int edges = silhouetteFaceEdges[0];
  vec3 corners[3] =
    vec3[3](silhouetteFaceCorner0[0], silhouetteFaceCorner1[0], silhouetteFaceCorner2[0]);
  float reach = silhouetteFaceReach[0];
  for (int k = 0; k < 3; ++k)
  {
    if ((edges & (1 << k)) == 0)
    {
      continue;
    }
    vec2 a = corners[k].xy, b = corners[(k + 1) % 3].xy;
    float len = distance(a, b);
    vec2 along = (len > 1.0e-6 ? (b - a) / len : vec2(1.0, 0.0)) * reach;
    vec2 across = vec2(-along.y, along.x);
    for (int j = 0; j < 4; ++j)
    {
      vec2 q = (j < 2 ? a - along : b + along) + (j % 2 == 0 ? -across : across);
      silhouetteEdgeA = corners[k];
      silhouetteEdgeB = corners[(k + 1) % 3];
      silhouetteOpposite = corners[(k + 2) % 3];
      silhouetteReach = reach;
      gl_Position = vec4(q / silhouetteMapSize * 2.0 - 1.0, 0.0, 1.0);
      EmitVertex();
    }
    EndPrimitive();
  }
}
