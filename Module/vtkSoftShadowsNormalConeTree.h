// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSoftShadowsNormalConeTree.h
 * @brief  Private: a hierarchy of normal cones over edges, for silhouette searches.
 *
 * Smoothies need the silhouette edges of a static mesh every time the light
 * moves (Volokh, sections 2.2 and 5.1: the brute-force test of every edge is
 * the bottleneck). This tree groups the edges that have two consistently
 * oriented faces by position and normal; each node bounds, for all faces of
 * its edges, the quantity the silhouette test takes the sign of,
 *
 *   g_f(L) = n_f . L - w d_f     (light L, w = 1 positional, 0 directional;
 *                                  d_f = n_f . p, p a corner of the face),
 *
 * by writing it as n_f . (L - w c) - w (d_f - n_f . c) for the node's centre
 * c. The first term is bounded by a box around the node's normals: with its
 * centre a and two directions u, s across the mean normal (u along the
 * normals' widest spread), every n_f = a + alpha u + beta s + rest with
 * |alpha| <= ru, |beta| <= rs and a small |rest| <= rr, so n_f . V lies
 * within ru |u . V| + rs |s . V| + rr |V| of a . V (V = L - w c). Normals of
 * a patch spread unevenly (a tube's turn faster around it than along it):
 * on meshbench's knot a ball holding them (the chord form of a normal cone)
 * reached 1.77 leaves for each leaf with a silhouette edge, the box 1.26
 * (leaves of 8 to 16 edges). The second term lies within the range of
 * e_f = d_f - n_f . c over the node's faces. When the bounds prove every
 * face of a node toward the light (g > 0) or every face away (g <= 0), none
 * of its edges is a silhouette edge and the node is skipped. Otherwise its
 * children (or, in a leaf, its edges, with the exact test) are visited.
 *
 * The bounds are tested in float with a margin that covers float round-off
 * many times over (see Tolerance()). The leaves decide each face in float,
 * from a copy of its plane stored with the leaf, and fall back to
 * FacesLight() in double, as the brute-force search tests every face,
 * wherever float round-off could change the sign: both searches return the
 * same edges, bit for bit.
 *
 * Made for memory and few instructions, which bound the search: a node holds
 * its four children's bounds side by side, so that one fetch decides all four
 * with the same arithmetic, in one SIMD register lane by lane; a leaf's face
 * planes (four by four, tested four at once) and its edges' faces lie
 * together, where one run of fetches brings them; the walk goes a level at a
 * time, asking for every node of the next level before looking at any; the
 * leaves reached are then tested in equal shares among threads, fetched a few
 * ahead; and ids and points are read only for the silhouette edges found,
 * after all leaves are tested.
 *
 * Not installed, not wrapped.
 */

#ifndef vtkSoftShadowsNormalConeTree_h
#define vtkSoftShadowsNormalConeTree_h

#include "vtkSoftShadowsLargeBuffers.h" // for RawVector
#include "vtkType.h"

#include <cstdint> // for std::int32_t, INT32_MIN
#include <vector>  // for std::vector

namespace vtksoftshadows
{
/**
 * Does the face with unit normal n and plane offset d face the light
 * (x, y, z, w)? The one test both silhouette searches use: g > 0 exactly.
 */
inline bool FacesLight(const double* n, double d, const double light[4])
{
  return n[0] * light[0] + n[1] * light[1] + n[2] * light[2] - light[3] * d > 0.0;
}

class NormalConeTree
{
public:
  /// An edge with two consistently oriented faces, the first running it as the
  /// edge table does; a silhouette edge when exactly one of them faces the light.
  struct Edge
  {
    std::int32_t Id;
    std::int32_t Faces[2];
    std::int32_t Points[2]; // as the first face runs the edge
  };

  /**
   * Builds the tree over `edges`, given every face's unit normal (3 a face)
   * and plane offset, and each edge's midpoint (3 an edge, in the order of
   * `edges`); `origin` and `radius` are a ball holding every point of the
   * mesh. The tree keeps its own copy of the planes of the faces it uses,
   * and its float bounds and planes relative to `origin`: their round-off
   * then follows the mesh's size, not its distance from (0, 0, 0).
   */
  void Build(const RawVector<Edge>& edges, const RawVector<double>& midpoints,
    const double* normals, const double* offsets, const double origin[3], double radius);

  /**
   * Lists a query fills, kept by the caller from one query to the next: fresh
   * memory is slow to touch (on some virtual machines ~10 us a page, more
   * than a whole query's arithmetic), reused memory is not.
   */
  struct QueryBuffers
  {
    struct Walk // a subtree's walk: its levels, the leaves it reaches
    {
      std::vector<std::int32_t> Level, Next, Leaves;
    };
    struct Share // a thread's share of the leaves: what it finds
    {
      std::vector<std::int32_t> Found, Out;
      vtkIdType Tested = 0;
    };
    std::vector<Walk> Walks;
    std::vector<Share> Shares;
    std::vector<std::int32_t> Queue, Frontier, Reached;
  };

  /**
   * Appends the silhouette edges among the tree's edges for the light
   * (x, y, z, w) to `silhouette`, each as its id and its two points, ordered
   * so that the faces lie to the left seen from the light (first point first
   * when the edge's first face faces the light). The order is the tree's,
   * whatever the number of threads. Returns how many edges were tested
   * exactly. Multi-threaded with vtkSMPTools.
   */
  vtkIdType Query(
    const double light[4], QueryBuffers& buffers, std::vector<std::int32_t>& silhouette) const;

  vtkIdType GetNumberOfNodes() const { return static_cast<vtkIdType>(this->Nodes.size()); }
  vtkIdType GetNumberOfEdges() const { return this->NumberOfEdges; }

  /**
   * Margin that covers float round-off of the nodes' bounds for the light
   * `local` (relative to the origin), plus `exact`, the bound on the exact
   * test's own round-off (see the .cxx).
   */
  float Tolerance(const double local[4], double exact) const;

private:
  /// Sentinel of an unused child.
  static constexpr std::int32_t Empty = INT32_MIN;

  // Four children's bounds, lane by lane (288 bytes). Rounded outward from
  // double (radii and offset maximum up, offset minimum down), so that the
  // bounds stay conservative.
  struct Node
  {
    float AxisX[4], AxisY[4], AxisZ[4]; // a: the centre of the child's normals' box
    float UX[4], UY[4], UZ[4];          // u: the normals' widest spread, about unit
    float SX[4], SY[4], SZ[4];          // s: across a and u, about unit
    // n_f = a + alpha u + beta s + rest, |alpha| <= RadiusU, |beta| <= RadiusS,
    // |rest| <= Residual, for all the child's faces.
    float RadiusU[4], RadiusS[4], Residual[4];
    float CenterX[4], CenterY[4], CenterZ[4];
    float OffsetMin[4]; // range of e_f = d_f - n_f . c over the child's faces
    float OffsetMax[4];
    std::int32_t Child[4]; // >= 0 a node; -1 - its first block for a leaf; or Empty
  };

  // A leaf is a run of blocks in LeafBlocks: a LeafHeader, its faces' float
  // planes four at a time (n.x of four faces, n.y, n.z, d), then two bytes an
  // edge, its faces among the leaf's.
  struct Block
  {
    float Values[4];
  };
  struct LeafHeader
  {
    std::int32_t EdgeBegin; // its edges in tree order, into EdgeOutputs
    std::int32_t FaceBase;  // its faces' ids, into LeafFaces
    std::int32_t NumEdges;
    std::int32_t NumFaces;
  };

  // Bits, one a child, of the children not proven one-sided.
  static unsigned VisitMask(const Node& node, const float light[4], float tolerance);
  // Whether each child (each lane `lane` reads) is proven one-sided.
  template <typename Lane>
  static auto OneSided(const Node& node, const float light[4], float tolerance, Lane lane);
  std::int32_t AppendLeaf(const std::int32_t* order, std::int32_t begin, std::int32_t end,
    const RawVector<Edge>& edges, const RawVector<double>& localOffsets,
    RawVector<std::int32_t>& local);
  struct Builder;
  struct BinaryNode;

  RawVector<Node> Nodes;                // Nodes[0] is the root
  RawVector<Block> LeafBlocks;          // all leaves, in tree order
  RawVector<std::int32_t> LeafFaces;    // a leaf's faces, into Planes
  RawVector<std::int32_t> EdgeOutputs;  // 3 an edge: id, points as its first face runs it
  RawVector<double> Planes;             // n.x n.y n.z d a face, exact
  double Origin[3] = { 0.0, 0.0, 0.0 }; // the float bounds and planes are relative to it
  double Radius = 0.0;                  // |p - Origin| <= Radius for every point p
  double MaxOffset = 0.0;               // largest |d| over the faces
  double MaxLocalOffset = 0.0;          // largest |d - n . Origin| over the faces
  vtkIdType NumberOfEdges = 0;
};
}

#endif
// VTK-HeaderTest-Exclude: vtkSoftShadowsNormalConeTree.h
