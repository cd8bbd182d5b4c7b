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
 * c: the first term is bounded by the node's cone of normals (axis a, half
 * angle t) and the angle between a and L - w c, the second by the range of
 * d_f - n_f . c over the node's faces. When the bounds prove every face of a
 * node toward the light (g > 0) or every face away (g <= 0), none of its edges
 * is a silhouette edge and the node is skipped. Otherwise its children (or, in
 * a leaf, its edges, with the exact test) are visited.
 *
 * The bounds are conservative with a margin far above round-off (see
 * Tolerance()). The leaves decide each face in float, from a copy of its
 * plane stored with the leaf, and fall back to FacesLight() in double, as the
 * brute-force search tests every face, wherever float round-off could change
 * the sign: both searches return the same edges, bit for bit.
 *
 * The search is bound by memory latency, not arithmetic: it walks the tree a
 * level at a time, asking for every node of the next level and every leaf's
 * data to be fetched before looking at any, and a leaf reads 16 bytes a face
 * and 2 an edge (ids and points only for silhouette edges).
 *
 * Not installed, not wrapped.
 */

#ifndef vtkSoftShadowsNormalConeTree_h
#define vtkSoftShadowsNormalConeTree_h

#include "vtkSoftShadowsLargeBuffers.h" // for RawVector
#include "vtkType.h"

#include <cstdint> // for std::int32_t, std::uint8_t
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
   * `edges`). The tree keeps its own copy of the planes of the faces it uses,
   * and each leaf a float copy of its faces' planes.
   */
  void Build(const RawVector<Edge>& edges, const RawVector<double>& midpoints,
    const double* normals, const double* offsets);

  /**
   * Appends the silhouette edges among the tree's edges for the light
   * (x, y, z, w) to `silhouette`, each as its id and its two points, ordered
   * so that the faces lie to the left seen from the light (first point first
   * when the edge's first face faces the light). The order is the tree's,
   * whatever the number of threads. Returns how many edges were tested
   * exactly. `scale` bounds |p| over the mesh, for the round-off margin.
   * Multi-threaded with vtkSMPTools.
   */
  vtkIdType Query(const double light[4], double scale, std::vector<std::int32_t>& silhouette) const;

  vtkIdType GetNumberOfNodes() const { return static_cast<vtkIdType>(this->Nodes.size()); }
  vtkIdType GetNumberOfEdges() const
  {
    return static_cast<vtkIdType>(this->EdgeOutputs.size() / 3);
  }

  /// Margin that covers the round-off of the bounds against the exact test.
  static double Tolerance(const double light[4], double scale);

private:
  // 64 bytes, a cache line: the walk is bound by memory, not arithmetic. The
  // float fields are rounded outward (cosine, offset minimum down; sine,
  // offset maximum up), so the bounds stay conservative.
  struct Node
  {
    double Axis[3]; // unit axis of the cone of the faces' normals
    float Cos;      // at most the cosine of the cone's half angle: smallest Axis . n
    float Sin;      // at least its sine: largest |Axis x n| (exact for small angles)
    float Center[3];
    float OffsetMin; // range of d_f - n_f . Center over the node's faces
    float OffsetMax;
    std::int32_t Begin; // the node's edges, Begin .. End - 1 in tree order
    std::int32_t End;
    std::int32_t Right; // right child (the left one follows the node); < 0 in a leaf
  };

  // True when the bounds prove all of the node's faces on one side of the light.
  static bool OneSided(const Node& node, const double light[4], double tolerance);
  struct Builder;

  RawVector<Node> Nodes;
  // Leaf data, leaf by leaf in tree order (a leaf's Right is -1 minus the
  // index of its first face in LeafFaces).
  RawVector<float> LeafPlanes;         // n.x n.y n.z d a leaf's face, rounded to float
  RawVector<std::int32_t> LeafFaces;   // the face, into Planes
  RawVector<std::uint8_t> EdgeFaces;   // 2 an edge: its faces among its leaf's
  RawVector<std::int32_t> EdgeOutputs; // 3 an edge: id, points as its first face runs it
  RawVector<double> Planes;            // n.x n.y n.z d a face, exact
  double MaxOffset = 0.0;              // largest |d| over the faces
};
}

#endif
// VTK-HeaderTest-Exclude: vtkSoftShadowsNormalConeTree.h
