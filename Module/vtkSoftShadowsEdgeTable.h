// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSoftShadowsEdgeTable.h
 * @brief  Private: every unique edge of a TriangleMesh with all of its faces.
 *
 * Built on OpenMesh's half-edge structure: faces go into an
 * OpenMesh::PolyConnectivity one by one, and every edge of it is an edge here
 * with its one or two faces. OpenMesh refuses faces that would make its
 * structure non-manifold (a third face on an edge, a face running an edge the
 * same way as its neighbour, a vertex whose fan cannot be linked); those faces
 * are matched to the edges afterwards, by looking their edges up in the
 * half-edge structure, or in a hash table for edges only refused faces have.
 * Nothing is lost: every face edge belongs to exactly one table edge.
 *
 * Edges come in OpenMesh's edge order, then the edges only refused faces have,
 * in the order they were met. Each edge's points are in the order its first
 * face runs it.
 *
 * Not installed, not wrapped: OpenMesh stays out of the public headers.
 */

#ifndef vtkSoftShadowsEdgeTable_h
#define vtkSoftShadowsEdgeTable_h

#include "vtkSmartPointer.h"
#include "vtkSoftShadowsTriangleMesh.h"
#include "vtkTypeInt32Array.h"

#include <cstdint> // for std::int32_t
#include <vector>  // for std::vector

namespace vtksoftshadows
{
struct EdgeTable
{
  /// Two point ids an edge, in the order its first face runs it (ready to be
  /// the connectivity of one line per edge).
  vtkSmartPointer<vtkTypeInt32Array> Points;
  /// Two faces an edge: 2 f when face f runs the edge as Points does, 2 f + 1
  /// when it runs it the other way; the first always runs it as Points does.
  /// A border edge's second is -1. Edges with more faces list the rest below.
  RawVector<std::int32_t> Faces;
  /// Edges with three or more faces (increasing), and their faces after the
  /// first two: those of MoreEdges[i] are MoreFaces[MoreOffsets[i]] ..
  /// MoreFaces[MoreOffsets[i + 1] - 1], encoded as in Faces.
  std::vector<std::int32_t> MoreEdges;
  std::vector<std::int32_t> MoreOffsets;
  std::vector<std::int32_t> MoreFaces;
  /// 0 border (one face), 1 manifold (two), 2 non-manifold (more), an edge:
  /// the values of vtkEdgeAdjacencyFilter::EdgeTypes.
  RawVector<std::uint8_t> Types;
  /// Faces OpenMesh's half-edge structure refused and that were matched by hand.
  vtkIdType RefusedFaces = 0;

  vtkIdType GetNumberOfEdges() const { return static_cast<vtkIdType>(this->Faces.size() / 2); }
  /// Two faces running the edge in opposite directions, and no more: the only
  /// case where "one face toward the light, one away" is the whole silhouette test.
  bool IsConsistentManifold(vtkIdType edge) const
  {
    return this->Types[edge] == 1 && (this->Faces[2 * edge + 1] & 1) == 1;
  }
};

void BuildEdgeTable(const TriangleMesh& mesh, EdgeTable& table);
}

#endif
// VTK-HeaderTest-Exclude: vtkSoftShadowsEdgeTable.h
