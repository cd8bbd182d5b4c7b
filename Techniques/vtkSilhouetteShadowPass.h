// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSilhouetteShadowPass
 * @brief   Silhouette-distance shadow maps (Valient & Bujnak, "GPU friendly,
 *          anti-aliased, soft shadow mapping", SCCG 2005): anti-aliased hard
 *          shadows, and soft ones for spherical lights.
 *
 * Technique `silhouette`. Per light:
 *
 *  1. the framework's depth map, as `hard` draws it;
 *  2. the silhouette pass (section 2.1.1) over each caster's topology aware
 *     mesh (vtkTopologyAwareMeshFilter, built once per polydata through the
 *     caster registry's cache and uploaded once): the vertex shader finds
 *     the face's silhouette edges (eq. 1), collapses faces without one,
 *     repairs faces degenerate after projection and grows the rest about
 *     their incenter (eq. 2); the fragment shader keeps the thick silhouette
 *     and writes the signed distance to its nearest point and that point's
 *     depth into a float map the size of the depth map, the nearest
 *     silhouette winning;
 *  3. receivers (section 2.2) look the light up with eq. 4 in a lookup
 *     texture: the Hard variant one sample on one row, the anti-aliased
 *     hard shadow; the Soft variant (default) four samples, the row chosen
 *     by the penumbra's width from the light's radius (section 2.2.1), its
 *     profile the fraction of the light's disc left uncovered by a straight
 *     edge.
 *
 * The offset of section 2.2 between the shadow map's boundary and the
 * silhouette's is made on the shadow map's side: the depth map counts as
 * occluded only where the four texels around the point all are (one
 * textureGather), a shadow a texel smaller, so that the silhouette's
 * anti-aliased edge stays where the geometry puts it rather than a texel
 * out.
 *
 * Spot, directional and point lights; a point light's six cube faces each
 * get a silhouette pass into a cube map beside the framework's cube of
 * squared distances, whose four texels around a receiver give the shadow
 * map's verdict (float cube maps: PackedCubeMaps is turned off with a
 * warning). Casters without polygons (lines, points)
 * cast their depth-map shadow only; what the TAM filter does not handle
 * (coincident points with different ids, non-manifold edges) is in its
 * documentation.
 *
 * @sa vtkTopologyAwareMeshFilter vtkSoftShadowPass
 */

#ifndef vtkSilhouetteShadowPass_h
#define vtkSilhouetteShadowPass_h

#include "vtkSoftShadowPass.h"
#include "vtkSoftShadowsTechniquesModule.h" // for export macro

#include <memory> // for std::unique_ptr

class VTKSOFTSHADOWSTECHNIQUES_EXPORT vtkSilhouetteShadowPass : public vtkSoftShadowPass
{
public:
  static vtkSilhouetteShadowPass* New();
  vtkTypeMacro(vtkSilhouetteShadowPass, vtkSoftShadowPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Variants
  {
    Soft = 0,
    Hard = 1
  };

  ///@{
  /**
   * Soft (default): penumbrae from the light's radius, four samples. Hard:
   * anti-aliased hard shadows, one sample, whatever the radius.
   */
  vtkSetClampMacro(Variant, int, Soft, Hard);
  vtkGetMacro(Variant, int);
  void SetVariantToSoft() { this->SetVariant(Soft); }
  void SetVariantToHard() { this->SetVariant(Hard); }
  ///@}

  ///@{
  /**
   * The expected silhouette width in texels (the paper's rendering
   * parameter): distances are kept within half of it plus a texel diagonal
   * of the silhouette. 0 (default) sizes it from the light: twice the widest
   * penumbra (soft) or 2 (hard).
   */
  vtkSetClampMacro(ExpectedWidth, double, 0.0, 256.0);
  vtkGetMacro(ExpectedWidth, double);
  ///@}

  ///@{
  /**
   * Width in texels over which a hard edge goes from lit to shadowed, and
   * the narrowest penumbra. The distance is exact to a fraction of a texel,
   * so the edge needs no wider ramp than the screen's own edges (against
   * an exact hard shadow, 1 texel doubles the error of 0.1). Default 0.1.
   */
  vtkSetClampMacro(EdgeWidth, double, 0.01, 16.0);
  vtkGetMacro(EdgeWidth, double);
  ///@}

  ///@{
  /**
   * Soft: the widest penumbra half-width kept, in texels; wider ones are
   * clamped to it (and the silhouette pass draws more the wider it is).
   * Default 48.
   */
  vtkSetClampMacro(MaximumPenumbra, double, 1.0, 128.0);
  vtkGetMacro(MaximumPenumbra, double);
  ///@}

  ///@{
  /**
   * Soft: the samples a point in a penumbra takes, itself included, and
   * how far those around it lie, in penumbra half-widths, evenly around a
   * circle; the lookup's profiles narrow as they spread. Section 2.2.1
   * takes 4. They follow one silhouette's penumbra; where others overlap
   * it, the OverlapSamples take over. Defaults 4 and 0.25 (wider spreads
   * pick up other silhouettes on folded meshes).
   */
  vtkSetClampMacro(PenumbraSamples, int, 1, 64);
  vtkGetMacro(PenumbraSamples, int);
  vtkSetClampMacro(SampleSpread, double, 0.0, 0.8);
  vtkGetMacro(SampleSpread, double);
  ///@}

  ///@{
  /**
   * Soft: where another silhouette lies within a penumbra's reach (grates,
   * fences, lattices, folds), the samples a point takes instead, itself
   * included, spread out to OverlapSpread half-widths as the crowding
   * grows. Each sample follows its own nearest silhouette, so only many
   * spread over the penumbra add overlapping penumbrae up; where one
   * edge's penumbra falls alone, the paper's few are exact and wide ones
   * are not. A point tells the two apart by how far its distance map,
   * half a penumbra to either side, departs from one straight edge's
   * (docs/quality.md). 1 takes the paper's samples everywhere. Defaults 1
   * and 0.6: 8 meet the truth's steadiness under a grate and lower the
   * error on most scenes, but raise it where a low occluder's edge lies in
   * another's penumbra, and cost more on llvmpipe: a sixth more
   * instructions on a crowded scene, 11-22% more time at 1920x1080
   * (docs/quality.md, "Overlapping penumbrae").
   */
  vtkSetClampMacro(OverlapSamples, int, 1, 64);
  vtkGetMacro(OverlapSamples, int);
  vtkSetClampMacro(OverlapSpread, double, 0.0, 0.8);
  vtkGetMacro(OverlapSpread, double);
  ///@}

  ///@{
  /**
   * Lookup texture: texels per segment of eq. 4 (4 segments side by side)
   * and, soft, rows of penumbra widths. Defaults 256 and 32.
   */
  vtkSetClampMacro(LookupTexels, int, 8, 4096);
  vtkGetMacro(LookupTexels, int);
  vtkSetClampMacro(LookupRows, int, 2, 1024);
  vtkGetMacro(LookupRows, int);
  ///@}

  enum SilhouetteGeometries
  {
    IncenterScaling = 0,
    EdgeRectangles = 1
  };

  ///@{
  /**
   * How pass 2 covers the thick silhouette. IncenterScaling, the paper's
   * (section 2.1.1): the vertex shader grows each silhouette face about its
   * incenter by eq. 2, after repairing faces degenerate after projection.
   * EdgeRectangles: a geometry shader draws a rectangle around each
   * silhouette edge, w_sc from it on every side, from the TAM's per-face
   * layout (one point a face). Both cover every point the fragment shader
   * keeps, and write the same map; a thin or large face grown by eq. 2
   * covers much more than its band. Default EdgeRectangles.
   */
  vtkSetClampMacro(SilhouetteGeometry, int, IncenterScaling, EdgeRectangles);
  vtkGetMacro(SilhouetteGeometry, int);
  void SetSilhouetteGeometryToIncenterScaling() { this->SetSilhouetteGeometry(IncenterScaling); }
  void SetSilhouetteGeometryToEdgeRectangles() { this->SetSilhouetteGeometry(EdgeRectangles); }
  ///@}

  ///@{
  /**
   * The TAM's layout on the GPU (vtkTopologyAwareMeshFilter's options).
   * PerFaceAttributes: the face's corners and neighbours' normals once a
   * face, drawn as instances of 3 vertices (the paper's stream frequency;
   * a third of the memory) instead of in each of its 3 vertices; always so
   * with EdgeRectangles. HalfPrecision: as 16-bit floats (half the memory;
   * corners rounded to 1/2048 of their size). Both default off.
   */
  vtkSetMacro(PerFaceAttributes, bool);
  vtkGetMacro(PerFaceAttributes, bool);
  vtkBooleanMacro(PerFaceAttributes, bool);
  vtkSetMacro(HalfPrecision, bool);
  vtkGetMacro(HalfPrecision, bool);
  vtkBooleanMacro(HalfPrecision, bool);
  ///@}

  ///@{
  /**
   * For casters whose data does not change shape: build their TAMs without
   * the faces that can never have a silhouette edge
   * (vtkTopologyAwareMeshFilter::DropNonSilhouetteFaces). Default off.
   */
  vtkSetMacro(DropNonSilhouetteFaces, bool);
  vtkGetMacro(DropNonSilhouetteFaces, bool);
  vtkBooleanMacro(DropNonSilhouetteFaces, bool);
  ///@}

  ///@{
  /**
   * Show the signed distance map as receivers look it up instead of the
   * shadow: 0.5 on a silhouette, darker on the occluder's side. Default off.
   */
  vtkSetMacro(DebugView, bool);
  vtkGetMacro(DebugView, bool);
  vtkBooleanMacro(DebugView, bool);
  ///@}

  ///@{
  /**
   * Results of the last frame: the bytes of every caster's TAM on the GPU
   * and the TAM vertices drawn per light. The silhouette pass's GPU time,
   * all lights, is GetTechniqueGPUTime().
   */
  vtkGetMacro(TopologyAwareMeshBytes, vtkIdType);
  vtkGetMacro(TopologyAwareMeshVertices, vtkIdType);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkSilhouetteShadowPass();
  ~vtkSilhouetteShadowPass() override;

  bool RenderShadowMaps(const vtkRenderState* s) override;
  Traits GetTraits() const override;
  ReceiverCode GetReceiverCode() override;
  /// Light `slot`'s visibility: eq. 4 looked up (or the debug view).
  std::string GetVisibility(int slot) const;

  int Variant = Soft;
  double ExpectedWidth = 0.0;
  double EdgeWidth = 0.1;
  double MaximumPenumbra = 48.0;
  int PenumbraSamples = 4;
  double SampleSpread = 0.25;
  int OverlapSamples = 1;
  double OverlapSpread = 0.6;
  int LookupTexels = 256;
  int LookupRows = 32;
  int SilhouetteGeometry = EdgeRectangles;
  bool PerFaceAttributes = false;
  bool HalfPrecision = false;
  bool DropNonSilhouetteFaces = false;
  bool DebugView = false;
  vtkIdType TopologyAwareMeshBytes = 0;
  vtkIdType TopologyAwareMeshVertices = 0;

private:
  vtkSilhouetteShadowPass(const vtkSilhouetteShadowPass&) = delete;
  void operator=(const vtkSilhouetteShadowPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
