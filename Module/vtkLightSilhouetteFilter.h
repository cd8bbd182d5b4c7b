// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightSilhouetteFilter
 * @brief   The silhouette edges of a surface as seen from a light, as lines.
 *
 * vtkLightSilhouetteFilter finds the edges of its input's faces that separate
 * a face toward the light from a face away from it, the edges smoothies extrude
 * (Volokh, sections 2.2 and 3.1; Chan & Durand). Border edges always count.
 *
 * A face is toward the light when g = n . L - w (n . p) > 0, with n its unit
 * normal by winding, p one of its corners, and the light L = LightPosition,
 * w = 1 for a positional light; for a directional light L is the direction
 * toward the light and w = 0. Faces of zero area are never toward the light.
 * An edge is a silhouette edge when all its faces lie on one side of the plane
 * through the edge and the light: for the usual edge, two faces running it in
 * opposite directions, that is exactly "one face toward the light, one away".
 * The general form also gets right an edge whose two faces run it the same way
 * (a flipped face, the seam of a Moebius strip: one of them is taken reversed)
 * and non-manifold edges (three or more faces: a silhouette only when all of
 * them lie on one side).
 *
 * The light is LightPosition and Positional, or a vtkLight (SetLight()), whose
 * transformed position is used for positional lights, and the direction from
 * its transformed focal point to its transformed position for directional
 * ones; a light given with SetLight() is followed when it changes.
 *
 * Two searches give exactly the same edges:
 * - BRUTE_FORCE tests every edge (Volokh, section 5.1);
 * - NORMAL_CONE_TREE (the default) walks a hierarchy of normal cones over the
 *   edges that skips whole groups of edges whose faces all face the same way
 *   (SPEC section 5's faster search for static meshes; see
 *   vtkSoftShadowsNormalConeTree.h for the bounds). It is built on the first
 *   update and reused while the input is unmodified, so a moving light only
 *   pays for the search. Multi-threaded with vtkSMPTools.
 * Both reuse the edge-to-faces map (vtkEdgeAdjacencyFilter's, built on
 * OpenMesh) while the input is unmodified. The cache (edge map, face planes
 * and hierarchy) takes about 150 bytes a face; it goes with the filter.
 *
 * Edges are matched by point id (coincident points with different ids are not
 * merged). Vertex and line cells are ignored, with one warning; faces that
 * repeat a point id are dropped, with one warning. An input without points or
 * faces, a NaN or infinite coordinate, or a light that is not finite (or a
 * directional light without a direction) is an error and gives an empty
 * output.
 *
 * @par Output
 * - Points: the input's points (the same vtkPoints, not copied: the
 *   silhouette changes with every light, the mesh does not). Lines that meet
 *   share their point, where smoothies put their corners. Run
 *   vtkCleanPolyData to keep only the points the lines use.
 * - Lines: one 2-point line per silhouette edge, oriented so that seen from
 *   the light the faces casting the shadow lie to its left (it runs the way
 *   its first face runs it when that face is toward the light, the other way
 *   if not): smoothies are extruded to the right, away from the occluder.
 *   BRUTE_FORCE lists them in increasing edge id, NORMAL_CONE_TREE in the
 *   hierarchy's order (the same for any number of threads).
 * - Cell data: "EdgeIds" (1 component, vtkIdType), the edge's cell id in
 *   vtkEdgeAdjacencyFilter's output for the same input, where its type, faces
 *   and normals are.
 *
 * @sa vtkEdgeAdjacencyFilter vtkTopologyAwareMeshFilter
 */

#ifndef vtkLightSilhouetteFilter_h
#define vtkLightSilhouetteFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"             // for vtkSmartPointer
#include "vtkSoftShadowsFiltersModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkLight;

class VTKSOFTSHADOWSFILTERS_EXPORT vtkLightSilhouetteFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLightSilhouetteFilter* New();
  vtkTypeMacro(vtkLightSilhouetteFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The light: a point for a positional light, the direction toward the light
   * (from the scene) for a directional one. Ignored while a vtkLight is set.
   * Default (0, 0, 1).
   */
  vtkSetVector3Macro(LightPosition, double);
  vtkGetVector3Macro(LightPosition, double);
  ///@}

  ///@{
  /**
   * Whether LightPosition is a point (true) or a direction (false). Ignored
   * while a vtkLight is set. Default true.
   */
  vtkSetMacro(Positional, bool);
  vtkGetMacro(Positional, bool);
  vtkBooleanMacro(Positional, bool);
  ///@}

  ///@{
  /**
   * Take the light from a vtkLight instead, at every update (its transformed
   * position; for a directional light the direction from its transformed focal
   * point to its transformed position). nullptr (the default) goes back to
   * LightPosition and Positional.
   */
  void SetLight(vtkLight* light);
  vtkLight* GetLight();
  ///@}

  /**
   * Silhouette searches.
   */
  enum Methods
  {
    BRUTE_FORCE = 0,
    NORMAL_CONE_TREE = 1
  };

  ///@{
  /**
   * The search: BRUTE_FORCE tests every edge; NORMAL_CONE_TREE (the default)
   * builds a hierarchy over the edges once per input and then tests only the
   * edges near the silhouette. Both give the same output.
   */
  vtkSetClampMacro(Method, int, BRUTE_FORCE, NORMAL_CONE_TREE);
  vtkGetMacro(Method, int);
  void SetMethodToBruteForce() { this->SetMethod(BRUTE_FORCE); }
  void SetMethodToNormalConeTree() { this->SetMethod(NORMAL_CONE_TREE); }
  ///@}

  ///@{
  /**
   * Results of the last update: edges of the input, silhouette edges found,
   * edges the search tested one by one (all of them for BRUTE_FORCE), the
   * wall-clock seconds spent building the cached edge map and, for
   * NORMAL_CONE_TREE, the hierarchy (0 when they were reused), and the
   * seconds the search itself took (without building or output).
   */
  vtkGetMacro(NumberOfEdges, vtkIdType);
  vtkGetMacro(NumberOfSilhouetteEdges, vtkIdType);
  vtkGetMacro(NumberOfTestedEdges, vtkIdType);
  vtkGetMacro(BuildTime, double);
  vtkGetMacro(SearchTime, double);
  ///@}

  /**
   * Includes the light's modification time.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkLightSilhouetteFilter();
  ~vtkLightSilhouetteFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double LightPosition[3] = { 0.0, 0.0, 1.0 };
  bool Positional = true;
  vtkSmartPointer<vtkLight> Light;
  int Method = NORMAL_CONE_TREE;

  vtkIdType NumberOfEdges = 0;
  vtkIdType NumberOfSilhouetteEdges = 0;
  vtkIdType NumberOfTestedEdges = 0;
  double BuildTime = 0.0;
  double SearchTime = 0.0;

private:
  vtkLightSilhouetteFilter(const vtkLightSilhouetteFilter&) = delete;
  void operator=(const vtkLightSilhouetteFilter&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
