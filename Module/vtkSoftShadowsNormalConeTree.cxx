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
  this->Edges.clear();
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

  // Edges in tree order, and the planes of their faces numbered in the order
  // the edges first meet them: a leaf's faces are neighbours in memory.
  std::int32_t maxFace = 0;
  for (const Edge& edge : edges)
  {
    maxFace = std::max({ maxFace, edge.Faces[0], edge.Faces[1] });
  }
  RawVector<std::int32_t> local(static_cast<std::size_t>(maxFace) + 1);
  std::fill(local.begin(), local.end(), -1);
  this->Edges.resize(numEdges);
  this->Planes.reserve(4 * (static_cast<std::size_t>(maxFace) + 1));
  for (vtkIdType i = 0; i < numEdges; ++i)
  {
    Edge edge = edges[builder.Order[i]];
    for (std::int32_t& f : edge.Faces)
    {
      if (local[f] < 0)
      {
        local[f] = static_cast<std::int32_t>(this->Planes.size() / 4);
        const double* n = normals + 3 * static_cast<vtkIdType>(f);
        this->Planes.insert(this->Planes.end(), { n[0], n[1], n[2], offsets[f] });
      }
      f = local[f];
    }
    this->Edges[i] = edge;
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
  const double* planes = this->Planes.data();

  // Visits the subtree under `root`, testing the edges of the leaves it reaches.
  auto visit = [&](std::int32_t root, std::vector<std::int32_t>& out,
                 std::vector<std::int32_t>& stack) -> vtkIdType
  {
    vtkIdType tested = 0;
    stack.clear();
    stack.push_back(root);
    while (!stack.empty())
    {
      const std::int32_t index = stack.back();
      stack.pop_back();
      const Node& node = this->Nodes[index];
      if (OneSided(node, light, tolerance))
      {
        continue;
      }
      if (node.Right >= 0)
      {
        // The walk waits on memory, not arithmetic: fetch the right child
        // while the left one (next in memory) is looked at.
        __builtin_prefetch(this->Nodes.data() + node.Right);
        stack.push_back(node.Right);
        stack.push_back(index + 1);
        continue;
      }
      for (std::int32_t i = node.Begin; i < node.End; ++i)
      {
        const Edge& edge = this->Edges[i];
        const double* p0 = planes + 4 * static_cast<vtkIdType>(edge.Faces[0]);
        const double* p1 = planes + 4 * static_cast<vtkIdType>(edge.Faces[1]);
        const bool front = FacesLight(p0, p0[3], light);
        if (front != FacesLight(p1, p1[3], light))
        {
          out.push_back(edge.Id);
          out.push_back(edge.Points[front ? 0 : 1]);
          out.push_back(edge.Points[front ? 1 : 0]);
        }
      }
      tested += node.End - node.Begin;
    }
    return tested;
  };

  std::vector<std::int32_t> stack;
  if (this->GetNumberOfEdges() < SerialBelowEdges)
  {
    return visit(0, silhouette, stack);
  }

  // The top of the tree, breadth first, until there are enough subtrees to
  // share among threads; then each subtree depth first.
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
  vtkSMPThreadLocal<std::vector<std::int32_t>> stacks;
  vtkSMPTools::For(0, static_cast<vtkIdType>(frontier.size()), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<std::int32_t>& localStack = stacks.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        tested[i] = visit(frontier[i], found[i], localStack);
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
