// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Receivers of silhouette-distance shadow maps (Valient & Bujnak, section
// 2.2): a light's depth map, its silhouette map (signed distance to the
// nearest silhouette in texels, positive on the occluder's side, and that
// silhouette point's depth) and its lookup texture, which holds four
// segments side by side (eq. 4), each of LookupTexels texels, and
// one row per penumbra width (section 2.2.1; one row for hard shadows).
// The receivers' shader declares, before this file, the soft variant's
// samples a point takes, how far those around it lie, in penumbra
// half-widths, and the turn from one to the next: the paper's
// (silhouette...) and those where penumbrae overlap (silhouetteOverlap...);
// and how much the paper's profiles narrow
// (vtkSilhouetteShadowPass::GetReceiverCode):
//   const int silhouetteSamples; const float silhouetteSpread;
//   const vec2 silhouetteTurn; // cos, sin
//   const int silhouetteOverlapSamples; const float silhouetteOverlapSpread;
//   const vec2 silhouetteOverlapTurn;
//   const float silhouetteNarrowing; // the paper's set's
// Uses: vtkSoftShadowReceiverFS.glsl (vtkShadowReceiverInMap) and
// vtkShadowCubeLookupFS.glsl (vtkShadowCubeFace, vtkShadowCubeDirection), which
// the receivers' shader declares before it;
// vtkSilhouetteCommon.glsl.

uniform vec4 silhouetteDepthRange[VTK_SHADOW_LIGHTS]; // near, far, 1 if parallel, K
uniform vec2 silhouetteBand[VTK_SHADOW_LIGHTS]; // W: distances span [-W, W]; Wmax: widest penumbra
// Per light, what eq. 4's lookup needs as multiply-adds: x, the penumbra's
// half-width in texels per unit of map depth between silhouette and
// receiver (0 for hard shadows); y, the distance's scale 0.5 / W; z, a
// row per texel of width; w, the first row's centre.
uniform vec4 silhouetteLookupScale[VTK_SHADOW_LIGHTS];
uniform float silhouetteMapSize;
uniform vec2 silhouetteLookupSegment; // a segment's scale and first centre, T texels each: (T - 1) / 4T, 1 / 8T
// Where the samples around the point lie, in units of their reach: (0, 1),
// then each turned by their set's turn (a full turn over their count) from
// the one before: section 2.2.1's three, 120 degrees apart, or more, which
// sum overlapping penumbrae (docs/quality.md). Turned, not read from an
// array, whose size would tell the compiler the loop's most iterations, and
// have it unrolled into samples that run for every pixel
// (silhouetteRingFor()).
const vec2 silhouetteFirstAround = vec2(0.0, 1.0);
vec2 silhouetteNextAround(vec2 d, vec2 turn)
{
  return vec2(turn.x * d.x - turn.y * d.y, turn.y * d.x + turn.x * d.y);
}

// Eq. 4 and, for soft shadows, the row of the penumbra's width: the
// visibility of a sample given its distance and silhouette depth (edge), its
// own depth z and the shadow map's verdict (occluded: z_O < z). The
// penumbra's half-width is K (r - e) behind a directional light's angular
// size and K (r - e) / (e r) behind a spot light's radius, with r and e the
// distances along the light's axis; both are proportional to the map depths'
// difference (for a perspective map 1 / e - 1 / r is), so one scale per
// light serves (vtkSilhouetteShadowPass::GetReceiverCode). The profile
// is the row of the width times `narrowing`, for samples spread around the
// point.
float silhouetteResolve(sampler2D lookup, vec2 edge, float z, float occluded, int i, bool soft,
  float narrowing, out float width)
{
  vec4 scale = silhouetteLookupScale[i];
  float inFront = edge.y < z ? 1.0 : 0.0; // z_E < z
  // The distance term inset so that filtering never mixes two segments.
  float d = clamp(edge.x * scale.y + 0.5, 0.0, 1.0);
  float coord = d * silhouetteLookupSegment.x +
    (silhouetteLookupSegment.y + 0.25 * occluded + 0.5 * inFront); // eq. 4
  // The penumbra's half-width, clamped to the widest the lookup holds.
  width = soft && inFront > 0.0 ? min(scale.x * (z - edge.y), silhouetteBand[i].y) : 0.0;
  return texture(lookup, vec2(coord, width * narrowing * scale.z + scale.w)).r;
}

// The silhouette's depth at a sample from the four texels around it: the
// nearest, texels without a silhouette holding 1 (the map's clear value).
// Filtering depths with empty texels would move them, badly so in a point
// light's depth range.
float silhouetteDepth(vec4 z4)
{
  return min(min(z4.x, z4.y), min(z4.z, z4.w));
}

// A sample's distance from the four silhouette-map texels around it (d4,
// gather order (0,1), (1,1), (1,0), (0,0); f: the position between them),
// given how many of the four depth-map texels see it (lit). The shadow map's verdict is all four occluded: a shadow
// shrunk by up to a texel, which is the paper's offset between the two
// boundaries (section 2.2), made on the shadow map's side so that the
// silhouette's edge stays where the geometry puts it. `across` returns
// where (texels from the sample) the depth map must show the light for the
// sample to be in a penumbra's inner half; zero when no test is needed.
float silhouetteEdge(vec4 d4, vec2 f, float lit, int i, out vec2 across)
{
  float edge = mix(mix(d4.w, d4.z, f.x), mix(d4.x, d4.y, f.x), f.y);
  across = vec2(0.0);
  if (lit == 4.0)
  {
    // Seen by all four texels, the point is the surface nearest the light:
    // it can lie on a silhouette's occluder side only by being that
    // occluder (a surface beside its own border or silhouette), which does
    // not shadow itself. (Within a shadow's true edge, one of the four is
    // occluded.)
    edge = edge > 0.0 ? -silhouetteBand[i].x : edge;
  }
  else if (lit == 0.0 && edge > 0.0 && all(greaterThan(d4, vec4(-silhouetteBand[i].x))))
  {
    // In the shadow map's shadow, on the occluder's side: the inner half of
    // a penumbra only if the light shows past the silhouette. Across an
    // inner fold (a bump in front of more of the occluder) it does not.
    vec2 gradient = vec2(mix(d4.z - d4.w, d4.y - d4.x, f.y), mix(d4.x - d4.w, d4.y - d4.z, f.x));
    across = -gradient / max(length(gradient), 1.0e-6) * (edge + 1.5);
  }
  return edge;
}

// Distances at or below this mean no silhouette near: the map's clear
// value lies far below the band, and so does a filtered read that mixes it
// in, where every kept distance lies within the band.
float silhouetteNoneBelow(int i)
{
  return -2.0 * silhouetteBand[i].x;
}

// No silhouette at any of the four texels: whatever casts there has no
// faces the technique drew (lines, points, imposters) and casts the depth
// map's shadow alone, the four texels' mean. (Every face's shadow edge lies
// within its silhouette's band, at least a texel diagonal wide.)
bool silhouetteNone(vec4 d4, int i)
{
  return all(lessThanEqual(d4, vec4(silhouetteNoneBelow(i))));
}

// The signed distance at a sample from the four texels around it (d4, in
// gather order; f: the position between them) and its gradient in texels a
// texel; `known` false where one of them has no silhouette near.
vec3 silhouetteField(vec4 d4, vec2 f, int i, out bool known)
{
  known = all(greaterThan(d4, vec4(silhouetteNoneBelow(i))));
  return vec3(mix(mix(d4.w, d4.z, f.x), mix(d4.x, d4.y, f.x), f.y),
    mix(d4.z - d4.w, d4.y - d4.x, f.y), mix(d4.x - d4.w, d4.y - d4.z, f.x));
}

// Section 2.2.1's samples follow the profile of one straight silhouette,
// whose distance grows a texel a texel along its gradient. How far the
// distance `reach` texels to one side of the point (`found`, read up to
// half a texel diagonal off; `seen` false where the map keeps none) misses
// the `expected` of one edge: where the map keeps no distance, one edge
// lies beyond the band.
float silhouetteMiss(float found, bool seen, float expected, float reach, int i)
{
  float band = silhouetteBand[i].x;
  return seen
    ? max(abs(clamp(found, -band, band) - clamp(expected, -band, band)) - 0.75, 0.0)
    : (abs(expected) > band - 2.0 ? 0.0 : reach);
}

// How far the crowding probes lie to either side of a point, in widths of
// its penumbra.
const float silhouetteProbeReach = 0.5;

// How crowded the penumbra `width` texels wide about a point is, from its
// distance field (silhouetteField()) and what the map holds half a width to
// either side along the field's gradient (`found`, behind and ahead; the
// caller reads them at silhouetteCrowdingReach()). From 0, the penumbra of
// a lone edge, whose profile the paper's samples follow, to 1, another
// silhouette within reach, whose penumbra overlaps, as the distance to
// either side misses one edge's (silhouetteMiss()). (Points on the ridge
// between two silhouettes, where the gradient flattens, miss as well: a
// rule of their own found no more, docs/quality.md.)
float silhouetteCrowdingFrom(vec3 field, vec2 found, float width, int i)
{
  float reach = silhouetteProbeReach * width;
  float none = silhouetteNoneBelow(i);
  float miss = max(silhouetteMiss(found.x, found.x > none, field.x - reach, reach, i),
    silhouetteMiss(found.y, found.y > none, field.x + reach, reach, i));
  return smoothstep(0.1, 0.4, miss / width);
}

// Where silhouetteCrowdingFrom() needs the map read: `reach` texels along
// the field's unit gradient to either side. False, with the crowding
// itself, where the field tells it alone: no silhouette near (0) or a
// field with no direction, the ridge between two (1).
bool silhouetteCrowdingReach(
  vec3 field, bool known, float width, out vec2 reach, out float crowding)
{
  float slope = length(field.yz);
  bool directed = known && slope >= 1.0e-3;
  crowding = known ? 1.0 : 0.0;
  reach = directed ? field.yz / slope * (silhouetteProbeReach * width) : vec2(0.0);
  return directed;
}

// The samples around a point in a penumbra `width` texels wide: `count`
// of them, `spread` half-widths off it, turned by `turn` from one to the
// next (from silhouetteFirstAround), their profiles narrowed by `narrowing`.
// Where one silhouette's penumbra falls (crowding 0), section 2.2.1's:
// silhouetteSamples - 1 at silhouetteSpread. Where others' overlap,
// silhouetteOverlapSamples - 1, spread out to silhouetteOverlapSpread as
// the crowding grows: each follows its own nearest silhouette, so together
// they add the penumbrae up (docs/quality.md). The point keeps its
// profile (silhouetteNarrowing), and the ring's narrows so that the mean
// keeps the light disc's second moment, which for the paper's set is
// silhouetteNarrowing again (SampleNarrowing() in
// vtkSilhouetteShadowPass.cxx). None outside a penumbra, where their reach
// is 0 and they would repeat the point. A loop whose count varies runs
// once, masked, for a group of pixels none of which enters it, where
// unrolled samples ran for every pixel.
struct silhouetteRing
{
  int count;
  float spread;
  float narrowing;
  vec2 turn;
};

silhouetteRing silhouetteRingFor(float width, float crowding)
{
  bool overlap = crowding > 0.0;
  silhouetteRing ring;
  ring.count = width <= 0.0 ? 0 : (overlap ? silhouetteOverlapSamples : silhouetteSamples) - 1;
  ring.spread =
    overlap ? mix(silhouetteSpread, silhouetteOverlapSpread, crowding) : silhouetteSpread;
  ring.turn = overlap ? silhouetteOverlapTurn : silhouetteTurn;
  // Per axis, a disc profile of radius r adds r^2 / 4, a ring of radius s
  // r adds s^2 r^2 / 2 for its `count` samples out of count + 1.
  ring.narrowing = sqrt(max(1.0 +
      (1.0 - silhouetteNarrowing * silhouetteNarrowing) / float(max(ring.count, 1)) -
      2.0 * ring.spread * ring.spread,
    0.0));
  return ring;
}

#if VTK_SHADOW_MAPS > 0
// One sample at map point p of a spot or directional light; `depth`, its
// silhouette's depth, found if `own`, else given.
float silhouetteSample(sampler2DShadow map, sampler2D silhouettes, sampler2D lookup, vec3 p,
  int i, bool soft, bool own, float narrowing, inout float depth, out float width)
{
  float lit = dot(textureGather(map, p.xy, p.z), vec4(1.0));
  vec4 d4 = textureGather(silhouettes, p.xy, 0);
  if (silhouetteNone(d4, i))
  {
    width = 0.0;
    return 0.25 * lit;
  }
  vec2 f = fract(p.xy * silhouetteMapSize - 0.5);
  vec2 across;
  if (own)
  {
    depth = silhouetteDepth(textureGather(silhouettes, p.xy, 1));
  }
  vec2 edge = vec2(silhouetteEdge(d4, f, lit, i, across), depth);
  if (across != vec2(0.0) &&
    dot(textureGather(map, p.xy + across / silhouetteMapSize, p.z), vec4(1.0)) == 0.0)
  {
    edge.x = -silhouetteBand[i].x;
  }
  return silhouetteResolve(
    lookup, edge, p.z, lit == 0.0 ? 1.0 : 0.0, i, soft, narrowing, width);
}

// How crowded the penumbra `width` texels wide about map point p is
// (silhouetteCrowdingFrom()), from the distance half a width to either side
// along its gradient (p's own gather is the sample's, which the compiler
// shares). The two probes read one texel each: four cost more and found
// the same (docs/quality.md).
float silhouetteCrowding(sampler2D silhouettes, vec2 p, float width, int i)
{
  bool known;
  vec3 field = silhouetteField(
    textureGather(silhouettes, p, 0), fract(p * silhouetteMapSize - 0.5), i, known);
  vec2 reach;
  float crowding;
  if (!silhouetteCrowdingReach(field, known, width, reach, crowding))
  {
    return crowding;
  }
  ivec2 last = ivec2(int(silhouetteMapSize) - 1);
  vec2 texel = p * silhouetteMapSize;
  vec2 found = vec2(texelFetch(silhouettes, clamp(ivec2(texel - reach), ivec2(0), last), 0).r,
    texelFetch(silhouettes, clamp(ivec2(texel + reach), ivec2(0), last), 0).r);
  return silhouetteCrowdingFrom(field, found, width, i);
}

// How a spot or directional light's map depth changes across the receiver
// at map point p, per unit of map coordinates, from p's screen derivatives
// (within the pixel quad they are those of one face's plane, and a plane
// stays a plane in the map's projection). The samples around the point are
// compared at that plane's depth where they lie: at the point's own, a
// receiver at a slant to the light shadows itself wherever it lies nearer
// the light, which darkens wide penumbrae. Derivatives cost a few shuffles
// where the plane from the normal and the map's matrix cost 16 uniform
// loads a fragment; on an imposter the plane is its sprite's. Called in
// uniform control flow.
vec2 silhouetteDepthSlope(vec3 p)
{
  vec3 dx = dFdx(p);
  vec3 dy = dFdy(p);
  float det = dx.x * dy.y - dx.y * dy.x;
  // Edge-on to the light, or no area (points, lines): no slope.
  return abs(det) > 1.0e-20 ? vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det
                            : vec2(0.0);
}

// Light i's visibility at a receiver (view-space point and unit normal).
// Soft, in a penumbra: the mean of the point and the samples around it
// (silhouetteRingFor()): section 2.2.1's where one silhouette's penumbra
// falls, more and wider where others' overlap it.
float silhouetteVisibility(sampler2DShadow map, sampler2D silhouettes, sampler2D lookup,
  vec3 positionVC, vec3 normalVC, int i, bool soft)
{
  vec3 p;
  bool inMap = vtkShadowReceiverInMap(i, positionVC, normalVC, p);
  vec2 slope = silhouetteDepthSlope(p); // before any return: derivatives
  if (!inMap)
  {
    return 1.0;
  }
  float depth = 1.0;
  float width;
  float point = silhouetteSample(
    map, silhouettes, lookup, p, i, soft, true, silhouetteNarrowing, depth, width);
  if (!soft)
  {
    return point;
  }
  float crowding = silhouetteOverlapSamples > 1 && width > 0.0
    ? silhouetteCrowding(silhouettes, p.xy, width, i)
    : 0.0;
  silhouetteRing ring = silhouetteRingFor(width, crowding);
  float visibility = point;
  vec2 around = silhouetteFirstAround;
  for (int k = 0; k < ring.count; ++k)
  {
    vec2 offset = ring.spread * width / silhouetteMapSize * around;
    float unused;
    visibility += silhouetteSample(map, silhouettes, lookup,
      vec3(p.xy + offset, p.z + dot(slope, offset)), i, soft, false, ring.narrowing, depth,
      unused);
    around = silhouetteNextAround(around, ring.turn);
  }
  return visibility / float(1 + ring.count); // the mean of the samples taken
}
#endif

#if VTK_SHADOW_CUBES > 0
// One sample of a point light along direction v (light to receiver), the
// receiver's squared distance `reference` (bias included): the cube faces'
// depth maps are the framework's squared distances, the silhouette cube
// holds each face's distances and depths.
float silhouetteCubeSample(samplerCube distances, samplerCube silhouettes, sampler2D lookup,
  vec3 v, float reference, int i, bool soft, bool own, float narrowing, inout float depth,
  out float width)
{
  vec3 s, t;
  float axis;
  vtkShadowCubeFace(v, s, t, axis);
  vec2 st = (vec2(dot(v, s), dot(v, t)) / axis * 0.5 + 0.5) * silhouetteMapSize;
  float lit = dot(vec4(greaterThanEqual(textureGather(distances, v), vec4(reference))), vec4(1.0));
  vec4 d4 = textureGather(silhouettes, v, 0);
  if (silhouetteNone(d4, i))
  {
    width = 0.0;
    return 0.25 * lit;
  }
  vec2 across;
  if (own)
  {
    depth = silhouetteDepth(textureGather(silhouettes, v, 1));
  }
  vec2 edge = vec2(silhouetteEdge(d4, fract(st - 0.5), lit, i, across), depth);
  // Texels of this face as a direction: 2 / size of the axis distance each.
  vec3 step = v + (across.x * s + across.y * t) * (2.0 * axis / silhouetteMapSize);
  if (across != vec2(0.0) &&
    all(lessThan(textureGather(distances, step), vec4(reference))))
  {
    edge.x = -silhouetteBand[i].x;
  }
  float z = silhouettePerspectiveDepth(silhouetteDepthRange[i], axis);
  return silhouetteResolve(lookup, edge, z, lit == 0.0 ? 1.0 : 0.0, i, soft, narrowing, width);
}

// How crowded the penumbra `width` texels wide about direction v is, on
// v's cube face (silhouetteCrowding()).
float silhouetteCubeCrowding(samplerCube silhouettes, vec3 v, float width, int i)
{
  vec3 s, t;
  float axis;
  vtkShadowCubeFace(v, s, t, axis);
  vec2 st = (vec2(dot(v, s), dot(v, t)) / axis * 0.5 + 0.5) * silhouetteMapSize;
  bool known;
  vec3 field = silhouetteField(textureGather(silhouettes, v, 0), fract(st - 0.5), i, known);
  vec2 reach;
  float crowding;
  if (!silhouetteCrowdingReach(field, known, width, reach, crowding))
  {
    return crowding;
  }
  // Texels of this face as a direction: 2 / size of the axis distance each.
  reach *= 2.0 * axis / silhouetteMapSize;
  vec3 step = reach.x * s + reach.y * t;
  // Filtered: where a cleared texel mixes in, the distance reads far below
  // the band, as none.
  vec2 found = vec2(texture(silhouettes, v - step).r, texture(silhouettes, v + step).r);
  return silhouetteCrowdingFrom(field, found, width, i);
}

// Light i's visibility (a point light, its cube map `distances` centred on
// `center`) at a receiver: as silhouetteVisibility(), on the cube's faces,
// from the point's own sample.
float silhouetteCubeVisibility(samplerCube distances, samplerCube silhouettes, sampler2D lookup,
  vec3 center, vec4 positionWC, vec3 normalWC, int i, bool soft)
{
  float size;
  vec3 v = vtkShadowCubeDirection(
    center, positionWC, normalWC, vtkShadowCubeTexel, vtkShadowNormalBias, size);
  float reference = dot(v, v) * vtkShadowDistanceBias;
  float depth = 1.0;
  float width;
  float point = silhouetteCubeSample(distances, silhouettes, lookup, v, reference, i, soft, true,
    silhouetteNarrowing, depth, width);
  if (!soft)
  {
    return point;
  }
  float crowding = silhouetteOverlapSamples > 1 && width > 0.0
    ? silhouetteCubeCrowding(silhouettes, v, width, i)
    : 0.0;
  // The samples around the point, on the point's cube face (a texel there is
  // 2 / size of the axis distance), each where its direction meets the
  // receiver's plane: compared at the point's own distance, a receiver
  // seen at a slant would shadow itself there (arcs beyond penumbrae).
  vec3 s, t;
  float axis;
  vtkShadowCubeFace(v, s, t, axis);
  float texel = width * 2.0 * axis / silhouetteMapSize;
  float facing = dot(normalWC, v);
  silhouetteRing ring = silhouetteRingFor(width, crowding);
  float visibility = point;
  vec2 d = silhouetteFirstAround;
  for (int k = 0; k < ring.count; ++k)
  {
    vec3 around = v + ring.spread * texel * (d.x * s + d.y * t);
    float along = dot(normalWC, around);
    around *= along * facing > 1.0e-12 * dot(around, around) ? facing / along : 1.0;
    float unused;
    visibility += silhouetteCubeSample(distances, silhouettes, lookup, around,
      dot(around, around) * vtkShadowDistanceBias, i, soft, false, ring.narrowing, depth, unused);
    d = silhouetteNextAround(d, ring.turn);
  }
  return visibility / float(1 + ring.count); // the mean of the samples taken
}
#endif

// The debug view: the signed distance map where the receiver looks it up,
// 0.5 on the silhouette, darker on the occluder's side.
float silhouetteCubeDebug(samplerCube silhouettes, vec3 center, vec4 positionWC, int i)
{
  return clamp(0.5 - 0.5 * texture(silhouettes, positionWC.xyz - center).r / silhouetteBand[i].x,
    0.0, 1.0);
}

float silhouetteDebug(sampler2D silhouettes, vec3 positionVC, vec3 normalVC, int i)
{
  vec3 p;
  if (!vtkShadowReceiverInMap(i, positionVC, normalVC, p))
  {
    return 1.0;
  }
  return clamp(0.5 - 0.5 * texture(silhouettes, p.xy).r / silhouetteBand[i].x, 0.0, 1.0);
}
