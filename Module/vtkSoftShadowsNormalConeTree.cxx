#include "vtkSoftShadowsNormalConeTree.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <glm/geometric.hpp> // for glm::dot, glm::cross, glm::length
#include <glm/vec3.hpp>      // for glm::dvec3

#include <algorithm>  // for std::nth_element, std::min, std::max
#include <cmath>      // for std::abs, std::sqrt
#include <functional> // for std::function

namespace vtksoftshadows
{
namespace
{
// Leaves of 8 to 16 edges: testing a leaf's edges (contiguous in memory) costs
// less than one more level of nodes (a cache miss each).
constexpr std::int32_t LeafSize = 16;
static_assert(2 * LeafSize <= 256, "a leaf's faces are numbered in a byte");
// The top levels of the tree are split serially, into up to 2^SerialDepth
// subtrees that are then built in parallel.
constexpr int SerialDepth = 5;
// A query shares its work among threads below this many nodes from the root,
// and only for trees of this many edges or more.
constexpr std::size_t ParallelFrontier = 64;
constexpr vtkIdType SerialBelowEdges = vtkIdType(1) << 14;

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
}

//------------------------------------------------------------------------------
struct NormalConeTree::Builder
{
  const RawVector<Edge>& Edges;
  const RawVector<double>& Midpoints;
  const double* Normals;
  const double* Offsets;
  RawVector<std::int32_t> Order; // the tree's edge order, into Edges
  RawVector<float> Keys;         // 6 an edge: scaled midpoint, mean normal (only to split)

  // The node's cone, centre and offset range, from all faces of its edges.
  void Bound(Node& node) const
  {
    glm::dvec3 sum(0.0), center(0.0);
    for (std::int32_t i = node.Begin; i < node.End; ++i)
    {
      const Edge& edge = this->Edges[this->Order[i]];
      sum += Vec(this->Normals + 3 * static_cast<vtkIdType>(edge.Faces[0]));
      sum += Vec(this->Normals + 3 * static_cast<vtkIdType>(edge.Faces[1]));
      center += Vec(this->Midpoints.data() + 3 * static_cast<vtkIdType>(this->Order[i]));
    }
    const double length = glm::length(sum);
    const glm::dvec3 axis = length > 0.0 ? sum / length : glm::dvec3(0.0, 0.0, 1.0);
    center /= static_cast<double>(node.End - node.Begin);
    // The centre is any point: take one a float holds exactly.
    for (int c = 0; c < 3; ++c)
    {
      node.Center[c] = static_cast<float>(center[c]);
      center[c] = node.Center[c];
    }
    double cosMin = 1.0, sinMax = 0.0;
    double offsetMin = VTK_DOUBLE_MAX, offsetMax = -VTK_DOUBLE_MAX;
    for (std::int32_t i = node.Begin; i < node.End; ++i)
    {
      const Edge& edge = this->Edges[this->Order[i]];
      for (std::int32_t f : edge.Faces)
      {
        const glm::dvec3 n = Vec(this->Normals + 3 * static_cast<vtkIdType>(f));
        cosMin = std::min(cosMin, glm::dot(axis, n));
        sinMax = std::max(sinMax, glm::length(glm::cross(axis, n)));
        const double e = this->Offsets[f] - glm::dot(n, center);
        offsetMin = std::min(offsetMin, e);
        offsetMax = std::max(offsetMax, e);
      }
    }
    for (int c = 0; c < 3; ++c)
    {
      node.Axis[c] = axis[c];
    }
    node.Cos = RoundDown(cosMin);
    node.Sin = RoundUp(std::min(1.0, sinMax));
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
  std::int32_t BuildSubtree(std::int32_t begin, std::int32_t end, std::vector<Node>& nodes)
  {
    const std::int32_t index = static_cast<std::int32_t>(nodes.size());
    nodes.emplace_back();
    Node node;
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
  const double* normals, const double* offsets)
{
  this->Nodes.clear();
  this->LeafPlanes.clear();
  this->LeafFaces.clear();
  this->EdgeFaces.clear();
  this->EdgeOutputs.clear();
  this->Planes.clear();
  const vtkIdType numEdges = static_cast<vtkIdType>(edges.size());
  if (numEdges == 0)
  {
    return;
  }
  Builder builder{ edges, midpoints, normals, offsets, {}, {} };
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
    Node Data;
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
  std::vector<std::vector<Node>> subtrees(ranges.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(ranges.size()), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType r = begin; r < end; ++r)
      {
        builder.BuildSubtree(ranges[r].first, ranges[r].second, subtrees[r]);
      }
    });

  // Assembly, depth first: a node, its left child's nodes, its right child's.
  this->Nodes.reserve(2 * (numEdges / LeafSize + 1));
  auto appendSubtree = [this, &subtrees](int r)
  {
    const std::int32_t base = static_cast<std::int32_t>(this->Nodes.size());
    for (Node node : subtrees[r])
    {
      node.Right = node.Right >= 0 ? node.Right + base : -1;
      this->Nodes.push_back(node);
    }
    std::vector<Node>().swap(subtrees[r]);
  };
  std::function<void(int)> append = [&](int top)
  {
    const std::int32_t index = static_cast<std::int32_t>(this->Nodes.size());
    this->Nodes.push_back(tops[top].Data);
    if (tops[top].Left >= 0)
    {
      append(tops[top].Left);
    }
    else
    {
      appendSubtree(tops[top].LeftSub);
    }
    this->Nodes[index].Right = static_cast<std::int32_t>(this->Nodes.size());
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

  // What the leaves read, leaf by leaf in tree order: for each edge two
  // bytes, its faces among its leaf's; for each leaf the float planes of its
  // faces, together in memory; the exact planes only for the rare faces the
  // float test cannot decide, and ids and points only for silhouette edges.
  std::int32_t maxFace = 0;
  for (const Edge& edge : edges)
  {
    maxFace = std::max({ maxFace, edge.Faces[0], edge.Faces[1] });
  }
  const std::size_t numFaces = static_cast<std::size_t>(maxFace) + 1;
  this->Planes.resize(4 * numFaces);
  this->MaxOffset = 0.0;
  for (std::size_t f = 0; f < numFaces; ++f)
  {
    std::copy_n(normals + 3 * f, 3, this->Planes.data() + 4 * f);
    this->Planes[4 * f + 3] = offsets[f];
    this->MaxOffset = std::max(this->MaxOffset, std::abs(offsets[f]));
  }
  this->EdgeFaces.resize(2 * numEdges);
  this->EdgeOutputs.resize(3 * numEdges);
  this->LeafPlanes.clear();
  this->LeafFaces.clear();
  RawVector<std::int32_t> local(numFaces);
  std::fill(local.begin(), local.end(), -1);
  for (Node& node : this->Nodes)
  {
    if (node.Right >= 0)
    {
      continue;
    }
    const std::int32_t first = static_cast<std::int32_t>(this->LeafFaces.size());
    node.Right = -1 - first;
    for (std::int32_t i = node.Begin; i < node.End; ++i)
    {
      const Edge& edge = edges[builder.Order[i]];
      for (int k = 0; k < 2; ++k)
      {
        const std::int32_t f = edge.Faces[k];
        if (local[f] < 0)
        {
          local[f] = static_cast<std::int32_t>(this->LeafFaces.size()) - first;
          this->LeafFaces.push_back(f);
          for (int c = 0; c < 4; ++c)
          {
            this->LeafPlanes.push_back(static_cast<float>(this->Planes[4 * f + c]));
          }
        }
        this->EdgeFaces[2 * i + k] = static_cast<std::uint8_t>(local[f]);
      }
      this->EdgeOutputs[3 * i] = edge.Id;
      this->EdgeOutputs[3 * i + 1] = edge.Points[0];
      this->EdgeOutputs[3 * i + 2] = edge.Points[1];
    }
    for (std::size_t j = static_cast<std::size_t>(first); j < this->LeafFaces.size(); ++j)
    {
      local[this->LeafFaces[j]] = -1;
    }
  }
}

//------------------------------------------------------------------------------
double NormalConeTree::Tolerance(const double light[4], double scale)
{
  // Every term of the bounds is computed with a relative error of a few
  // units of round-off (1e-16) of |L| + |w| scale; 1e-10 is a margin of about
  // a million over that, and costs only visits of nodes within 1e-10 of
  // grazing the light.
  const double l = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
  return 1e-10 * (l + std::abs(light[3]) * 2.0 * scale);
}

//------------------------------------------------------------------------------
bool NormalConeTree::OneSided(const Node& node, const double light[4], double tolerance)
{
  // g_f = n_f . V - w e_f with V = L - w c and e_f = d_f - n_f . c.
  const double w = light[3];
  const glm::dvec3 v(
    light[0] - w * node.Center[0], light[1] - w * node.Center[1], light[2] - w * node.Center[2]);
  const glm::dvec3 axis = Vec(node.Axis);
  const double av = glm::dot(axis, v);                // |V| cos(phi)
  const double sv = glm::length(glm::cross(axis, v)); // |V| sin(phi), accurate for small phi
  const double vv = glm::length(v);
  // n . V over the cone: |V| cos(phi + t) at least (or -|V| once phi + t >= pi),
  // |V| cos(phi - t) at most (or |V| once phi <= t). An overestimated sin(t)
  // only widens both bounds.
  const double lower = av <= -vv * node.Cos ? -vv : av * node.Cos - sv * node.Sin;
  const double upper = av >= vv * node.Cos ? vv : av * node.Cos + sv * node.Sin;
  const double gMin = lower - (w > 0.0 ? w * node.OffsetMax : w * node.OffsetMin);
  const double gMax = upper - (w > 0.0 ? w * node.OffsetMin : w * node.OffsetMax);
  return gMin > tolerance || gMax < -tolerance;
}

//------------------------------------------------------------------------------
vtkIdType NormalConeTree::Query(
  const double light[4], double scale, std::vector<std::int32_t>& silhouette) const
{
  if (this->Nodes.empty())
  {
    return 0;
  }
  const double tolerance = Tolerance(light, scale);

  // Which side of the light a face is on: in float, and again in double, as
  // the brute-force search does, only where the float result is within its
  // round-off bound of zero. Each float product and sum errs by at most 2^-24
  // times the sum of the terms' magnitudes (and rounding n, d and L to float
  // by as much again): 7 such errors at most; 16 leaves a margin. Both
  // searches therefore take the same decision for every face.
  const float lightF[4] = { static_cast<float>(light[0]), static_cast<float>(light[1]),
    static_cast<float>(light[2]), static_cast<float>(light[3]) };
  const float bound = static_cast<float>(16.0 * std::ldexp(1.0, -24) *
      (std::abs(light[0]) + std::abs(light[1]) + std::abs(light[2]) +
        std::abs(light[3]) * this->MaxOffset) +
    1e-30);
  const double* exactPlanes = this->Planes.data();
  const std::int32_t* leafFaces = this->LeafFaces.data();
  auto front = [&](const float* p, std::int32_t entry)
  {
    const float g = p[0] * lightF[0] + p[1] * lightF[1] + p[2] * lightF[2] - lightF[3] * p[3];
    if (std::abs(g) > bound)
    {
      return g > 0.0f;
    }
    const double* exact = exactPlanes + 4 * static_cast<vtkIdType>(leafFaces[entry]);
    return FacesLight(exact, exact[3], light);
  };

  // Visits the subtree under `root` level by level, then tests the edges of
  // the leaves reached. The walk is bound by memory latency: each level asks
  // for all the nodes of the next (and the data of every leaf reached) to be
  // fetched before it looks at any, so that many fetches are in flight
  // instead of one at a time.
  const float* leafPlanes = this->LeafPlanes.data();
  const std::uint8_t* edgeFaces = this->EdgeFaces.data();
  const std::int32_t* edgeOutputs = this->EdgeOutputs.data();
  const Node* nodes = this->Nodes.data();
  struct Lists
  {
    std::vector<std::int32_t> Level, Next, Leaves;
  };
  auto visit = [&](std::int32_t root, std::vector<std::int32_t>& out, Lists& lists) -> vtkIdType
  {
    std::vector<std::int32_t>& level = lists.Level;
    std::vector<std::int32_t>& next = lists.Next;
    std::vector<std::int32_t>& reached = lists.Leaves;
    level.assign(1, root);
    reached.clear();
    while (!level.empty())
    {
      next.clear();
      for (std::int32_t index : level)
      {
        const Node& node = nodes[index];
        if (OneSided(node, light, tolerance))
        {
          continue;
        }
        if (node.Right >= 0)
        {
          __builtin_prefetch(nodes + index + 1);
          __builtin_prefetch(nodes + node.Right);
          next.push_back(index + 1);
          next.push_back(node.Right);
          continue;
        }
        // A leaf of n edges has about n faces (16 bytes each), 2 n bytes of
        // edges and 12 n bytes of outputs.
        const float* planes = leafPlanes + 4 * static_cast<vtkIdType>(-1 - node.Right);
        for (std::int32_t i = 0; i < node.End - node.Begin + 4; i += 4)
        {
          __builtin_prefetch(planes + 4 * i);
        }
        __builtin_prefetch(edgeFaces + 2 * static_cast<vtkIdType>(node.Begin));
        for (std::int32_t i = node.Begin; i < node.End + 5; i += 5)
        {
          __builtin_prefetch(edgeOutputs + 3 * static_cast<vtkIdType>(i));
        }
        reached.push_back(index);
      }
      level.swap(next);
    }
    vtkIdType tested = 0;
    for (std::int32_t leaf : reached)
    {
      const Node& node = nodes[leaf];
      const std::int32_t first = -1 - node.Right;
      const float* planes = leafPlanes + 4 * static_cast<vtkIdType>(first);
      for (std::int32_t i = node.Begin; i < node.End; ++i)
      {
        const std::int32_t f0 = edgeFaces[2 * static_cast<vtkIdType>(i)];
        const std::int32_t f1 = edgeFaces[2 * static_cast<vtkIdType>(i) + 1];
        const bool toward = front(planes + 4 * f0, first + f0);
        if (toward != front(planes + 4 * f1, first + f1))
        {
          const std::int32_t* edge = edgeOutputs + 3 * static_cast<vtkIdType>(i);
          out.push_back(edge[0]);
          out.push_back(edge[toward ? 1 : 2]);
          out.push_back(edge[toward ? 2 : 1]);
        }
      }
      tested += node.End - node.Begin;
    }
    return tested;
  };

  if (this->GetNumberOfEdges() < SerialBelowEdges)
  {
    Lists lists;
    return visit(0, silhouette, lists);
  }

  // The top of the tree, breadth first, until there are enough subtrees to
  // share among threads; then each subtree as above.
  std::vector<std::int32_t> queue{ 0 };
  std::vector<std::int32_t> frontier;
  std::size_t head = 0;
  while (head < queue.size() && queue.size() - head + frontier.size() < ParallelFrontier)
  {
    const std::int32_t index = queue[head++];
    const Node& node = this->Nodes[index];
    if (OneSided(node, light, tolerance))
    {
      continue;
    }
    if (node.Right < 0)
    {
      frontier.push_back(index);
      continue;
    }
    queue.push_back(index + 1);
    queue.push_back(node.Right);
  }
  frontier.insert(frontier.end(), queue.begin() + head, queue.end());

  // One result list a subtree, joined in frontier order: the output order
  // does not depend on how threads share the subtrees.
  std::vector<std::vector<std::int32_t>> found(frontier.size());
  std::vector<vtkIdType> tested(frontier.size(), 0);
  vtkSMPThreadLocal<Lists> lists;
  vtkSMPTools::For(0, static_cast<vtkIdType>(frontier.size()), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      Lists& local = lists.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        tested[i] = visit(frontier[i], found[i], local);
      }
    });
  vtkIdType total = 0;
  for (std::size_t i = 0; i < frontier.size(); ++i)
  {
    total += tested[i];
    silhouette.insert(silhouette.end(), found[i].begin(), found[i].end());
  }
  return total;
}
}
