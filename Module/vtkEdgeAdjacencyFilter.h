// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkEdgeAdjacencyFilter
 * @brief   Every unique edge of a surface with its adjacent faces, as lines.
 *
 * vtkEdgeAdjacencyFilter finds the edges of the polygons and triangle strips of
 * its input (polygons are triangulated, strips decomposed, so the faces are
 * triangles) and, for each edge, the faces that share it: the edge-to-triangles
 * map that smoothies need (Volokh's report, section 2.2) and that the topology
 * aware mesh stores per face (Valient & Bujnak, section 2.1).
 *
 * It is built on OpenMesh's half-edge structure where the mesh is manifold
 * (large meshes are cut into chunks of consecutive faces, each with its own
 * structure built in parallel, and the edges chunks share merged). Faces that
 * structure refuses (a third face on an edge, a face running an edge
 * in the same direction as its neighbour, a vertex whose fan of faces cannot be
 * linked) are matched to the edges afterwards, so no edge and no face is lost:
 * every edge of every face belongs to exactly one output line.
 *
 * Edges are matched by point id, not by position: two coincident points with
 * different ids are different points (run vtkCleanPolyData first to merge them).
 * Vertex and line cells are ignored, with one warning. Triangles that repeat a
 * point id are dropped, with one warning. An input without points or faces, or
 * with a NaN or infinite coordinate, is an error and gives an empty output.
 *
 * @par Output
 * - Points: the input's points (the same vtkPoints), with its point data.
 * - Lines: one 2-point line per unique edge, running the way the edge's first
 *   face (the one that comes first in the input) runs it. Edges come in the
 *   order of OpenMesh's half-edge structure, then those that only refused
 *   faces have; the order is the same for a given input every time, and
 *   vtkLightSilhouetteFilter's "EdgeIds" index it.
 * - Cell data, one tuple per edge:
 *   - "EdgeType" (1 component, unsigned char): BORDER_EDGE (0), one face;
 *     MANIFOLD_EDGE (1), two faces; NON_MANIFOLD_EDGE (2), three or more.
 *   - "ConsistentOrientation" (1, unsigned char): 1 for a border edge and for
 *     a manifold edge whose two faces run it in opposite directions; 0
 *     otherwise (the seam of a Moebius strip, a flipped face, every
 *     non-manifold edge).
 *   - "FaceIds" (2, vtkIdType): input cell ids of the edge's first two faces
 *     (in input order); -1 where a border edge has no second face.
 *   - "FaceNormals" (6, float): unit normals (by winding) of those two faces;
 *     a border edge stores its face's negated normal second, as the topology
 *     aware mesh does, so that it always tests as a silhouette.
 * - Field data, all faces of the non-manifold edges (more than two each):
 *   - "NonManifoldEdgeIds" (1, vtkIdType): output cell ids of the
 *     non-manifold edges, increasing.
 *   - "NonManifoldFaceOffsets" (1, vtkIdType): one tuple more than edges; the
 *     faces of NonManifoldEdgeIds[i] are NonManifoldFaceIds[offset[i]] to
 *     NonManifoldFaceIds[offset[i + 1] - 1].
 *   - "NonManifoldFaceIds" (1, vtkIdType): input cell ids of all faces of
 *     those edges in input order, the two of "FaceIds" first.
 *
 * A face of zero area has the normal (0, 0, 0). Faces are the triangles after
 * triangulation, so the two faces of a quad's diagonal both carry the quad's
 * cell id.
 *
 * @sa vtkTopologyAwareMeshFilter vtkLightSilhouetteFilter vtkFeatureEdges
 */

#ifndef vtkEdgeAdjacencyFilter_h
#define vtkEdgeAdjacencyFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkSoftShadowsFiltersModule.h" // for export macro

class VTKSOFTSHADOWSFILTERS_EXPORT vtkEdgeAdjacencyFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkEdgeAdjacencyFilter* New();
  vtkTypeMacro(vtkEdgeAdjacencyFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Values of the "EdgeType" cell array.
   */
  enum EdgeTypes
  {
    BORDER_EDGE = 0,
    MANIFOLD_EDGE = 1,
    NON_MANIFOLD_EDGE = 2
  };

  ///@{
  /**
   * Counts from the last update: edges of each type, manifold edges whose two
   * faces run them in the same direction, and faces OpenMesh's half-edge
   * structure refused and that were matched to their edges separately (a
   * property of how the structure was built, for tests and curiosity).
   */
  vtkGetMacro(NumberOfBorderEdges, vtkIdType);
  vtkGetMacro(NumberOfManifoldEdges, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldEdges, vtkIdType);
  vtkGetMacro(NumberOfInconsistentEdges, vtkIdType);
  vtkGetMacro(NumberOfRefusedFaces, vtkIdType);
  ///@}

protected:
  vtkEdgeAdjacencyFilter() = default;
  ~vtkEdgeAdjacencyFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfBorderEdges = 0;
  vtkIdType NumberOfManifoldEdges = 0;
  vtkIdType NumberOfNonManifoldEdges = 0;
  vtkIdType NumberOfInconsistentEdges = 0;
  vtkIdType NumberOfRefusedFaces = 0;

private:
  vtkEdgeAdjacencyFilter(const vtkEdgeAdjacencyFilter&) = delete;
  void operator=(const vtkEdgeAdjacencyFilter&) = delete;
};

#endif
