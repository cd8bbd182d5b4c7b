// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTopologyAwareMeshFilter
 * @brief   Build a topology aware mesh (TAM) for silhouette rendering on the GPU.
 *
 * A topology aware mesh (Valient & Bujnak, "GPU friendly, anti-aliased, soft
 * shadow mapping", section 2.1) stores in every vertex what a vertex shader
 * needs to find the silhouette edges of its face without any adjacency lookup:
 * the vertex's own position, the three positions of its face, and the normals
 * of the three faces across the face's edges. Three vertices make one face;
 * faces share no vertex. A border edge stores the negated face normal, so that
 * it always tests as a silhouette (sign(n_f . v) != sign(-n_f . v)).
 *
 * The input's polygons are triangulated and its triangle strips decomposed;
 * vertex and line cells are ignored (one warning), faces that repeat a point id
 * are dropped (one warning). Neighbours are found by point id: coincident
 * points with different ids do not connect faces (run vtkCleanPolyData first).
 * An input without points or faces, or with a NaN or infinite coordinate, is an
 * error and gives an empty output.
 *
 * Two cases the paper does not meet:
 * - A neighbour that runs the shared edge in the same direction as the face
 *   (inconsistent orientation: a flipped face, the seam of a Moebius strip)
 *   stores its normal negated, i.e. as if it were turned to agree with the
 *   face, so that the paper's test is still the geometric one (the edge is a
 *   silhouette when the surface folds over as seen from the light).
 * - An edge shared by three or more faces (non-manifold) has no single
 *   neighbour: it is stored like a border edge, always a silhouette.
 *
 * @par Output, default layout (one vertex per face corner, 3 per face)
 * - Points: float, the corners of kept face i at 3 i, 3 i + 1, 3 i + 2, in the
 *   input's winding. Polys: triangle i = (3 i, 3 i + 1, 3 i + 2).
 * - Point data, the vertex buffer (one attribute per array):
 *   - "Position" (3 components, float; unsigned short with HalfPrecision): the
 *     vertex's own position (the paper's first field); in float, the very
 *     array of the Points.
 *   - "FacePositions" (9, float or unsigned short): V1, V2, V3, the corners
 *     of the vertex's face, the same in its three vertices.
 *   - "AdjacentNormals" (9, float or unsigned short): unit normals n1, n2, n3
 *     of the faces across edges V1V2, V2V3 and V3V1; -n_f for a border or
 *     non-manifold edge.
 * - Cell data: "InputCellIds" (1, vtkIdType), the input cell of each face.
 *
 * @par Output with PerFaceAttributes (the paper's "stream frequency" layout)
 * - Points: the input's points (the same vtkPoints). Polys: the kept faces,
 *   with the input's point ids.
 * - Cell data, the per-instance buffer (draw 3 vertices an instance, one
 *   instance a face; the corner is gl_VertexID):
 *   - "FacePositions" (9, float or unsigned short): as above, once a face.
 *   - "AdjacentNormals" (9, float or unsigned short): as above, once a face.
 *   - "InputCellIds" (1, vtkIdType): the input cell of each face (not part of
 *     the buffer).
 *
 * With HalfPrecision the unsigned short values are IEEE 754 binary16 bit
 * patterns, rounded to nearest even: upload them as GL_HALF_FLOAT.
 *
 * @par Memory
 * GetTopologyAwareMeshBytes() counts the buffer arrays above ("Position" when
 * present, "FacePositions", "AdjacentNormals"); GetInputMeshBytes() counts the
 * input as a renderer holds it: its points as float positions (12 bytes each),
 * its point-data arrays at their own sizes, and a 32-bit index buffer of its
 * triangles (12 bytes each). The paper reports 1.53 times the input mesh for its
 * half-precision TAM and 0.77 times with per-face data; its input meshes carried
 * more per vertex than most VTK meshes do (the ratio here is larger: see
 * GetMemoryRatio()).
 *
 * @sa vtkEdgeAdjacencyFilter vtkLightSilhouetteFilter
 */

#ifndef vtkTopologyAwareMeshFilter_h
#define vtkTopologyAwareMeshFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkSoftShadowsFiltersModule.h" // for export macro

class VTKSOFTSHADOWSFILTERS_EXPORT vtkTopologyAwareMeshFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkTopologyAwareMeshFilter* New();
  vtkTypeMacro(vtkTopologyAwareMeshFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Store the buffer arrays as half floats (IEEE binary16 bits in unsigned
   * short arrays) instead of floats, halving them, as the paper does. Points
   * stay float. Default off.
   */
  vtkSetMacro(HalfPrecision, bool);
  vtkGetMacro(HalfPrecision, bool);
  vtkBooleanMacro(HalfPrecision, bool);
  ///@}

  ///@{
  /**
   * Store the face positions and adjacent normals once per face, as cell data
   * (the paper's stream-frequency, or instanced, layout), instead of in each of
   * the face's three vertices. Default off.
   */
  vtkSetMacro(PerFaceAttributes, bool);
  vtkGetMacro(PerFaceAttributes, bool);
  vtkBooleanMacro(PerFaceAttributes, bool);
  ///@}

  ///@{
  /**
   * For rigid meshes: leave out faces that can never have a silhouette edge,
   * those whose three neighbours all exist and are coplanar with them (their
   * orientation-corrected unit normals differ from the face's by at most
   * CoplanarTolerance). No light position makes sign(n_f . v) differ from
   * sign(n_E . v) for such a face. Border and non-manifold edges always count
   * as silhouettes, so their faces stay. Default off.
   */
  vtkSetMacro(DropNonSilhouetteFaces, bool);
  vtkGetMacro(DropNonSilhouetteFaces, bool);
  vtkBooleanMacro(DropNonSilhouetteFaces, bool);
  ///@}

  ///@{
  /**
   * Largest distance |n_f - n_E| between unit normals for which
   * DropNonSilhouetteFaces takes two faces as coplanar; 0 asks for identical
   * normals. Default 1e-6 (well below what float shaders can tell apart).
   */
  vtkSetClampMacro(CoplanarTolerance, double, 0.0, 2.0);
  vtkGetMacro(CoplanarTolerance, double);
  ///@}

  ///@{
  /**
   * Results of the last update: bytes of the TAM's buffer arrays, bytes of the
   * input mesh as a renderer holds it (see the class description), their
   * ratio (0 before a successful update), and the faces left out by
   * DropNonSilhouetteFaces.
   */
  vtkGetMacro(TopologyAwareMeshBytes, vtkIdType);
  vtkGetMacro(InputMeshBytes, vtkIdType);
  double GetMemoryRatio() const;
  vtkGetMacro(NumberOfDroppedFaces, vtkIdType);
  ///@}

protected:
  vtkTopologyAwareMeshFilter() = default;
  ~vtkTopologyAwareMeshFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool HalfPrecision = false;
  bool PerFaceAttributes = false;
  bool DropNonSilhouetteFaces = false;
  double CoplanarTolerance = 1e-6;

  vtkIdType TopologyAwareMeshBytes = 0;
  vtkIdType InputMeshBytes = 0;
  vtkIdType NumberOfDroppedFaces = 0;

private:
  vtkTopologyAwareMeshFilter(const vtkTopologyAwareMeshFilter&) = delete;
  void operator=(const vtkTopologyAwareMeshFilter&) = delete;
};

#endif
