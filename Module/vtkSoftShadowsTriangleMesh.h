// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSoftShadowsTriangleMesh.h
 * @brief  Private: the triangles of a vtkPolyData as the mesh-topology filters see them.
 *
 * vtkTopologyAwareMeshFilter, vtkEdgeAdjacencyFilter and vtkLightSilhouetteFilter all
 * start from the same reading of their input: polygons (triangulated) and triangle
 * strips (decomposed) become faces; vertices and lines are ignored, with one warning;
 * faces that repeat a point id are dropped, with one warning; inputs without faces
 * and those vtkSoftShadowsMeshCheck refuses (point ids out of range, non-finite
 * points) are errors. Face normals are computed by one function, in
 * double precision, so that every filter (and both silhouette searches) sees the
 * very same numbers.
 *
 * Memory is kept small on purpose: these filters run on meshes of millions of
 * faces, where first touches of fresh memory cost as much as the work itself.
 * The input's points are read in place (float or double), point ids are 32-bit,
 * and cell ids are stored only when faces do not map one to one onto cells.
 *
 * Not installed, not wrapped: nothing of it appears in a public header.
 */

#ifndef vtkSoftShadowsTriangleMesh_h
#define vtkSoftShadowsTriangleMesh_h

#include "vtkDataArray.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowsLargeBuffers.h" // for RawVector
#include "vtkType.h"

#include <cmath>   // for std::sqrt
#include <cstdint> // for std::int32_t
#include <vector>  // for std::vector

class vtkAlgorithm;
class vtkPolyData;

namespace vtksoftshadows
{
/// Faces are numbered with 31 bits less one, so that a face and a direction bit
/// fit in an int32 (vtkSoftShadowsEdgeTable.h).
constexpr vtkIdType MaximumNumberOfFaces = (vtkIdType(1) << 30) - 1;

struct TriangleMesh
{
  /// The input's point coordinates, read in place when they are float or double.
  vtkSmartPointer<vtkDataArray> PointArray;
  const float* FloatPoints = nullptr;
  const double* DoublePoints = nullptr;
  std::vector<double> ConvertedPoints; // other point types, converted
  vtkIdType NumberOfPoints = 0;

  /// Three point ids a face, in the input's winding.
  RawVector<std::int32_t> Triangles;
  /// The input cell of each face; empty when face f is cell FirstCellId + f.
  std::vector<vtkIdType> CellIds;
  vtkIdType FirstCellId = 0;

  vtkIdType GetNumberOfFaces() const { return static_cast<vtkIdType>(this->Triangles.size() / 3); }
  vtkIdType GetCellId(vtkIdType face) const
  {
    return this->CellIds.empty() ? this->FirstCellId + face : this->CellIds[face];
  }

  /// Calls fn(points) with a float* or double* to x y z of every point.
  template <typename Functor>
  void VisitPoints(Functor&& fn) const
  {
    if (this->FloatPoints)
    {
      fn(this->FloatPoints);
    }
    else
    {
      fn(this->DoublePoints);
    }
  }
};

/**
 * The unit normal of face f by its winding, in double; (0, 0, 0) for a face of
 * zero area. Every filter of the module computes face normals here.
 */
template <typename T>
inline void FaceNormal(const T* x, const std::int32_t* triangle, double n[3])
{
  const T* p0 = x + 3 * static_cast<vtkIdType>(triangle[0]);
  const T* p1 = x + 3 * static_cast<vtkIdType>(triangle[1]);
  const T* p2 = x + 3 * static_cast<vtkIdType>(triangle[2]);
  const double u[3] = { double(p1[0]) - double(p0[0]), double(p1[1]) - double(p0[1]),
    double(p1[2]) - double(p0[2]) };
  const double v[3] = { double(p2[0]) - double(p0[0]), double(p2[1]) - double(p0[1]),
    double(p2[2]) - double(p0[2]) };
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (length > 0.0 && length <= VTK_DOUBLE_MAX)
  {
    n[0] /= length;
    n[1] /= length;
    n[2] /= length;
  }
  else
  {
    n[0] = n[1] = n[2] = 0.0;
  }
}

/**
 * Reads the faces of `input`. On an empty input (no points, or no polygons and no
 * strips, or no face with three distinct points), a non-finite point or too many
 * points or faces, reports an error through `filter` and returns false. Warns once
 * through `filter` when vertices or lines are ignored and when degenerate faces
 * (repeated point ids) are dropped.
 */
bool ExtractTriangles(vtkPolyData* input, vtkAlgorithm* filter, TriangleMesh& mesh);

/**
 * Neighbours of every face edge, found through the faces around each point (no
 * half-edge structure: this is the fast path the TAM needs). Edge k of face f runs
 * from corner k to corner (k + 1) % 3. Entry 3 f + k is:
 * - 2 g     when exactly one other face g has that edge and runs it the other way
 *           (consistent orientation),
 * - 2 g + 1 when exactly one other face g has it and runs it the same way,
 * - Border (-1) when no other face has it, NonManifold (-2) when two or more do.
 */
constexpr std::int32_t Border = -1;
constexpr std::int32_t NonManifold = -2;
void FindFaceNeighbours(const TriangleMesh& mesh, RawVector<std::int32_t>& neighbours);

/**
 * IEEE 754 binary16 bits of `value`, rounded to nearest even (what GL_HALF_FLOAT
 * attributes hold); overflow gives infinity.
 */
std::uint16_t FloatToHalf(float value);

}

#endif
// VTK-HeaderTest-Exclude: vtkSoftShadowsTriangleMesh.h
