// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// The view samples' lists in the light's map (Sintorn et al., section 3.1),
// one stage per define:
// - ALIASFREE_BOUNDS: the bounds of the samples in the light's clip space
//   and their greatest depth (to fit the map and the far plane, 4.3);
// - ALIASFREE_COUNT: each sample's texel, and its index in the texel's list
//   by atomic increment of the texel's count; the texel's greatest sample
//   depth;
// - ALIASFREE_DEPTH_LEVEL: one level of the pyramid of greatest depths
//   (each cell the greatest of the four below it), for culling influence
//   regions (vtkAliasFreeCastersGS.glsl);
// - ALIASFREE_DEPTH_MARKED: soft, restricted to silhouettes: the texels
//   that no silhouette edge's region marked emptied, as the soft pass tests
//   none of their samples (the levels are then built again);
// - ALIASFREE_SCAN_BLOCKS, ALIASFREE_SCAN_TOP, ALIASFREE_SCAN_ADD: the
//   exclusive prefix sum of the counts, the lists' offsets in one array
//   (blocks of 1024 texels, then the blocks' sums, then added back);
// - ALIASFREE_SCATTER: each sample's position stored at its list's offset
//   plus its index;
// - ALIASFREE_RESOLVE: each pixel's visibility from its sample's hidden bit
//   (hard) or the popcount of its mask of light samples (soft).
// A view sample is a pixel's surface (the camera pass's position and face
// normal) that faces the light (soft: some point of it): samples facing away
// are in their own shadow (visibility 0), pixels outside the light's map
// are lit.
// Uses: vtkAliasFreeLookup.glsl (the resolve; prepended by the pass).

#if defined(ALIASFREE_SCAN_BLOCKS) || defined(ALIASFREE_SCAN_TOP)
layout(local_size_x = 256) in;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif

#ifndef ALIASFREE_RESOLVE
layout(std430, binding = 0) buffer aliasfreeCountsBuffer { uint aliasfreeCounts[]; };
#endif
layout(std430, binding = 1) buffer aliasfreeOffsetsBuffer { uint aliasfreeOffsets[]; };
#if defined(ALIASFREE_RESOLVE) || defined(ALIASFREE_DEPTH_MARKED)
// The texels in some silhouette edge's influence region (vtkAliasFreeCastersFS.glsl).
layout(std430, binding = 2) readonly buffer aliasfreeMarksBuffer { uint aliasfreeMarks[]; };
#else
layout(std430, binding = 2) buffer aliasfreeBlocksBuffer { uint aliasfreeBlocks[]; };
#endif
// Per pixel: x = its texel (or aliasfreeNone) and y = its index in the
// texel's list, then in the global array; without a sample, y says why.
layout(std430, binding = 3) buffer aliasfreePixelsBuffer { uvec2 aliasfreePixels[]; };
layout(std430, binding = 4) buffer aliasfreeSamplesBuffer { vec4 aliasfreeSamples[]; };
layout(std430, binding = 5) buffer aliasfreeHiddenBuffer { uint aliasfreeHidden[]; };
#if defined(ALIASFREE_COUNT) || defined(ALIASFREE_DEPTH_LEVEL) || defined(ALIASFREE_DEPTH_MARKED)
// The greatest view sample depth (order-preserving integers) of each texel,
// then of each 2x2, 4x4, ... texels, level after level.
layout(std430, binding = 6) buffer aliasfreeDepthsBuffer { int aliasfreeDepths[]; };
#endif
// Bounds as order-preserving integers: x min, max, y min, max (clip / w),
// depth max; then the longest list and the number of samples; then the
// nearest sample's distance to a positional light's centre.
layout(std430, binding = 7) buffer aliasfreeStatsBuffer { int aliasfreeStats[]; };

const uint aliasfreeNone = 0xffffffffu;
const uint aliasfreeBackground = 0u; // no surface: receivers keep their own
const uint aliasfreeFacingAway = 1u; // in its own shadow
const uint aliasfreeOutside = 2u;    // outside the light's map: lit

uniform ivec2 aliasfreeScreen;  // pixels
uniform int aliasfreeMapSize;   // texels a side
uniform int aliasfreeTexels;    // aliasfreeMapSize^2; or, scanning blocks' sums, their number
uniform sampler2D aliasfreePositions; // world position, w = 1 on a surface
uniform sampler2D aliasfreeNormals;   // face normal towards the camera, w = 1 where defined
uniform mat4 aliasfreeWorldToClip;    // the light's map (fitted, after ALIASFREE_BOUNDS)
uniform vec4 aliasfreeLight;          // position (w = 1), or direction towards it (w = 0)
uniform vec3 aliasfreeEye;            // the map's eye and axis, for depths
uniform vec3 aliasfreeAxis;
// How far a sample's face may turn from the light's centre and still see
// part of the light: 0 (hard); a spot light's bounding radius (world); for
// directional lights the sine of the angular radius.
uniform float aliasfreeFacingSlack;

int aliasfreeOrdered(float f)
{
  int i = floatBitsToInt(f);
  return i >= 0 ? i : i ^ 0x7fffffff;
}

uint aliasfreePixelIndex()
{
  return gl_GlobalInvocationID.y * uint(aliasfreeScreen.x) + gl_GlobalInvocationID.x;
}

bool aliasfreeInScreen()
{
  return all(lessThan(gl_GlobalInvocationID.xy, uvec2(aliasfreeScreen)));
}

// This pixel's view sample: false, with the reason in `why`, if there is none.
bool aliasfreeViewSample(out vec3 position, out vec2 ndc, out uint why)
{
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  vec4 p = texelFetch(aliasfreePositions, pixel, 0);
  why = aliasfreeBackground;
  position = p.xyz;
  ndc = vec2(0.0);
  if (p.w < 0.5)
  {
    return false;
  }
  vec4 n = texelFetch(aliasfreeNormals, pixel, 0);
  vec3 towards = aliasfreeLight.w > 0.5 ? aliasfreeLight.xyz - p.xyz : aliasfreeLight.xyz;
  why = aliasfreeFacingAway;
  float slack = aliasfreeLight.w > 0.5 ? aliasfreeFacingSlack : aliasfreeFacingSlack * length(towards);
  if (n.w > 0.5 && dot(n.xyz, towards) <= -slack)
  {
    return false; // points and lines (no face) face every way
  }
  vec4 clip = aliasfreeWorldToClip * vec4(p.xyz, 1.0);
  why = aliasfreeOutside;
  if (clip.w <= 0.0)
  {
    return false;
  }
  ndc = clip.xy / clip.w;
  return all(lessThanEqual(abs(ndc), vec2(1.0)));
}

#if defined(ALIASFREE_BOUNDS) || defined(ALIASFREE_COUNT)
// The work group's statistics, reduced in shared memory first: one global
// atomic per work group instead of one per sample, which all hit the same
// few words.
shared int aliasfreeGroupStats[8];

void aliasfreeBeginStats()
{
  // Identities: the largest integer for minima, the smallest for maxima, 0 for sums.
  const int identity[8] = int[8](0x7fffffff, -0x7fffffff - 1, 0x7fffffff, -0x7fffffff - 1,
    -0x7fffffff - 1, 0, 0, 0x7fffffff);
  if (gl_LocalInvocationIndex < 8u)
  {
    aliasfreeGroupStats[gl_LocalInvocationIndex] = identity[gl_LocalInvocationIndex];
  }
  barrier();
}

void aliasfreeEndStats()
{
  barrier();
  if (gl_LocalInvocationIndex == 0u)
  {
#ifdef ALIASFREE_BOUNDS
    atomicMin(aliasfreeStats[0], aliasfreeGroupStats[0]);
    atomicMax(aliasfreeStats[1], aliasfreeGroupStats[1]);
    atomicMin(aliasfreeStats[2], aliasfreeGroupStats[2]);
    atomicMax(aliasfreeStats[3], aliasfreeGroupStats[3]);
    atomicMax(aliasfreeStats[4], aliasfreeGroupStats[4]);
    atomicMin(aliasfreeStats[7], aliasfreeGroupStats[7]);
#else
    atomicMax(aliasfreeStats[5], aliasfreeGroupStats[5]);
    atomicAdd(aliasfreeStats[6], aliasfreeGroupStats[6]);
#endif
  }
}
#endif

#ifdef ALIASFREE_BOUNDS
void main()
{
  aliasfreeBeginStats();
  vec3 p;
  vec2 ndc;
  uint why;
  if (aliasfreeInScreen() && aliasfreeViewSample(p, ndc, why))
  {
    atomicMin(aliasfreeGroupStats[0], aliasfreeOrdered(ndc.x));
    atomicMax(aliasfreeGroupStats[1], aliasfreeOrdered(ndc.x));
    atomicMin(aliasfreeGroupStats[2], aliasfreeOrdered(ndc.y));
    atomicMax(aliasfreeGroupStats[3], aliasfreeOrdered(ndc.y));
    atomicMax(aliasfreeGroupStats[4], aliasfreeOrdered(dot(p - aliasfreeEye, aliasfreeAxis)));
    if (aliasfreeLight.w > 0.0)
    {
      atomicMin(aliasfreeGroupStats[7], aliasfreeOrdered(distance(p, aliasfreeLight.xyz)));
    }
  }
  aliasfreeEndStats();
}
#endif

#ifdef ALIASFREE_COUNT
void main()
{
  aliasfreeBeginStats();
  vec3 p;
  vec2 ndc;
  uint why;
  uint pixel = aliasfreePixelIndex();
  if (aliasfreeInScreen())
  {
    if (!aliasfreeViewSample(p, ndc, why))
    {
      aliasfreePixels[pixel] = uvec2(aliasfreeNone, why);
    }
    else
    {
      ivec2 t = clamp(ivec2((ndc * 0.5 + 0.5) * float(aliasfreeMapSize)), ivec2(0),
        ivec2(aliasfreeMapSize - 1));
      uint texel = uint(t.y * aliasfreeMapSize + t.x);
      uint index = atomicAdd(aliasfreeCounts[texel], 1u);
      atomicMax(aliasfreeDepths[texel], aliasfreeOrdered(dot(p - aliasfreeEye, aliasfreeAxis)));
      aliasfreePixels[pixel] = uvec2(texel, index);
      atomicMax(aliasfreeGroupStats[5], int(index) + 1);
      atomicAdd(aliasfreeGroupStats[6], 1);
    }
  }
  aliasfreeEndStats();
}
#endif

#if defined(ALIASFREE_SCAN_BLOCKS) || defined(ALIASFREE_SCAN_TOP)
// Exclusive prefix sum of `per` consecutive values a thread, 256 threads:
// each thread sums its own, the threads' sums are scanned in shared memory
// (Hillis and Steele), then each thread writes its values' prefixes.
shared uint aliasfreeSums[256];

uint aliasfreeRead(uint i);
void aliasfreeWrite(uint i, uint value);

uint aliasfreeScan(uint first, uint per, uint end)
{
  uint own = 0u;
  for (uint i = first; i < min(first + per, end); ++i)
  {
    own += aliasfreeRead(i);
  }
  uint thread = gl_LocalInvocationID.x;
  aliasfreeSums[thread] = own;
  barrier();
  for (uint step = 1u; step < 256u; step *= 2u)
  {
    uint add = thread >= step ? aliasfreeSums[thread - step] : 0u;
    barrier();
    aliasfreeSums[thread] += add;
    barrier();
  }
  uint running = aliasfreeSums[thread] - own;
  for (uint i = first; i < min(first + per, end); ++i)
  {
    uint value = aliasfreeRead(i);
    aliasfreeWrite(i, running);
    running += value;
  }
  return aliasfreeSums[255];
}
#endif

#ifdef ALIASFREE_SCAN_BLOCKS
uint aliasfreeRead(uint i) { return aliasfreeCounts[i]; }
void aliasfreeWrite(uint i, uint value) { aliasfreeOffsets[i] = value; }
void main()
{
  // Work groups in rows of at most 65535 (the dispatch's guaranteed limit).
  uint block = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  if (block * 1024u >= uint(aliasfreeTexels))
  {
    return;
  }
  uint total = aliasfreeScan(block * 1024u + gl_LocalInvocationID.x * 4u, 4u, uint(aliasfreeTexels));
  if (gl_LocalInvocationID.x == 0u)
  {
    aliasfreeBlocks[block] = total;
  }
}
#endif

#ifdef ALIASFREE_SCAN_TOP
// One work group over the blocks' sums, in place.
uint aliasfreeRead(uint i) { return aliasfreeBlocks[i]; }
void aliasfreeWrite(uint i, uint value) { aliasfreeBlocks[i] = value; }
void main()
{
  uint blocks = uint(aliasfreeTexels);
  uint per = (blocks + 255u) / 256u;
  aliasfreeScan(gl_LocalInvocationID.x * per, per, blocks);
}
#endif

#ifdef ALIASFREE_SCAN_ADD
void main()
{
  uint i = gl_GlobalInvocationID.y * uint(aliasfreeMapSize) + gl_GlobalInvocationID.x;
  if (gl_GlobalInvocationID.x < uint(aliasfreeMapSize) && i < uint(aliasfreeTexels))
  {
    aliasfreeOffsets[i] += aliasfreeBlocks[i >> 10];
  }
}
#endif

#ifdef ALIASFREE_DEPTH_LEVEL
uniform ivec3 aliasfreeLevelFrom; // the level below: its first cell, cells a side (x and y)
uniform ivec3 aliasfreeLevelTo;   // this level
void main()
{
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(cell, aliasfreeLevelTo.yz)))
  {
    return;
  }
  int deepest = -0x7fffffff - 1;
  for (int k = 0; k < 4; ++k)
  {
    ivec2 below = min(2 * cell + ivec2(k & 1, k >> 1), aliasfreeLevelFrom.yz - 1);
    deepest = max(deepest, aliasfreeDepths[aliasfreeLevelFrom.x + below.y * aliasfreeLevelFrom.y + below.x]);
  }
  aliasfreeDepths[aliasfreeLevelTo.x + cell.y * aliasfreeLevelTo.y + cell.x] = deepest;
}
#endif

#ifdef ALIASFREE_DEPTH_MARKED
void main()
{
  uint i = gl_GlobalInvocationID.y * uint(aliasfreeMapSize) + gl_GlobalInvocationID.x;
  if (gl_GlobalInvocationID.x < uint(aliasfreeMapSize) && i < uint(aliasfreeTexels) &&
    aliasfreeMarks[i] == 0u)
  {
    aliasfreeDepths[i] = -0x7fffffff - 1;
  }
}
#endif

#ifdef ALIASFREE_SCATTER
void main()
{
  if (!aliasfreeInScreen())
  {
    return;
  }
  uint pixel = aliasfreePixelIndex();
  uvec2 entry = aliasfreePixels[pixel];
  if (entry.x == aliasfreeNone)
  {
    return;
  }
  uint slot = aliasfreeOffsets[entry.x] + entry.y;
  aliasfreeSamples[slot] =
    vec4(texelFetch(aliasfreePositions, ivec2(gl_GlobalInvocationID.xy), 0).xyz, 1.0);
  aliasfreePixels[pixel].y = slot;
}
#endif

#ifdef ALIASFREE_RESOLVE
// aliasfreeWords (vtkAliasFreeLookup.glsl): 0 hard, one bit a sample; else
// words a mask.
uniform int aliasfreeRestrict;        // soft: 1 where only marked texels hold masks
uniform int aliasfreeListedOnly;      // 1: write only the pixels listed (a cube's later faces)
layout(std430, binding = 0) readonly buffer aliasfreeCentreBuffer { uint aliasfreeCentre[]; };
uniform vec3 aliasfreeCameraPosition;
layout(rgba32f, binding = 0) writeonly uniform image2D aliasfreeVisibility;
// Temporal jitter: the visibility accumulated over the frames before (their
// number; 0: none, this frame starts it; -1: no jitter, no history).
layout(rgba32f, binding = 1) uniform image2D aliasfreeHistoryImage;
uniform int aliasfreeHistory;

void main()
{
  if (!aliasfreeInScreen())
  {
    return;
  }
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  uvec2 entry = aliasfreePixels[aliasfreePixelIndex()];
  if (aliasfreeListedOnly == 1 && entry.x == aliasfreeNone)
  {
    return;
  }
  vec4 p = texelFetch(aliasfreePositions, pixel, 0);
  float visibility = 1.0;
  if (entry.x != aliasfreeNone)
  {
    uint slot = entry.y;
    if (aliasfreeWords == 0)
    {
      visibility = float(1u - ((aliasfreeHidden[slot >> 5] >> (slot & 31u)) & 1u));
    }
    else if (aliasfreeRestrict == 1 && aliasfreeMarks[entry.x] == 0u)
    {
      // Outside every silhouette edge's influence: all of the light or none.
      visibility = float(1u - ((aliasfreeCentre[slot >> 5] >> (slot & 31u)) & 1u));
    }
    else
    {
      // The light samples behind the sample's own surface (its tangent
      // plane) are hidden by that surface: near a terminator, part of the
      // light is.
      vec4 n = texelFetch(aliasfreeNormals, pixel, 0);
      aliasfreePlaneMask below = aliasfreeSide(n.w > 0.5 ? -n.xyz : vec3(0.0), p.xyz, aliasfreeLight);
      uint hidden = 0u;
      for (int w = 0; w < aliasfreeWords; ++w)
      {
        uint own = n.w > 0.5 ? aliasfreeWord(below, w) : 0u;
        hidden += uint(bitCount(aliasfreeHidden[slot * uint(aliasfreeWords) + uint(w)] | own));
      }
      visibility = 1.0 - float(hidden) / float(32 * aliasfreeWords);
    }
  }
  else if (entry.y == aliasfreeFacingAway)
  {
    visibility = 0.0;
  }
  // (visibility, valid, camera distance): vtkShadowScreenBuffers::BeginVisibility().
  float valid = entry.x != aliasfreeNone || entry.y != aliasfreeBackground ? 1.0 : 0.0;
  vec4 result =
    vec4(visibility, valid, valid > 0.5 ? distance(p.xyz, aliasfreeCameraPosition) : 0.0, 0.0);
  if (aliasfreeWords > 0 && aliasfreeHistory > 0)
  {
    vec4 before = imageLoad(aliasfreeHistoryImage, pixel);
    float k = float(aliasfreeHistory);
    result.r = (before.r * k + visibility) / (k + 1.0);
  }
  if (aliasfreeWords > 0 && aliasfreeHistory >= 0)
  {
    imageStore(aliasfreeHistoryImage, pixel, result);
  }
  imageStore(aliasfreeVisibility, pixel, result);
}
#endif
