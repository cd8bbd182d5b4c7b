// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Tests a caster triangle against the view samples listed in this texel
// (Sintorn et al., section 3.3; empty lists end at once), soft in this
// cell of 2x2 texels (the soft pass draws at half the map's resolution:
// llvmpipe runs a loop's body at least once a fragment, so a quarter of the
// fragments over the same regions does less work):
// - hard: a sample is hidden when it lies inside the planes through the
//   triangle's edges and the light and behind the triangle's plane; its bit
//   is set by an atomic OR;
// - soft (ALIASFREE_SOFT, section 4.2): the light samples the triangle hides
//   from a view sample p are those inside the planes through p and each edge
//   and behind the triangle; each plane's bitmask comes from the lookup
//   table (vtkAliasFreeLookup.glsl), the four are ANDed and ORed into p's
//   mask.
// With ALIASFREE_EDGES it only marks the texels of silhouette edges'
// influence regions (vtkAliasFreeCastersGS.glsl) that hold samples. Both
// skip texels whose samples all lie nearer the light than the triangle;
// soft, restricted to silhouettes, the texels no edge marked too (their
// samples take the centre's hard shadow).
// Closed casters hide a sample only from their outer side (hard: only their
// light-back-facing triangles are drawn); open ones from both. No triangle
// hides a sample within aliasfreeEpsilon of its plane (relative to the
// sample's distance from the light): one on the triangle itself.
// Uses: vtkAliasFreeCastersGS.glsl (its outputs), vtkAliasFreeLookup.glsl
// (soft, prepended by the pass).

layout(std430, binding = 0) readonly buffer aliasfreeCountsBuffer { uint aliasfreeCounts[]; };
layout(std430, binding = 1) readonly buffer aliasfreeOffsetsBuffer { uint aliasfreeOffsets[]; };
layout(std430, binding = 4) readonly buffer aliasfreeSamplesBuffer { vec4 aliasfreeSamples[]; };
layout(std430, binding = 5) coherent buffer aliasfreeHiddenBuffer { uint aliasfreeHidden[]; };

uniform int aliasfreeMapTexels; // texels a side
#ifdef ALIASFREE_EDGES
// Texels in the influence region of a silhouette edge, which it marks.
layout(std430, binding = 2) buffer aliasfreeMarksBuffer { uint aliasfreeMarks[]; };
#endif
#if defined(ALIASFREE_SOFT) || defined(ALIASFREE_EDGES)
// The texels' greatest view sample depths (order-preserving integers; soft,
// restricted to silhouettes: of the marked texels only, the others read as
// empty), and the depth beyond which this triangle may hide a sample.
layout(std430, binding = 7) readonly buffer aliasfreeDepthsBuffer { int aliasfreeDepths[]; };
flat in int aliasfreeReachable;
#endif
uniform int aliasfreeClosed;
uniform float aliasfreeOrientation;
uniform float aliasfreeEpsilon;
uniform vec4 aliasfreeLight; // world position (w = 1), or direction towards it (w = 0)

#ifdef ALIASFREE_SOFT
flat in vec3 aliasfreeA;
flat in vec3 aliasfreeB;
flat in vec3 aliasfreeC;
#else
flat in vec4 aliasfreePlane;
flat in vec4 aliasfreeEdge0;
flat in vec4 aliasfreeEdge1;
flat in vec4 aliasfreeEdge2;
#endif

// aliasfreeEpsilon is relative to a sample's distance from a spot light;
// for directional lights it is in world units.
float aliasfreeScale(vec3 p)
{
  return aliasfreeLight.w > 0.5 ? distance(p, aliasfreeLight.xyz) : 1.0;
}

// A sample this near a triangle's plane lies on it (its own face, seen
// from either side: a camera inside a closed caster sees its back faces) and
// is not hidden by it.
float aliasfreeTolerance(vec3 p)
{
  return aliasfreeEpsilon * aliasfreeScale(p);
}

void main()
{
#ifdef ALIASFREE_SOFT
  // The cell's four texels' lists, those with samples deep enough.
  ivec2 cell = ivec2(gl_FragCoord.xy);
  int n = aliasfreeMapTexels;
  if (aliasfreeDepths[n * n + cell.y * ((n + 1) / 2) + cell.x] < aliasfreeReachable)
  {
    return; // no sample here, or every one nearer the light than the triangle
  }
  uint firsts[4], ends[4];
  uint total = 0u;
  for (int k = 0; k < 4; ++k)
  {
    ivec2 t = 2 * cell + ivec2(k & 1, k >> 1);
    uint i = uint(t.y * n + t.x);
    bool tested = t.x < n && t.y < n && aliasfreeDepths[i] >= aliasfreeReachable;
    firsts[k] = tested ? aliasfreeOffsets[i] : 0u;
    total += tested ? aliasfreeCounts[i] : 0u;
    ends[k] = total;
  }
  vec3 normal = normalize(cross(aliasfreeB - aliasfreeA, aliasfreeC - aliasfreeA));
  vec3 corners[3] = vec3[3](aliasfreeA, aliasfreeB, aliasfreeC);
  for (uint j = 0u; j < total; ++j)
  {
    int k = j < ends[0] ? 0 : (j < ends[1] ? 1 : (j < ends[2] ? 2 : 3));
    uint s = firsts[k] + j - (k == 0 ? 0u : ends[k - 1]);
#else
  ivec2 texel = ivec2(gl_FragCoord.xy);
  uint index = uint(texel.y * aliasfreeMapTexels + texel.x);
#ifdef ALIASFREE_EDGES
  if (aliasfreeDepths[index] < aliasfreeReachable)
  {
    return; // no sample here, or every one nearer the light than the triangle
  }
#endif
  uint count = aliasfreeCounts[index];
  if (count == 0u)
  {
    return;
  }
#ifdef ALIASFREE_EDGES
  aliasfreeMarks[index] = 1u;
  return;
#endif
  uint first = aliasfreeOffsets[index];
#endif
#ifdef ALIASFREE_SOFT
    vec3 p = aliasfreeSamples[s].xyz;
    // p's side of the triangle: light samples on the other side may be hidden.
    float side = dot(normal, p - aliasfreeA);
    // A triangle in p's own plane (p's face, coplanar neighbours) hides
    // nothing from it: its cone is flat. Closed casters hide from outside.
    if (abs(side) <= aliasfreeTolerance(p) ||
      (aliasfreeClosed == 1 && aliasfreeOrientation * side <= 0.0))
    {
      continue;
    }
    // The four planes' masks; none hidden as soon as one plane leaves the
    // whole light outside (most samples of a region: the lit side), all as
    // long as every plane holds the whole light (the umbra).
    // The edge planes' normals all point into the cone by one sign:
    // dot(cross(q - p, r - p), o - p) is the same triple product for each
    // edge, -side |b - a x c - a|. Taken from side, which the tolerance keeps
    // clear of 0, rather than per edge: for a p almost in the triangle's
    // plane the three products round to random signs, and planes that
    // should bound a sliver of a cone would hold the whole light.
    float inward = side > 0.0 ? -1.0 : 1.0;
    aliasfreePlaneMask planes[4];
    planes[3] = aliasfreeSide(inward * normal, aliasfreeA, aliasfreeLight);
    bool none = aliasfreeEmpty(planes[3]);
    bool all = aliasfreeFull(planes[3]);
    for (int i = 0; i < 3 && !none; ++i)
    {
      vec3 q = corners[i], r = corners[(i + 1) % 3];
      vec3 m = inward * cross(q - p, r - p);
      none = dot(m, m) <= 0.0; // p on an edge's line
      planes[i] = aliasfreeSide(m, p, aliasfreeLight);
      none = none || aliasfreeEmpty(planes[i]);
      all = all && aliasfreeFull(planes[i]);
    }
    if (none)
    {
      continue;
    }
    uint base = s * uint(aliasfreeWords);
    if (all)
    {
      for (int w = 0; w < aliasfreeWords; ++w)
      {
        aliasfreeHidden[base + uint(w)] = 0xffffffffu; // whatever others OR, all stay set
      }
      continue;
    }
    for (int w = 0; w < aliasfreeWords; ++w)
    {
      uint hidden = aliasfreeWord(planes[0], w) & aliasfreeWord(planes[1], w) &
        aliasfreeWord(planes[2], w) & aliasfreeWord(planes[3], w);
      if (hidden != 0u)
      {
        atomicOr(aliasfreeHidden[base + uint(w)], hidden);
      }
    }
  }
#else
  for (uint s = first; s < first + count; ++s)
  {
    vec4 p = vec4(aliasfreeSamples[s].xyz, 1.0);
    if (dot(aliasfreeEdge0, p) >= 0.0 && dot(aliasfreeEdge1, p) >= 0.0 &&
      dot(aliasfreeEdge2, p) >= 0.0 && dot(aliasfreePlane, p) < -aliasfreeTolerance(p.xyz))
    {
      atomicOr(aliasfreeHidden[s >> 5], 1u << (s & 31u));
    }
  }
#endif
}
