// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSmoothieShadowPass
 * @brief   Smoothies (Chan & Durand, "Rendering fake soft shadows with
 *          smoothies", EGSR 2003, as Volokh's report implements them): soft
 *          shadow edges from geometry drawn along the casters' silhouettes.
 *
 * Technique `smoothies`. Per caster polydata, built once through the caster
 * registry's cache: its coincident points merged, the edge-to-faces map and
 * face normals (vtkEdgeAdjacencyFilter) and the silhouette search
 * (vtkLightSilhouetteFilter, with its normal-cone tree by default). Per light,
 * whenever the light moves in a caster's model space, the caster's silhouette
 * edges with the light in that space, chained into lines with adjacency (each
 * edge with the one that follows it). Then per light:
 *
 *  1. the shadow map: each fragment's linear depth written into a 32-bit
 *     float map with MIN blending (section 3.2); a point light's is the
 *     framework's cube of squared distances;
 *  2. the smoothie buffer (sections 3.1, 3.3 to 3.5): a geometry shader
 *     extrudes each silhouette edge in the light's screen space into a
 *     smoothie edge (two triangles, the side chosen by the adjacent faces'
 *     normals averaged in screen space, figure 2a) and adds the smoothie
 *     corner where it meets the next edge (figure 2b); their fragments
 *     write their depth and alpha' = alpha / (1 - b/r) (clamped; none where
 *     b ~ r) into a float buffer with MIN blending; a point light's six cube
 *     faces each get their own smoothie face;
 *  3. receivers (section 4): 0 if d > d_s, alpha' if d > d_m, else 1, at the
 *     four nearest texels, weighted bilinearly.
 *
 * The thickness t is the outer half of the penumbra the light's radius gives
 * (PenumbraScale times it) unless Thickness fixes it: alpha' is then the
 * fragment's distance from the silhouette over the penumbra's outer width at
 * its receiver, which for spot and point lights is exactly the report's
 * alpha / (1 - b/r) with t = that width for a receiver infinitely far, and
 * for directional lights its parallel counterpart (the width grows with
 * r - b). Smoothies are fake: the umbra stays the hard shadow's, and the
 * soft edge lies outside it.
 *
 * Spot, directional and point lights. Casters without polygons (lines,
 * points) cast their shadow-map shadow only. Silhouette edges crossing a
 * cube face's eye plane draw no smoothie on that face.
 *
 * @sa vtkLightSilhouetteFilter vtkEdgeAdjacencyFilter vtkSoftShadowPass
 */

#ifndef vtkSmoothieShadowPass_h
#define vtkSmoothieShadowPass_h

#include "vtkSoftShadowPass.h"
#include "vtkSoftShadowsTechniquesModule.h" // for export macro

#include <memory> // for std::unique_ptr

class VTKSOFTSHADOWSTECHNIQUES_EXPORT vtkSmoothieShadowPass : public vtkSoftShadowPass
{
public:
  static vtkSmoothieShadowPass* New();
  vtkTypeMacro(vtkSmoothieShadowPass, vtkSoftShadowPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * A fixed smoothie thickness t in shadow-map texels, with the report's
   * alpha / (1 - b/r) correction; 0 (default) sizes it from the light's
   * radius (see above).
   */
  vtkSetClampMacro(Thickness, double, 0.0, 256.0);
  vtkGetMacro(Thickness, double);
  ///@}

  ///@{
  /**
   * Sized from the radius: the soft edge's width as a fraction of the outer
   * half of the light's penumbra. Default 0.7, nearest to the ray-cast truth
   * with the SquareRoot falloff on the quality scenes (docs/quality.md).
   */
  vtkSetClampMacro(PenumbraScale, double, 0.01, 4.0);
  vtkGetMacro(PenumbraScale, double);
  ///@}

  enum Falloffs
  {
    Linear = 0,    ///< alpha' as the report has it
    SquareRoot = 1 ///< its square root
  };

  ///@{
  /**
   * How the shadow rises across the smoothie: Linear, the report's alpha',
   * or SquareRoot (default), steepest at the umbra like the outer half of a
   * disc light's penumbra; against the ray-cast truth it is 10-25% nearer
   * (docs/quality.md).
   */
  vtkSetClampMacro(Falloff, int, Linear, SquareRoot);
  vtkGetMacro(Falloff, int);
  void SetFalloffToLinear() { this->SetFalloff(Linear); }
  void SetFalloffToSquareRoot() { this->SetFalloff(SquareRoot); }
  ///@}

  ///@{
  /**
   * The widest smoothie, in shadow-map texels: thicker ones (blockers very
   * near a large light) are clamped to it. Default 64.
   */
  vtkSetClampMacro(MaximumThickness, double, 1.0, 1024.0);
  vtkGetMacro(MaximumThickness, double);
  ///@}

  ///@{
  /**
   * The silhouette search (vtkLightSilhouetteFilter::Methods): the
   * normal-cone tree (default) or brute force. Both find the same edges.
   */
  vtkSetClampMacro(SilhouetteSearch, int, 0, 1);
  vtkGetMacro(SilhouetteSearch, int);
  ///@}

  ///@{
  /**
   * Where the smoothie edges and corners are built: on the GPU (default), a
   * geometry shader extruding the silhouette edges as they are drawn, so
   * that one edge list serves every frustum; or on the CPU, as the report
   * does, triangles per frustum (six for a point light) built again whenever
   * the light or the caster moves (docs/benchmarks.md compares them).
   */
  vtkSetMacro(BuildOnGPU, bool);
  vtkGetMacro(BuildOnGPU, bool);
  vtkBooleanMacro(BuildOnGPU, bool);
  ///@}

  ///@{
  /**
   * Results of the last frame, over every caster and light: silhouette
   * edges. GetTechniqueCPUTime() is the time of the silhouette searches and
   * of building the smoothies' edge lists and, on the CPU, their triangles
   * (near 0 when nothing moved).
   */
  vtkGetMacro(NumberOfSilhouetteEdges, vtkIdType);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkSmoothieShadowPass();
  ~vtkSmoothieShadowPass() override;

  bool RenderShadowMaps(const vtkRenderState* s) override;
  Traits GetTraits() const override;
  ReceiverCode GetReceiverCode() override;
  /// Each light's smoothie buffer (spot and directional lights' linear
  /// depths take the place of the framework's map).

  double Thickness = 0.0;
  double PenumbraScale = 0.7;
  int Falloff = SquareRoot;
  double MaximumThickness = 64.0;
  int SilhouetteSearch = 1;
  bool BuildOnGPU = true;
  vtkIdType NumberOfSilhouetteEdges = 0;

private:
  vtkSmoothieShadowPass(const vtkSmoothieShadowPass&) = delete;
  void operator=(const vtkSmoothieShadowPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
