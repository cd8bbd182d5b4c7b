// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Conservative rasterization of a caster triangle into the alias-free map
// (Sintorn et al., section 3.2, after Hasselgren et al.): every texel the
// triangle touches runs the fragment shader, which tests the texel's view
// samples. The covered region is the triangle's projection, or with
// ALIASFREE_SOFT its influence region (4.1), grown by the texel square
// (their Minkowski sum: each vertex of the region becomes the square's
// corners between its two edges' outward normals), so that a texel is drawn
// exactly when the region touches it; then a triangle fan as a strip.
// With ALIASFREE_EDGES, an edge that is a silhouette for some point of the
// light (section 4.3: the light not wholly on one side of both its faces;
// borders and other odd edges always) covers its influence region, where
// the penumbrae lie: the texels outside every such region take the hard
// shadow of the light's centre.
// Both cull with the view samples' depths, read from a pyramid of their
// greatest depths: a triangle hides no sample nearer the light than itself,
// so its region is drawn only as deep as the deepest sample under it, and
// not at all when none lies beyond it.
// Uses: vtkAliasFreeCastersVS.glsl (its output), vtkAliasFreeCastersFS.glsl.

#ifdef ALIASFREE_EDGES
layout(lines_adjacency) in; // an edge a, b (and two unused vertices)
layout(triangle_strip, max_vertices = 16) out;
in vec4 aliasfreeFace0In[]; // its faces' normals (model); w = 1: always a silhouette
in vec3 aliasfreeFace1In[];
uniform mat3 aliasfreeNormalToWorld;
#else
layout(triangles) in;
#ifdef ALIASFREE_SOFT
layout(triangle_strip, max_vertices = 22) out;
#else
layout(triangle_strip, max_vertices = 9) out;
#endif
#endif

in vec3 aliasfreeWorldIn[];

uniform mat4 aliasfreeWorldToClip; // the fitted map
uniform vec4 aliasfreeLight;       // world position (w = 1), or direction towards it (w = 0)
uniform float aliasfreeMapSize;
// The target drawn: its size, and the map's NDC scaled about -1 into it
// ((ndc + 1) scale - 1), so that its cell k covers the map's texels from
// k / scale on: 1 at the map's size; soft, half of it rounded up, and n / 2R,
// a cell for texels 2k and 2k + 1 of an odd map too.
uniform float aliasfreeRasterSize;
uniform float aliasfreeRasterScale;
uniform int aliasfreeClosed;       // 1: the caster is closed, with outward normals...
uniform float aliasfreeOrientation; // ... along +cross(b - a, c - a) (1) or against it (-1)
#if defined(ALIASFREE_SOFT) || defined(ALIASFREE_EDGES)
uniform float aliasfreeReach;  // the light's bounding sphere (world), or tan(angular radius)
uniform vec3 aliasfreeEye;      // the map's eye and axis
uniform vec3 aliasfreeAxis;
uniform vec3 aliasfreeSide0;    // two unit vectors across the axis
uniform vec3 aliasfreeSide1;
uniform float aliasfreeFar;     // depth of the farthest view sample
// The pyramid of the view samples' greatest depths, order-preserving
// integers (vtkAliasFreeListsCS.glsl): texels, then 2x2 texels, and so on.
layout(std430, binding = 7) readonly buffer aliasfreeDepthsBuffer { int aliasfreeDepths[]; };
// The depth beyond which a sample may be hidden, as the pyramid holds it.
flat out int aliasfreeReachable;
int aliasfreeReachableDepth = 0;
#endif

#ifdef ALIASFREE_SOFT
flat out vec3 aliasfreeA; // the triangle, world
flat out vec3 aliasfreeB;
flat out vec3 aliasfreeC;
#else
flat out vec4 aliasfreePlane; // the triangle's plane, positive towards the light
flat out vec4 aliasfreeEdge0; // the planes through its edges and the light, positive inside
flat out vec4 aliasfreeEdge1;
flat out vec4 aliasfreeEdge2;
#endif

const float aliasfreePiOver6 = 0.52359877559830;
const int aliasfreeMaxPoints = 18;
const int aliasfreeDepthPasses = 2; // lookups of the depth pyramid a region (a third gains little)
vec2 aliasfreeRegion[aliasfreeMaxPoints];
int aliasfreeRegionSize = 0;

// A vertex at `ndc`, in the target's clip space (the whole map: no scaling).
void aliasfreeEmitVertex(vec2 ndc, bool inMap)
{
#ifdef ALIASFREE_SOFT
  aliasfreeA = aliasfreeWorldIn[0];
  aliasfreeB = aliasfreeWorldIn[1];
  aliasfreeC = aliasfreeWorldIn[2];
#endif
#if defined(ALIASFREE_SOFT) || defined(ALIASFREE_EDGES)
  aliasfreeReachable = aliasfreeReachableDepth;
#endif
  gl_Position = vec4(inMap ? (ndc + 1.0) * aliasfreeRasterScale - 1.0 : ndc, 0.0, 1.0);
  EmitVertex();
}

// The whole map: for triangles whose region cannot be bounded (behind the
// light's eye plane, a light inside its reach).
void aliasfreeEmitAll()
{
  aliasfreeEmitVertex(vec2(-1.0, -1.0), false);
  aliasfreeEmitVertex(vec2(1.0, -1.0), false);
  aliasfreeEmitVertex(vec2(-1.0, 1.0), false);
  aliasfreeEmitVertex(vec2(1.0, 1.0), false);
  EndPrimitive();
}

// The texel square's corner k (counter-clockwise from (+, +)) and the corner
// farthest along direction n.
vec2 aliasfreeCorner(int k, float h)
{
  return h * vec2(k == 0 || k == 3 ? 1.0 : -1.0, k < 2 ? 1.0 : -1.0);
}
int aliasfreeSupport(vec2 n)
{
  return n.y >= 0.0 ? (n.x >= 0.0 ? 0 : 1) : (n.x >= 0.0 ? 3 : 2);
}

float aliasfreeCross(vec2 a, vec2 b)
{
  return a.x * b.y - a.y * b.x;
}

// The region (a convex polygon, counter-clockwise) grown by the texel
// square, emitted as a strip: p0, p1, p(n-1), p2, p(n-2), ...
void aliasfreeEmitGrown()
{
  int n = aliasfreeRegionSize;
  // Half a cell of the target, a little more so that rounding never loses
  // one (in the map's NDC).
  float h = 1.001 / (aliasfreeRasterSize * aliasfreeRasterScale);
  vec2 grown[aliasfreeMaxPoints + 4];
  int count = 0;
  for (int i = 0; i < n; ++i)
  {
    vec2 p = aliasfreeRegion[i];
    vec2 before = p - aliasfreeRegion[(i + n - 1) % n];
    vec2 after = aliasfreeRegion[(i + 1) % n] - p;
    int k = aliasfreeSupport(vec2(before.y, -before.x));
    int last = aliasfreeSupport(vec2(after.y, -after.x));
    for (int step = 0; step < 4 && count < aliasfreeMaxPoints + 4; ++step)
    {
      grown[count++] = p + aliasfreeCorner(k, h);
      if (k == last)
      {
        break;
      }
      k = (k + 1) % 4;
    }
  }
  int left = 1, right = count - 1;
  aliasfreeEmitVertex(grown[0], true);
  for (bool fromLeft = true; left <= right; fromLeft = !fromLeft)
  {
    aliasfreeEmitVertex(fromLeft ? grown[left++] : grown[right--], true);
  }
  EndPrimitive();
}

// The convex hull (counter-clockwise) of `points` into aliasfreeRegion, by
// gift wrapping: a handful of points.
void aliasfreeHull(vec2 points[aliasfreeMaxPoints], int count)
{
  int start = 0;
  for (int i = 1; i < count; ++i)
  {
    if (points[i].x < points[start].x ||
      (points[i].x == points[start].x && points[i].y < points[start].y))
    {
      start = i;
    }
  }
  int current = start;
  aliasfreeRegionSize = 0;
  do
  {
    aliasfreeRegion[aliasfreeRegionSize++] = points[current];
    int next = (current + 1) % count;
    for (int i = 0; i < count; ++i)
    {
      float turn = aliasfreeCross(points[next] - points[current], points[i] - points[current]);
      // Clockwise of the candidate, or as far on its line: the hull turns there.
      if (turn < 0.0 ||
        (turn == 0.0 &&
          distance(points[i], points[current]) > distance(points[next], points[current])))
      {
        next = i;
      }
    }
    current = next;
  } while (current != start && aliasfreeRegionSize < aliasfreeMaxPoints);
}

#if defined(ALIASFREE_SOFT) || defined(ALIASFREE_EDGES)
// The points whose convex hull is the influence region of the first n
// input vertices drawn to depth `far`, into aliasfreePoints: their number,
// or -1 if the region is unbounded (the whole map).
vec2 aliasfreePoints[aliasfreeMaxPoints];
int aliasfreeProject(int n, float far)
{
  // Section 4.1: from each vertex v, the light's silhouette bounded by a
  // hexagon and projected through v onto the far plane (or farther for
  // vertices beyond it).
  for (int i = 0; i < n; ++i)
  {
    far = max(far, dot(aliasfreeWorldIn[i] - aliasfreeEye, aliasfreeAxis) * 1.001);
  }
  int count = 0;
  for (int i = 0; i < n; ++i)
  {
    vec3 v = aliasfreeWorldIn[i];
    float depth = dot(v - aliasfreeEye, aliasfreeAxis);
    vec3 centre, side0, side1;
    float reach;
    if (aliasfreeLight.w > 0.5)
    {
      // The sphere seen from v: a circle of radius R sqrt(1 - R^2 / D^2),
      // R^2 / D nearer v than the sphere's centre, across v -> centre.
      vec3 toLight = aliasfreeLight.xyz - v;
      float D = length(toLight);
      if (D <= aliasfreeReach * 1.001)
      {
        return -1;
      }
      vec3 u = toLight / D;
      centre = aliasfreeLight.xyz - u * (aliasfreeReach * aliasfreeReach / D);
      reach = aliasfreeReach * sqrt(max(1.0 - aliasfreeReach * aliasfreeReach / (D * D), 0.0)) /
        cos(aliasfreePiOver6);
      side0 = normalize(abs(u.x) < 0.9 ? cross(u, vec3(1.0, 0.0, 0.0)) : cross(u, vec3(0.0, 1.0, 0.0)));
      side1 = cross(u, side0);
      for (int k = 0; k < 6; ++k)
      {
        float angle = float(k) * 2.0 * aliasfreePiOver6;
        vec3 h = centre + reach * (cos(angle) * side0 + sin(angle) * side1);
        float hd = dot(h - aliasfreeEye, aliasfreeAxis);
        if (depth <= hd + 1.0e-6 * abs(depth))
        {
          return -1; // v beside or before the light: no bound
        }
        vec3 x = h + (v - h) * ((far - hd) / (depth - hd));
        vec4 clip = aliasfreeWorldToClip * vec4(x, 1.0);
        if (clip.w <= 0.0)
        {
          return -1;
        }
        aliasfreePoints[count++] = clip.xy / clip.w;
      }
    }
    else
    {
      // Directional: v moved to the far plane along the cone's directions,
      // a circle of radius (far - depth) tan(angular radius) across the axis.
      reach = max(far - depth, 0.0) * aliasfreeReach / cos(aliasfreePiOver6);
      centre = v + max(far - depth, 0.0) * aliasfreeAxis;
      for (int k = 0; k < 6; ++k)
      {
        float angle = float(k) * 2.0 * aliasfreePiOver6;
        vec3 x = centre + reach * (cos(angle) * aliasfreeSide0 + sin(angle) * aliasfreeSide1);
        vec4 clip = aliasfreeWorldToClip * vec4(x, 1.0);
        aliasfreePoints[count++] = clip.xy / clip.w;
      }
    }
  }
  return count;
}

int aliasfreeOrdered(float f)
{
  int i = floatBitsToInt(f);
  return i >= 0 ? i : i ^ 0x7fffffff;
}

// The deepest view sample under the bounds of the first `count`
// aliasfreePoints (grown by a texel), as an order-preserving integer (the
// smallest integer where there is none): from the pyramid's finest level
// that covers the bounds with 3x3 cells.
int aliasfreeDeepestUnder(int count)
{
  vec2 lo = aliasfreePoints[0], hi = lo;
  for (int i = 1; i < count; ++i)
  {
    lo = min(lo, aliasfreePoints[i]);
    hi = max(hi, aliasfreePoints[i]);
  }
  const int none = -0x7fffffff - 1;
  int size = int(aliasfreeMapSize);
  vec2 toTexels = vec2(0.5 * aliasfreeMapSize);
  ivec2 t0 = ivec2(floor((clamp(lo, -2.0, 2.0) + 1.0) * toTexels)) - 1;
  ivec2 t1 = ivec2(floor((clamp(hi, -2.0, 2.0) + 1.0) * toTexels)) + 1;
  if (any(lessThan(t1, ivec2(0))) || any(greaterThanEqual(t0, ivec2(size))))
  {
    return none; // wholly outside the map
  }
  t0 = max(t0, ivec2(0));
  t1 = min(t1, ivec2(size - 1));
  int first = 0;
  while (max(t1.x - t0.x, t1.y - t0.y) > 2)
  {
    first += size * size;
    size = (size + 1) / 2;
    t0 /= 2;
    t1 /= 2;
  }
  int deepest = none;
  for (int y = t0.y; y <= t1.y; ++y)
  {
    for (int x = t0.x; x <= t1.x; ++x)
    {
      deepest = max(deepest, aliasfreeDepths[first + y * size + x]);
    }
  }
  return deepest;
}

// The influence region of the first n input vertices into aliasfreeRegion:
// 1 if bounded, 0 if empty, -1 if unbounded (the whole map). Drawn only as
// deep as the deepest view sample under it, found by drawing it at the
// farthest sample's depth, then again at the depth found under that, which
// the shallower region's smaller bounds may lower again.
int aliasfreeInfluence(int n)
{
  float nearest = 3.0e38, farthest = -3.0e38;
  for (int i = 0; i < n; ++i)
  {
    float depth = dot(aliasfreeWorldIn[i] - aliasfreeEye, aliasfreeAxis);
    nearest = min(nearest, depth);
    farthest = max(farthest, depth);
  }
  if (aliasfreeLight.w > 0.5 && farthest < -aliasfreeReach)
  {
    return 0; // wholly behind the light: between it and no view sample
  }
  // A segment from a point of the light to a sample reaches no deeper than
  // the deeper of the two: beyond the light, the triangle hides only
  // samples deeper than its nearest point.
  float lightDeepest = aliasfreeLight.w > 0.5
    ? dot(aliasfreeLight.xyz - aliasfreeEye, aliasfreeAxis) + aliasfreeReach
    : -3.0e38;
  nearest = nearest > lightDeepest ? nearest : -3.0e38;
  aliasfreeReachableDepth = aliasfreeOrdered(nearest);
  float far = aliasfreeFar;
  if (nearest > far)
  {
    return 0;
  }
  int count = aliasfreeProject(n, far);
  for (int pass = 0; pass < aliasfreeDepthPasses && count > 0; ++pass)
  {
    int deepest = aliasfreeDeepestUnder(count);
    if (deepest < aliasfreeReachableDepth)
    {
      return 0;
    }
    float depth = intBitsToFloat(deepest >= 0 ? deepest : deepest ^ 0x7fffffff);
    if (depth >= far)
    {
      break;
    }
    far = depth;
    count = aliasfreeProject(n, far);
  }
  if (count < 0)
  {
    return -1;
  }
  aliasfreeHull(aliasfreePoints, count);
  if (aliasfreeRegionSize < 3 && far < aliasfreeFar)
  {
    // Drawn shallower, a region can come out empty (its points all but
    // one): then the deepest one stands.
    aliasfreeHull(aliasfreePoints, aliasfreeProject(n, aliasfreeFar));
  }
  return aliasfreeRegionSize < 3 ? 0 : 1;
}

// The influence region of the first n input vertices, grown, or the whole
// map where it is unbounded.
void aliasfreeEmitInfluence(int n)
{
  int region = aliasfreeInfluence(n);
  if (region < 0)
  {
    aliasfreeEmitAll();
  }
  else if (region > 0)
  {
    aliasfreeEmitGrown();
  }
}
#endif

vec3 aliasfreeTowardsLight(vec3 p)
{
  return aliasfreeLight.w > 0.5 ? aliasfreeLight.xyz - p : aliasfreeLight.xyz;
}

#ifdef ALIASFREE_EDGES
// Where the light's centre lies from a face's plane, in units of the
// light's reach: beyond 1 the whole light is in front, below -1 behind.
float aliasfreeSideOf(vec3 n, vec3 p)
{
  return aliasfreeLight.w > 0.5
    ? dot(n, aliasfreeLight.xyz - p) / aliasfreeReach
    : dot(n, normalize(aliasfreeLight.xyz)) * sqrt(1.0 + aliasfreeReach * aliasfreeReach) / aliasfreeReach;
}

void main()
{
  vec3 a = aliasfreeWorldIn[0];
  vec4 face0 = aliasfreeFace0In[0];
  vec3 n0 = aliasfreeNormalToWorld * face0.xyz;
  vec3 n1 = aliasfreeNormalToWorld * aliasfreeFace1In[0];
  if (face0.w < 0.5 && dot(n0, n0) > 0.0 && dot(n1, n1) > 0.0)
  {
    float s0 = aliasfreeSideOf(normalize(n0), a), s1 = aliasfreeSideOf(normalize(n1), a);
    if ((s0 > 1.0 && s1 > 1.0) || (s0 < -1.0 && s1 < -1.0))
    {
      return; // a silhouette for no point of the light
    }
  }
  aliasfreeEmitInfluence(2);
}
#else
void main()
{
  vec3 a = aliasfreeWorldIn[0], b = aliasfreeWorldIn[1], c = aliasfreeWorldIn[2];
  vec3 normal = cross(b - a, c - a);
  if (dot(normal, normal) <= 0.0)
  {
    return; // no area: hides nothing
  }
  normal = normalize(normal);
  float facing = dot(normal, aliasfreeTowardsLight(a));
#ifdef ALIASFREE_SOFT
  // Closed casters: a triangle hides light samples behind its inner side
  // only; none when the whole light lies on its outer side.
  if (aliasfreeClosed == 1)
  {
    vec3 outward = aliasfreeOrientation * normal;
    float reach = aliasfreeLight.w > 0.5
      ? dot(outward, aliasfreeLight.xyz - a) - aliasfreeReach
      : dot(outward, normalize(aliasfreeLight.xyz)) - aliasfreeReach / sqrt(1.0 + aliasfreeReach * aliasfreeReach);
    if (reach > 0.0)
    {
      return;
    }
  }
  aliasfreeEmitInfluence(3);
#else
  // Closed casters: light-back-facing triangles alone (section 3.3).
  if (aliasfreeClosed == 1 && aliasfreeOrientation * facing > 0.0)
  {
    return;
  }
  vec3 towards = facing >= 0.0 ? normal : -normal;
  aliasfreePlane = vec4(towards, -dot(towards, a));
  vec3 corners[3] = vec3[3](a, b, c);
  vec4 edges[3];
  for (int i = 0; i < 3; ++i)
  {
    vec3 p = corners[i], q = corners[(i + 1) % 3], r = corners[(i + 2) % 3];
    vec3 m = aliasfreeLight.w > 0.5 ? cross(p - aliasfreeLight.xyz, q - aliasfreeLight.xyz)
                                    : cross(q - p, aliasfreeLight.xyz);
    float length2 = dot(m, m);
    if (length2 <= 0.0)
    {
      return; // seen edge-on from the light
    }
    m *= inversesqrt(length2);
    m *= dot(m, r - p) >= 0.0 ? 1.0 : -1.0;
    edges[i] = vec4(m, -dot(m, p));
  }
  aliasfreeEdge0 = edges[0];
  aliasfreeEdge1 = edges[1];
  aliasfreeEdge2 = edges[2];
  vec4 clips[3];
  int behind = 0;
  for (int i = 0; i < 3; ++i)
  {
    clips[i] = aliasfreeWorldToClip * vec4(corners[i], 1.0);
    behind += clips[i].w <= 0.0 ? 1 : 0;
  }
  if (behind > 0)
  {
    // Wholly behind the light's eye plane: between it and no view sample;
    // across it: unbounded in the map.
    if (behind < 3)
    {
      aliasfreeEmitAll();
    }
    return;
  }
  vec2 p0 = clips[0].xy / clips[0].w, p1 = clips[1].xy / clips[1].w, p2 = clips[2].xy / clips[2].w;
  float area = aliasfreeCross(p1 - p0, p2 - p0);
  if (area == 0.0)
  {
    return; // edge-on from the light: hides nothing
  }
  aliasfreeRegion[0] = p0;
  aliasfreeRegion[1] = area > 0.0 ? p1 : p2;
  aliasfreeRegion[2] = area > 0.0 ? p2 : p1;
  aliasfreeRegionSize = 3;
  aliasfreeEmitGrown();
#endif
}
#endif
