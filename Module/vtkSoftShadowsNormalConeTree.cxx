// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSoftShadowsNormalConeTree.h"

#include "vtkSMPTools.h"

#include <glm/geometric.hpp> // for glm::dot, glm::length
#include <glm/vec3.hpp>      // for glm::dvec3

#include <algorithm>  // for std::nth_element, std::min, std::max
#include <cmath>      // for std::abs, std::ldexp, std::nextafter
#include <cstring>    // for std::memcpy
#include <functional> // for std::function

#if defined(__SSE__)
#include <xmmintrin.h> // for _mm_movemask_ps
#endif

namespace vtksoftshadows
{
namespace
{
// Leaves of 16 to 32 edges: testing a leaf's edges (together in memory, four
// faces an instruction) costs less than one more level of nodes. On
// meshbench's knot leaves of 8 to 16 edges took 15-25% longer a light, and
// of 32 to 64 (two mask words) 20-35% longer.
constexpr std::int32_t LeafSize = 32;
static_assert(2 * LeafSize <= 64, "a leaf's faces are bits of a 64-bit mask");
// The top levels of the tree are split serially, into up to 2^SerialDepth
// subtrees that are then built in parallel.
constexpr int SerialDepth = 5;
// A query's walk is shared among threads below this many nodes and leaves
// from the root, and only for trees of this many edges or more. Few walks:
// each keeps more fetches in flight the wider its levels are, and the leaves
// they reach are shared evenly afterwards whatever the walks' sizes. On the
// knot 4 beat 8 by 7-20% a light, 8 beat 64 by 15%; 2 was slower than 4.
constexpr std::size_t ParallelFrontier = 4;
constexpr vtkIdType SerialBelowEdges = vtkIdType(1) << 14;
// The leaves reached are then tested in this many runs a thread (for work
// stealing to even out), of at least this many leaves each.
constexpr std::size_t SharesPerThread = 4;
constexpr std::size_t MinimumShare = 64;

glm::dvec3 Vec(const double* v)
{
  return glm::dvec3(v[0], v[1], v[2]);
}

// Floats no greater (no smaller) than a double.
float RoundDown(double value)
{
  const float f = static_cast<float>(value);
  return static_cast<double>(f) <= value ? f : std::nextafter(f, -VTK_FLOAT_MAX);
}
float RoundUp(double value)
{
  const float f = static_cast<float>(value);
  return static_cast<double>(f) >= value ? f : std::nextafter(f, VTK_FLOAT_MAX);
}

// A vector a float holds exactly, near v: stored, and v made equal to it (the
// bounds are then taken against what the query reads).
void ToFloat(glm::dvec3& v, float out[3])
{
  for (int c = 0; c < 3; ++c)
  {
    out[c] = static_cast<float>(v[c]);
    v[c] = out[c];
  }
}

#if defined(__GNUC__) || defined(__clang__)
// Four floats (or ints) in one SIMD register, with the compiler's vector
// extensions: SSE on x86-64, NEON on ARM. A node's four children are tested
// at once, lane by lane.
using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));
Float4 Load4(const float* values)
{
  Float4 v;
  std::memcpy(&v, values, sizeof(v));
  return v;
}
Int4 Load4(const std::int32_t* values)
{
  Int4 v;
  std::memcpy(&v, values, sizeof(v));
  return v;
}
// The lanes' sign bits, four bits (one instruction with SSE).
unsigned Bits(Int4 mask)
{
#if defined(__SSE__)
  return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(mask)));
#else
  return (mask[0] & 1u) | (mask[1] & 2u) | (mask[2] & 4u) | (mask[3] & 8u);
#endif
}
Float4 Abs(Float4 x)
{
  return reinterpret_cast<Float4>(reinterpret_cast<Int4>(x) & 0x7fffffff);
}
Float4 Max(Float4 a, Float4 b)
{
  return a > b ? a : b;
}
Float4 Min(Float4 a, Float4 b)
{
  return a < b ? a : b;
}
#else
// Elsewhere one child at a time.
float Abs(float x)
{
  return std::abs(x);
}
float Max(float a, float b)
{
  return std::max(a, b);
}
float Min(float a, float b)
{
  return std::min(a, b);
}
#endif

// A hint that memory will be read soon; nothing where the compiler has none.
inline void Prefetch(const void* address)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(address);
#else
  (void)address;
#endif
}

inline int LowestBit(std::uint64_t bits)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(bits);
#else
  int k = 0;
  while (!(bits & 1))
  {
    bits >>= 1;
    ++k;
  }
  return k;
#endif
}
}

//------------------------------------------------------------------------------
// A node of the binary tree the build makes first, with its bounds already in
// the form a Node keeps for each of its children.
struct NormalConeTree::BinaryNode
{
  float Axis[3], U[3], S[3];
  float RadiusU, RadiusS, Residual;
  float Center[3];
  float OffsetMin, OffsetMax;
  std::int32_t Begin, End; // its edges, Begin .. End - 1 in tree order
  std::int32_t Right;      // right child (the left one follows the node); < 0 in a leaf
};

//------------------------------------------------------------------------------
struct NormalConeTree::Builder
{
  const RawVector<Edge>& Edges;
  const RawVector<double>& Midpoints;
  const double* Normals;
  const double* Offsets; // relative to Origin
  glm::dvec3 Origin;
  RawVector<std::int32_t> Order; // the tree's edge order, into Edges
  RawVector<float> Keys;         // 6 an edge: scaled midpoint, mean normal (only to split)

  // The node's normal box (axis, frame, radii), centre and offset range, from
  // all faces of its edges, each rounded to float outward.
  void Bound(BinaryNode& node) const
  {
    auto forFaces = [&](auto&& visit)
    {
      for (std::int32_t i = node.Begin; i < node.End; ++i)
      {
        for (std::int32_t f : this->Edges[this->Order[i]].Faces)
        {
          visit(f, Vec(this->Normals + 3 * static_cast<vtkIdType>(f)));
        }
      }
    };
    glm::dvec3 sum(0.0), center(0.0);
    forFaces([&](std::int32_t, const glm::dvec3& n) { sum += n; });
    for (std::int32_t i = node.Begin; i < node.End; ++i)
    {
      center += Vec(this->Midpoints.data() + 3 * static_cast<vtkIdType>(this->Order[i]));
    }
    center = center / static_cast<double>(node.End - node.Begin) - this->Origin;
    const double length = glm::length(sum);
    const glm::dvec3 t = length > 0.0 ? sum / length : glm::dvec3(0.0, 0.0, 1.0);

    // The frame: u along the normals' widest spread across t (the principal
    // axis of their tangential deviations), s across both.
    const glm::dvec3 e1 =
      glm::normalize(std::abs(t.x) < 0.9 ? glm::cross(t, glm::dvec3(1.0, 0.0, 0.0))
                                         : glm::cross(t, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 e2 = glm::cross(t, e1);
    double cxx = 0.0, cxy = 0.0, cyy = 0.0;
    forFaces(
      [&](std::int32_t, const glm::dvec3& n)
      {
        const double x = glm::dot(n, e1), y = glm::dot(n, e2);
        cxx += x * x;
        cxy += x * y;
        cyy += y * y;
      });
    const double angle = 0.5 * std::atan2(2.0 * cxy, cxx - cyy);
    glm::dvec3 u = std::cos(angle) * e1 + std::sin(angle) * e2;
    glm::dvec3 s = glm::cross(t, u);
    ToFloat(u, node.U);
    ToFloat(s, node.S);

    // The box's centre a, then each normal n = a + alpha u + beta s + rest:
    // exact with the float u, s and a whatever their round-off, so the
    // radii bound |alpha|, |beta| and |rest| for the vectors the query uses.
    double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
    double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
    forFaces(
      [&](std::int32_t, const glm::dvec3& n)
      {
        const double c[3] = { glm::dot(n, t), glm::dot(n, u), glm::dot(n, s) };
        for (int k = 0; k < 3; ++k)
        {
          lo[k] = std::min(lo[k], c[k]);
          hi[k] = std::max(hi[k], c[k]);
        }
      });
    glm::dvec3 axis = 0.5 * ((lo[0] + hi[0]) * t + (lo[1] + hi[1]) * u + (lo[2] + hi[2]) * s);
    ToFloat(axis, node.Axis);
    ToFloat(center, node.Center);
    double radiusU = 0.0, radiusS = 0.0, residual = 0.0;
    double offsetMin = VTK_DOUBLE_MAX, offsetMax = -VTK_DOUBLE_MAX;
    forFaces(
      [&](std::int32_t f, const glm::dvec3& n)
      {
        const glm::dvec3 d = n - axis;
        const double alpha = glm::dot(d, u), beta = glm::dot(d, s);
        radiusU = std::max(radiusU, std::abs(alpha));
        radiusS = std::max(radiusS, std::abs(beta));
        residual = std::max(residual, glm::length(d - alpha * u - beta * s));
        const double e = this->Offsets[f] - glm::dot(n, center);
        offsetMin = std::min(offsetMin, e);
        offsetMax = std::max(offsetMax, e);
      });
    node.RadiusU = RoundUp(radiusU);
    node.RadiusS = RoundUp(radiusS);
    node.Residual = RoundUp(residual);
    node.OffsetMin = RoundDown(offsetMin);
    node.OffsetMax = RoundUp(offsetMax);
  }

  // Median split along the widest of the six key coordinates (position and
  // normal), so that nodes gather edges that are near each other and face the
  // same way: tight cones, small offset ranges. Returns the middle.
  std::int32_t Split(std::int32_t begin, std::int32_t end)
  {
    float lo[6], hi[6];
    std::fill(lo, lo + 6, VTK_FLOAT_MAX);
    std::fill(hi, hi + 6, -VTK_FLOAT_MAX);
    for (std::int32_t i = begin; i < end; ++i)
    {
      const float* key = this->Keys.data() + 6 * static_cast<vtkIdType>(this->Order[i]);
      for (int c = 0; c < 6; ++c)
      {
        lo[c] = std::min(lo[c], key[c]);
        hi[c] = std::max(hi[c], key[c]);
      }
    }
    int axis = 0;
    for (int c = 1; c < 6; ++c)
    {
      axis = hi[c] - lo[c] > hi[axis] - lo[axis] ? c : axis;
    }
    const std::int32_t middle = begin + (end - begin) / 2;
    const float* keys = this->Keys.data();
    std::nth_element(this->Order.begin() + begin, this->Order.begin() + middle,
      this->Order.begin() + end,
      [keys, axis](std::int32_t a, std::int32_t b)
      {
        return keys[6 * static_cast<vtkIdType>(a) + axis] <
          keys[6 * static_cast<vtkIdType>(b) + axis];
      });
    return middle;
  }

  // A whole subtree, depth first, into `nodes` (Right relative to `nodes`).
  std::int32_t BuildSubtree(std::int32_t begin, std::int32_t end, std::vector<BinaryNode>& nodes)
  {
    const std::int32_t index = static_cast<std::int32_t>(nodes.size());
    nodes.emplace_back();
    BinaryNode node;
    node.Begin = begin;
    node.End = end;
    node.Right = -1;
    this->Bound(node);
    if (end - begin > LeafSize)
    {
      const std::int32_t middle = this->Split(begin, end);
      this->BuildSubtree(begin, middle, nodes);
      node.Right = this->BuildSubtree(middle, end, nodes);
    }
    nodes[index] = node;
    return index;
  }
};

//------------------------------------------------------------------------------
void NormalConeTree::Build(const RawVector<Edge>& edges, const RawVector<double>& midpoints,
  const double* normals, const double* offsets, const double origin[3], double radius)
{
  std::copy_n(origin, 3, this->Origin);
  this->Radius = radius;
  this->Nodes.clear();
  this->LeafBlocks.clear();
  this->LeafFaces.clear();
  this->EdgeOutputs.clear();
  this->Planes.clear();
  const vtkIdType numEdges = static_cast<vtkIdType>(edges.size());
  this->NumberOfEdges = numEdges;
  if (numEdges == 0)
  {
    return;
  }
  // The planes relative to the origin: d' = d - n . origin.
  std::int32_t maxFace = 0;
  for (const Edge& edge : edges)
  {
    maxFace = std::max({ maxFace, edge.Faces[0], edge.Faces[1] });
  }
  const std::size_t numFaces = static_cast<std::size_t>(maxFace) + 1;
  RawVector<double> localOffsets(numFaces);
  this->MaxOffset = this->MaxLocalOffset = 0.0;
  for (std::size_t f = 0; f < numFaces; ++f)
  {
    localOffsets[f] = offsets[f] - glm::dot(Vec(normals + 3 * f), Vec(origin));
    this->MaxOffset = std::max(this->MaxOffset, std::abs(offsets[f]));
    this->MaxLocalOffset = std::max(this->MaxLocalOffset, std::abs(localOffsets[f]));
  }
  Builder builder{ edges, midpoints, normals, localOffsets.data(), Vec(origin), {}, {} };
  builder.Order.resize(numEdges);
  builder.Keys.resize(6 * numEdges);

  // Positions in units of the mesh size, normals as they are: both span about 1.
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (vtkIdType i = 0; i < numEdges; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], midpoints[3 * i + c]);
      hi[c] = std::max(hi[c], midpoints[3 * i + c]);
    }
  }
  const double size =
    std::max(glm::length(glm::dvec3(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2])), VTK_DOUBLE_MIN);
  vtkSMPTools::For(0, numEdges,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        builder.Order[i] = static_cast<std::int32_t>(i);
        const glm::dvec3 n = Vec(normals + 3 * static_cast<vtkIdType>(edges[i].Faces[0])) +
          Vec(normals + 3 * static_cast<vtkIdType>(edges[i].Faces[1]));
        const double length = glm::length(n);
        for (int c = 0; c < 3; ++c)
        {
          builder.Keys[6 * i + c] = static_cast<float>((midpoints[3 * i + c] - lo[c]) / size);
          builder.Keys[6 * i + 3 + c] = static_cast<float>(length > 0.0 ? n[c] / length : 0.0);
        }
      }
    });

  // The top levels, serially: nodes (children still unknown) and the ranges
  // left for subtrees, in depth-first order.
  struct Top
  {
    BinaryNode Data;
    int Left = -1, Right = -1;       // children: indices into tops, or
    int LeftSub = -1, RightSub = -1; // indices into subtree ranges
  };
  std::vector<Top> tops;
  std::vector<std::pair<std::int32_t, std::int32_t>> ranges;
  // Returns the index of the top node for [begin, end), or -1 - subtree index.
  std::function<int(std::int32_t, std::int32_t, int)> split = [&](std::int32_t begin,
                                                                std::int32_t end, int depth) -> int
  {
    if (depth == SerialDepth || end - begin <= LeafSize)
    {
      ranges.emplace_back(begin, end);
      return -static_cast<int>(ranges.size());
    }
    const int index = static_cast<int>(tops.size());
    tops.emplace_back();
    tops[index].Data.Begin = begin;
    tops[index].Data.End = end;
    builder.Bound(tops[index].Data);
    const std::int32_t middle = builder.Split(begin, end);
    const int left = split(begin, middle, depth + 1);
    const int right = split(middle, end, depth + 1);
    (left >= 0 ? tops[index].Left : tops[index].LeftSub) = left >= 0 ? left : -left - 1;
    (right >= 0 ? tops[index].Right : tops[index].RightSub) = right >= 0 ? right : -right - 1;
    return index;
  };
  const int root = split(0, static_cast<std::int32_t>(numEdges), 0);

  // The subtrees, in parallel.
  std::vector<std::vector<BinaryNode>> subtrees(ranges.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(ranges.size()), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType r = begin; r < end; ++r)
      {
        builder.BuildSubtree(ranges[r].first, ranges[r].second, subtrees[r]);
      }
    });

  // Assembly of the binary tree, depth first: a node, its left child's
  // nodes, its right child's.
  std::vector<BinaryNode> binary;
  binary.reserve(2 * (numEdges / LeafSize + 1));
  auto appendSubtree = [&binary, &subtrees](int r)
  {
    const std::int32_t base = static_cast<std::int32_t>(binary.size());
    for (BinaryNode node : subtrees[r])
    {
      node.Right = node.Right >= 0 ? node.Right + base : -1;
      binary.push_back(node);
    }
    std::vector<BinaryNode>().swap(subtrees[r]);
  };
  std::function<void(int)> append = [&](int top)
  {
    const std::int32_t index = static_cast<std::int32_t>(binary.size());
    binary.push_back(tops[top].Data);
    if (tops[top].Left >= 0)
    {
      append(tops[top].Left);
    }
    else
    {
      appendSubtree(tops[top].LeftSub);
    }
    binary[index].Right = static_cast<std::int32_t>(binary.size());
    if (tops[top].Right >= 0)
    {
      append(tops[top].Right);
    }
    else
    {
      appendSubtree(tops[top].RightSub);
    }
  };
  if (root >= 0)
  {
    append(root);
  }
  else
  {
    appendSubtree(-root - 1);
  }

  // The exact planes, for the rare faces the float test cannot decide.
  this->Planes.resize(4 * numFaces);
  for (std::size_t f = 0; f < numFaces; ++f)
  {
    std::copy_n(normals + 3 * f, 3, this->Planes.data() + 4 * f);
    this->Planes[4 * f + 3] = offsets[f];
  }

  // The binary tree collapsed into nodes of up to four children: a node's
  // children are its binary descendants two levels down, or fewer where
  // leaves come first. Nodes and leaves are laid out depth first, children in
  // tree order.
  this->EdgeOutputs.resize(3 * numEdges);
  this->Nodes.reserve(binary.size() / 3 + 1);
  RawVector<std::int32_t> local(numFaces);
  std::fill(local.begin(), local.end(), -1);
  auto numEdgesOf = [&binary](std::int32_t b) { return binary[b].End - binary[b].Begin; };
  std::function<std::int32_t(const std::int32_t*, int)> collapse = [&](const std::int32_t* children,
                                                                     int count) -> std::int32_t
  {
    std::int32_t slots[4] = { children[0], count > 1 ? children[1] : -1, -1, -1 };
    while (count < 4)
    {
      int widest = -1;
      for (int k = 0; k < count; ++k)
      {
        if (binary[slots[k]].Right >= 0 &&
          (widest < 0 || numEdgesOf(slots[k]) > numEdgesOf(slots[widest])))
        {
          widest = k;
        }
      }
      if (widest < 0)
      {
        break;
      }
      const std::int32_t opened = slots[widest];
      slots[widest] = opened + 1;
      slots[count++] = binary[opened].Right;
    }
    // In tree order (an insertion sort: at most four).
    for (int k = 1; k < count; ++k)
    {
      for (int j = k; j > 0 && binary[slots[j]].Begin < binary[slots[j - 1]].Begin; --j)
      {
        std::swap(slots[j], slots[j - 1]);
      }
    }
    const std::int32_t index = static_cast<std::int32_t>(this->Nodes.size());
    this->Nodes.emplace_back();
    Node node{};
    for (int k = 0; k < 4; ++k)
    {
      node.Child[k] = Empty;
    }
    for (int k = 0; k < count; ++k)
    {
      const BinaryNode& b = binary[slots[k]];
      node.AxisX[k] = b.Axis[0];
      node.AxisY[k] = b.Axis[1];
      node.AxisZ[k] = b.Axis[2];
      node.UX[k] = b.U[0];
      node.UY[k] = b.U[1];
      node.UZ[k] = b.U[2];
      node.SX[k] = b.S[0];
      node.SY[k] = b.S[1];
      node.SZ[k] = b.S[2];
      node.RadiusU[k] = b.RadiusU;
      node.RadiusS[k] = b.RadiusS;
      node.Residual[k] = b.Residual;
      node.CenterX[k] = b.Center[0];
      node.CenterY[k] = b.Center[1];
      node.CenterZ[k] = b.Center[2];
      node.OffsetMin[k] = b.OffsetMin;
      node.OffsetMax[k] = b.OffsetMax;
      if (b.Right >= 0)
      {
        const std::int32_t grandchildren[2] = { slots[k] + 1, b.Right };
        node.Child[k] = collapse(grandchildren, 2);
      }
      else
      {
        node.Child[k] =
          -1 - this->AppendLeaf(builder.Order.data(), b.Begin, b.End, edges, localOffsets, local);
      }
    }
    this->Nodes[index] = node;
    return index;
  };
  if (binary[0].Right >= 0)
  {
    const std::int32_t children[2] = { 1, binary[0].Right };
    collapse(children, 2);
  }
  else
  {
    const std::int32_t only = 0;
    collapse(&only, 1);
  }
}

//------------------------------------------------------------------------------
std::int32_t NormalConeTree::AppendLeaf(const std::int32_t* order, std::int32_t begin,
  std::int32_t end, const RawVector<Edge>& edges, const RawVector<double>& localOffsets,
  RawVector<std::int32_t>& local)
{
  const std::int32_t first = static_cast<std::int32_t>(this->LeafBlocks.size());
  LeafHeader header;
  header.EdgeBegin = begin;
  header.FaceBase = static_cast<std::int32_t>(this->LeafFaces.size());
  header.NumEdges = end - begin;
  std::uint8_t pairs[2 * LeafSize];
  for (std::int32_t i = begin; i < end; ++i)
  {
    const Edge& edge = edges[order[i]];
    for (int k = 0; k < 2; ++k)
    {
      const std::int32_t f = edge.Faces[k];
      if (local[f] < 0)
      {
        local[f] = static_cast<std::int32_t>(this->LeafFaces.size()) - header.FaceBase;
        this->LeafFaces.push_back(f);
      }
      pairs[2 * (i - begin) + k] = static_cast<std::uint8_t>(local[f]);
    }
    this->EdgeOutputs[3 * static_cast<vtkIdType>(i)] = edge.Id;
    this->EdgeOutputs[3 * static_cast<vtkIdType>(i) + 1] = edge.Points[0];
    this->EdgeOutputs[3 * static_cast<vtkIdType>(i) + 2] = edge.Points[1];
  }
  header.NumFaces = static_cast<std::int32_t>(this->LeafFaces.size()) - header.FaceBase;

  Block block{};
  std::memcpy(block.Values, &header, sizeof(header));
  this->LeafBlocks.push_back(block);
  for (std::int32_t group = 0; group < header.NumFaces; group += 4)
  {
    Block planes[4] = {};
    for (std::int32_t k = 0; k < 4 && group + k < header.NumFaces; ++k)
    {
      const std::int32_t face = this->LeafFaces[header.FaceBase + group + k];
      for (int c = 0; c < 3; ++c)
      {
        planes[c].Values[k] = static_cast<float>(this->Planes[4 * face + c]);
      }
      planes[3].Values[k] = static_cast<float>(localOffsets[face]);
    }
    this->LeafBlocks.insert(this->LeafBlocks.end(), planes, planes + 4);
  }
  for (std::int32_t i = 0; i < 2 * header.NumEdges; i += sizeof(Block))
  {
    block = Block{};
    std::memcpy(
      block.Values, pairs + i, std::min<std::size_t>(sizeof(Block), 2 * header.NumEdges - i));
    this->LeafBlocks.push_back(block);
  }
  for (std::int32_t j = header.FaceBase; j < header.FaceBase + header.NumFaces; ++j)
  {
    local[this->LeafFaces[j]] = -1;
  }
  return first;
}

//------------------------------------------------------------------------------
float NormalConeTree::Tolerance(const double local[4], double exact) const
{
  // The float test of a child errs by at most 2^-17.5 B, B = |L|_1 + 2 |w|
  // R for the light L relative to the origin and the radius R around it
  // (|V|_1 <= B as |c| <= R; |e_f| <= 2 R): rounding L and forming V cost
  // 2^-23 B, each of a . V, u . V and s . V 2^-21 B, the spread (radii <= 2,
  // its terms <= 2 B each) 2^-17.8 B, the margins toward and away 2^-20.4 B.
  // 2^-14 (|L|_1 + 4 |w| R) is a margin of over 10 on that, and costs only
  // visits of nodes within 2^-14 of grazing the light.
  const double bound = std::abs(local[0]) + std::abs(local[1]) + std::abs(local[2]) +
    std::abs(local[3]) * 4.0 * this->Radius;
  return RoundUp(std::ldexp(bound, -14) + exact + 1e-30);
}

//------------------------------------------------------------------------------
template <typename Lane>
auto NormalConeTree::OneSided(const Node& node, const float light[4], float tolerance, Lane lane)
{
  // g_f = n_f . V - w e_f with V = L - w c and n_f = a + alpha u + beta s +
  // rest: n_f . V lies within ru |u . V| + rs |s . V| + rr |V|_1 of a . V
  // (|V| <= |V|_1, looser only in the small residual's term), and w e_f
  // within w times the offsets' range. All faces are on one side when the
  // gap m between a . V - w e and zero exceeds that spread, with m the
  // larger of the margins toward each side.
  const auto vx = light[0] - light[3] * lane(node.CenterX);
  const auto vy = light[1] - light[3] * lane(node.CenterY);
  const auto vz = light[2] - light[3] * lane(node.CenterZ);
  const auto av = lane(node.AxisX) * vx + lane(node.AxisY) * vy + lane(node.AxisZ) * vz;
  const auto uv = lane(node.UX) * vx + lane(node.UY) * vy + lane(node.UZ) * vz;
  const auto sv = lane(node.SX) * vx + lane(node.SY) * vy + lane(node.SZ) * vz;
  const auto spread = lane(node.RadiusU) * Abs(uv) + lane(node.RadiusS) * Abs(sv) +
    lane(node.Residual) * (Abs(vx) + Abs(vy) + Abs(vz));
  const auto e0 = light[3] * lane(node.OffsetMin);
  const auto e1 = light[3] * lane(node.OffsetMax);
  const auto toward = av - Max(e0, e1) - tolerance; // g_f > 0 for all when > spread
  const auto away = Min(e0, e1) - av - tolerance;   // g_f < 0 for all when > spread
  return Max(toward, away) > spread;
}

//------------------------------------------------------------------------------
// Inline: called once a node visited, from this file only.
inline unsigned NormalConeTree::VisitMask(const Node& node, const float light[4], float tolerance)
{
#if defined(__GNUC__) || defined(__clang__)
  // All four children at once, lane by lane.
  const Int4 oneSided =
    OneSided(node, light, tolerance, [](const float(&lanes)[4]) { return Load4(lanes); });
  const Int4 visit = ~oneSided & (Load4(node.Child) != Int4{ Empty, Empty, Empty, Empty });
  return Bits(visit);
#else
  unsigned mask = 0;
  for (int k = 0; k < 4; ++k)
  {
    const bool oneSided =
      OneSided(node, light, tolerance, [k](const float(&lanes)[4]) { return lanes[k]; });
    mask |= static_cast<unsigned>(!oneSided && node.Child[k] != Empty) << k;
  }
  return mask;
#endif
}

//------------------------------------------------------------------------------
vtkIdType NormalConeTree::Query(
  const double light[4], QueryBuffers& buffers, std::vector<std::int32_t>& silhouette) const
{
  if (this->Nodes.empty())
  {
    return 0;
  }
  // The light relative to the origin, as the float bounds and planes are:
  // n . L - w d = n . (L - w origin) - w (d - n . origin).
  const double local[4] = { light[0] - light[3] * this->Origin[0],
    light[1] - light[3] * this->Origin[1], light[2] - light[3] * this->Origin[2], light[3] };
  const float lightF[4] = { static_cast<float>(local[0]), static_cast<float>(local[1]),
    static_cast<float>(local[2]), static_cast<float>(local[3]) };

  // The exact test, FacesLight() in double with the input's own planes and
  // light, errs by a few units of double round-off (2^-53) of |L|_1 + |w|
  // max |d|; the local light, the local planes and the bounds' offsets carry
  // as much again from subtracting the origin: under 16 units of |L|_1 + |w|
  // (max |d| + |origin|_1) all told. Far from (0, 0, 0) that can exceed the
  // float round-off of a small mesh, so every float decision keeps 2^-44 of
  // it, 32 times as much, as a further margin.
  const double exact = std::ldexp(std::abs(light[0]) + std::abs(light[1]) + std::abs(light[2]) +
      std::abs(light[3]) *
        (this->MaxOffset + std::abs(this->Origin[0]) + std::abs(this->Origin[1]) +
          std::abs(this->Origin[2])),
    -44);
  const float tolerance = this->Tolerance(local, exact);

  // Which side of the light a face is on: in float, and again in double, as
  // the brute-force search does, only where the float result is within its
  // error bound of zero. Each float product and sum errs by at most 2^-24
  // times the sum of the terms' magnitudes (and rounding n, d and L to float
  // by as much again): 7 such errors at most; 16 leaves a margin. Both
  // searches therefore take the same decision for every face.
  const float bound = RoundUp(16.0 * std::ldexp(1.0, -24) *
      (std::abs(local[0]) + std::abs(local[1]) + std::abs(local[2]) +
        std::abs(local[3]) * this->MaxLocalOffset) +
    exact + 1e-30);
  const Node* nodes = this->Nodes.data();
  const Block* blocks = this->LeafBlocks.data();
  const std::int32_t* leafFaces = this->LeafFaces.data();
  const double* exactPlanes = this->Planes.data();
  const std::int32_t* edgeOutputs = this->EdgeOutputs.data();

  // A leaf's silhouette edges, as their index in tree order times two, plus
  // one when the edge's first face faces the light.
  auto testLeaf = [&](std::int32_t first, std::vector<std::int32_t>& found) -> vtkIdType
  {
    LeafHeader header;
    std::memcpy(&header, blocks[first].Values, sizeof(header));
    const float* planes = blocks[first + 1].Values;
    const std::int32_t groups = (header.NumFaces + 3) / 4;
    // One bit a face: toward the light, and too close to call in float.
    std::uint64_t front = 0, unsure = 0;
    for (std::int32_t group = 0; group < groups; ++group)
    {
      const float* p = planes + 16 * group;
#if defined(__GNUC__) || defined(__clang__)
      const Float4 g = Load4(p) * lightF[0] + Load4(p + 4) * lightF[1] + Load4(p + 8) * lightF[2] -
        lightF[3] * Load4(p + 12);
      front |= static_cast<std::uint64_t>(Bits(g > bound)) << (4 * group);
      unsure |= static_cast<std::uint64_t>(Bits(~(Abs(g) > bound))) << (4 * group);
#else
      for (int k = 0; k < 4; ++k)
      {
        const float g =
          p[k] * lightF[0] + p[4 + k] * lightF[1] + p[8 + k] * lightF[2] - lightF[3] * p[12 + k];
        front |= static_cast<std::uint64_t>(g > bound) << (4 * group + k);
        unsure |= static_cast<std::uint64_t>(!(std::abs(g) > bound)) << (4 * group + k);
      }
#endif
    }
    // Faces past the last (zero planes in the last group) are no faces.
    const std::uint64_t faces =
      header.NumFaces == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << header.NumFaces) - 1;
    unsure &= faces;
    while (unsure)
    {
      const int k = LowestBit(unsure);
      unsure &= unsure - 1;
      const double* exact =
        exactPlanes + 4 * static_cast<vtkIdType>(leafFaces[header.FaceBase + k]);
      front |= static_cast<std::uint64_t>(FacesLight(exact, exact[3], light)) << k;
    }
    // All faces on one side (a fifth of the leaves the bounds let through):
    // no edge to look at.
    if ((front & faces) == 0 || (front & faces) == faces)
    {
      return header.NumEdges;
    }
    const std::uint8_t* pairs = reinterpret_cast<const std::uint8_t*>(planes + 16 * groups);
    // Without branches: near the silhouette whether an edge is on it is a
    // coin toss, which a branch predictor cannot learn. Every edge is written
    // and only the silhouette ones are kept.
    const std::size_t count = found.size();
    found.resize(count + header.NumEdges);
    std::int32_t* out = found.data() + count;
    for (std::int32_t i = 0; i < header.NumEdges; ++i)
    {
      const std::uint64_t toward = (front >> pairs[2 * i]) & 1;
      const std::uint64_t away = ~(front >> pairs[2 * i + 1]) & 1;
      *out = 2 * (header.EdgeBegin + i) + static_cast<std::int32_t>(toward);
      out += toward ^ away ^ 1;
    }
    found.resize(out - found.data());
    // Their ids and points, for later.
    const std::int32_t* outputs = edgeOutputs + 3 * static_cast<vtkIdType>(header.EdgeBegin);
    for (std::int32_t value = 0; value < 3 * header.NumEdges; value += 16)
    {
      Prefetch(outputs + value);
    }
    return header.NumEdges;
  };
  auto prefetchLeaf = [blocks](std::int32_t first)
  {
    // A leaf of n edges has about n faces: the header, 16 n bytes of planes
    // and 2 n of edges.
    constexpr int lines = (16 + 18 * LeafSize + 63) / 64;
    for (int line = 0; line < lines; ++line)
    {
      Prefetch(blocks + first + 4 * line);
    }
  };
  auto prefetchNode = [nodes](std::int32_t index)
  {
    const char* bytes = reinterpret_cast<const char*>(nodes + index);
    for (std::size_t offset = 0; offset < sizeof(Node); offset += 64)
    {
      Prefetch(bytes + offset);
    }
    Prefetch(bytes + sizeof(Node) - 1);
  };

  // Walks what lies under one entry (a node, or -1 - a leaf's first block)
  // level by level, listing the leaves reached in tree order. Each level asks
  // for all the nodes of the next to be fetched before it looks at any, so
  // that many fetches are in flight instead of one at a time.
  using Walk = QueryBuffers::Walk;
  auto walk = [&](std::int32_t entry, Walk& lists)
  {
    std::vector<std::int32_t>& level = lists.Level;
    std::vector<std::int32_t>& next = lists.Next;
    level.clear();
    lists.Leaves.clear();
    (entry >= 0 ? level : lists.Leaves).push_back(entry >= 0 ? entry : -1 - entry);
    while (!level.empty())
    {
      next.clear();
      for (std::int32_t index : level)
      {
        const Node& node = nodes[index];
        for (unsigned mask = VisitMask(node, lightF, tolerance); mask; mask &= mask - 1)
        {
          const std::int32_t child = node.Child[LowestBit(mask)];
          if (child >= 0)
          {
            prefetchNode(child);
            next.push_back(child);
          }
          else
          {
            lists.Leaves.push_back(-1 - child);
          }
        }
      }
      level.swap(next);
    }
  };

  // Tests a run of reached leaves, fetching a few ahead, then writes the
  // silhouette edges found.
  using Share = QueryBuffers::Share;
  auto test = [&](const std::int32_t* leaves, std::size_t count, Share& share)
  {
    constexpr std::size_t ahead = 8;
    for (std::size_t i = 0; i < std::min(ahead, count); ++i)
    {
      prefetchLeaf(leaves[i]);
    }
    share.Tested = 0;
    share.Found.clear();
    share.Out.clear();
    for (std::size_t i = 0; i < count; ++i)
    {
      if (i + ahead < count)
      {
        prefetchLeaf(leaves[i + ahead]);
      }
      share.Tested += testLeaf(leaves[i], share.Found);
    }
    for (std::int32_t code : share.Found)
    {
      const std::int32_t* edge = edgeOutputs + 3 * static_cast<vtkIdType>(code >> 1);
      const bool toward = (code & 1) != 0;
      share.Out.push_back(edge[0]);
      share.Out.push_back(edge[toward ? 1 : 2]);
      share.Out.push_back(edge[toward ? 2 : 1]);
    }
  };

  std::vector<Walk>& walks = buffers.Walks;
  std::vector<Share>& shares = buffers.Shares;
  if (this->GetNumberOfEdges() < SerialBelowEdges)
  {
    walks.resize(std::max<std::size_t>(walks.size(), 1));
    shares.resize(std::max<std::size_t>(shares.size(), 1));
    walk(0, walks[0]);
    test(walks[0].Leaves.data(), walks[0].Leaves.size(), shares[0]);
    silhouette.insert(silhouette.end(), shares[0].Out.begin(), shares[0].Out.end());
    return shares[0].Tested;
  }

  // The top of the tree, breadth first, until there are enough subtrees and
  // leaves to share among threads; then each subtree's walk.
  std::vector<std::int32_t>& queue = buffers.Queue;
  std::vector<std::int32_t>& frontier = buffers.Frontier;
  queue.assign(1, 0);
  frontier.clear();
  std::size_t head = 0;
  while (head < queue.size() && queue.size() - head + frontier.size() < ParallelFrontier)
  {
    const Node& node = nodes[queue[head++]];
    for (unsigned mask = VisitMask(node, lightF, tolerance); mask; mask &= mask - 1)
    {
      const std::int32_t child = node.Child[LowestBit(mask)];
      (child >= 0 ? queue : frontier).push_back(child);
    }
  }
  frontier.insert(frontier.end(), queue.begin() + head, queue.end());
  const std::size_t numWalks = frontier.size();
  walks.resize(std::max(walks.size(), numWalks));
  vtkSMPTools::For(0, static_cast<vtkIdType>(numWalks), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        walk(frontier[i], walks[i]);
      }
    });

  // The leaves reached, in frontier order, shared among threads in equal
  // runs: subtrees reach very different numbers of leaves (one may hold a
  // third of the silhouette), runs of leaves cost about the same.
  std::vector<std::int32_t>& reached = buffers.Reached;
  reached.clear();
  for (std::size_t i = 0; i < numWalks; ++i)
  {
    reached.insert(reached.end(), walks[i].Leaves.begin(), walks[i].Leaves.end());
  }
  const std::size_t numShares = std::min<std::size_t>(
    SharesPerThread * static_cast<std::size_t>(vtkSMPTools::GetEstimatedNumberOfThreads()),
    reached.size() / MinimumShare + 1);
  shares.resize(std::max(shares.size(), numShares));
  vtkSMPTools::For(0, static_cast<vtkIdType>(numShares), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const std::size_t first = reached.size() * i / numShares;
        const std::size_t last = reached.size() * (i + 1) / numShares;
        test(reached.data() + first, last - first, shares[i]);
      }
    });

  // Joined in order: the output does not depend on how threads share the work.
  vtkIdType tested = 0;
  for (std::size_t i = 0; i < numShares; ++i)
  {
    tested += shares[i].Tested;
    silhouette.insert(silhouette.end(), shares[i].Out.begin(), shares[i].Out.end());
  }
  return tested;
}
}
