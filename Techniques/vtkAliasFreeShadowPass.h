// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkAliasFreeShadowPass
 * @brief   Alias-free shadow maps and sample-based soft shadows (Sintorn,
 *          Eisemann & Assarsson, "Sample Based Visibility for Soft Shadows
 *          using Alias-free Shadow Maps", EGSR 2008), in OpenGL 4.3 compute.
 *
 * Technique `aliasfree`. Shadows are computed for exactly the points the
 * camera sees, not for a map's texels, so there is no aliasing and, for
 * closed casters, no depth bias. Per frame and light:
 *
 *  1. view samples (section 3): the camera pass writes each pixel's surface
 *     position and face normal; the visible, light-front-facing ones are
 *     projected into the light's map (its frustum first fitted to their
 *     bounds, section 4.3), counted per texel by atomic increments, offset by
 *     a prefix sum over the map and packed in one global array (3.1);
 *  2. every caster triangle is drawn into the map by a geometry shader that
 *     grows it conservatively by half a texel (3.2; the exact Minkowski sum,
 *     at most 9 vertices) or, for soft shadows, covers its influence region
 *     (4.1: the convex hull of the light's bounding hexagons seen from each
 *     vertex and projected to the farthest view sample's depth); the fragment
 *     shader walks the texel's list (empty ones skipped) and tests each
 *     sample (3.3): hard, against the triangle's plane and the planes through
 *     its edges and the light, a hidden sample's bit set by an atomic OR;
 *     soft, the bitmask of the N light samples behind each of the planes
 *     through the sample and the triangle's edges (and behind the triangle)
 *     from a lookup table indexed by the plane's two angles and distance
 *     (4.2), ANDed, ORed into the sample's mask;
 *  3. visibility = 1 - hidden (hard) or 1 - popcount / N (soft), per pixel,
 *     for the receivers.
 *
 * For closed casters (every edge shared by two faces, consistently oriented)
 * a triangle hides a sample only from its outer side: light-back-facing
 * triangles alone cast hard shadows, and a surface never shadows itself, so
 * no bias is needed (3.3). Open casters (planes, sheets) are tested from both
 * sides, with their own plane moved away by 1e-5 of the sample's distance to
 * the light so that a sample does not hide itself.
 *
 * Light shapes (soft): a sphere of the light's radius (default; its samples
 * spread so that the sphere is sampled uniformly seen from every side), a disc
 * or a rectangle facing along the light's axis, each scaled per axis by
 * LightScale (an ellipsoid from the sphere). Directional lights sample the
 * cone of directions of their angular radius.
 *
 * Needs OpenGL 4.3 compute, shader storage buffers and atomics: without them
 * the pass reports one clear error and draws the scene without shadows.
 * Point lights take their six cube faces in turn, each with its own lists.
 * Translucent surfaces, which give no view samples, keep the framework's
 * hard shadow-map lookup. Memory for the lists, masks and the casters'
 * triangles and edges is reported (GetMemoryBytes()) and bounded by
 * MemoryLimit: a frame that would exceed it is drawn unshadowed with an
 * error. So is a frame whose soft spot or point
 * light reaches a surface it lights (its radius at least that surface's
 * distance from its centre), whose work would have no bound.
 *
 * The work of soft shadows grows with the casters' triangles times their
 * influence regions' texels in the map (wider with a larger light or a
 * larger map), hardly with the pixels: see docs/benchmarks.md, "Scale".
 *
 * @sa vtkSoftShadowPass vtkShadowCompute
 */

#ifndef vtkAliasFreeShadowPass_h
#define vtkAliasFreeShadowPass_h

#include "vtkSoftShadowPass.h"
#include "vtkSoftShadowsTechniquesModule.h" // for export macro

#include <memory> // for std::unique_ptr

class VTKSOFTSHADOWSTECHNIQUES_EXPORT vtkAliasFreeShadowPass : public vtkSoftShadowPass
{
public:
  static vtkAliasFreeShadowPass* New();
  vtkTypeMacro(vtkAliasFreeShadowPass, vtkSoftShadowPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Variants
  {
    Hard = 0, ///< alias-free hard shadows from the light's centre
    Soft = 1  ///< sample-based visibility of the light's area or volume
  };
  ///@{
  /**
   * Hard or Soft (default). Soft with a light of radius 0 is Hard.
   */
  vtkSetClampMacro(Variant, int, Hard, Soft);
  vtkGetMacro(Variant, int);
  void SetVariantToHard() { this->SetVariant(Hard); }
  void SetVariantToSoft() { this->SetVariant(Soft); }
  ///@}

  ///@{
  /**
   * Soft: light samples per view sample, a multiple of 32 from 32 to 1024
   * (the paper uses 128 to 1024). Default 256.
   */
  void SetNumberOfLightSamples(int count);
  vtkGetMacro(NumberOfLightSamples, int);
  ///@}

  enum LightShapes
  {
    Sphere = 0,   ///< a ball of the light's radius
    Disc = 1,     ///< a disc of the radius, facing along the light's axis
    Rectangle = 2 ///< a square of side 2 radius, facing along the axis
  };
  ///@{
  /**
   * Soft: the shape of spot lights (directional lights sample their cone of
   * directions). Default Sphere.
   */
  vtkSetClampMacro(LightShape, int, Sphere, Rectangle);
  vtkGetMacro(LightShape, int);
  ///@}

  ///@{
  /**
   * Soft: the shape's scale along the light's two side axes and its axis
   * (an ellipsoid from the sphere, an ellipse or a rectangle), each at least
   * 0.001. The first side axis is the world's x made perpendicular to the
   * light's axis (y when the axis is nearly along x), the second the axis
   * crossed with it. Default 1 1 1.
   */
  void SetLightScale(double x, double y, double z);
  void SetLightScale(const double scale[3]) { this->SetLightScale(scale[0], scale[1], scale[2]); }
  vtkGetVector3Macro(LightScale, double);
  ///@}

  ///@{
  /**
   * Fit the light's map to the bounds of the view samples seen through it,
   * so that its texels spread over what the camera sees and lists stay
   * short (section 4.3). Default on.
   */
  vtkSetMacro(FitToViewSamples, bool);
  vtkGetMacro(FitToViewSamples, bool);
  vtkBooleanMacro(FitToViewSamples, bool);
  ///@}

  ///@{
  /**
   * Soft: test light samples only in the texels of the influence regions of
   * edges that are silhouettes for some point of the light (section 4.3);
   * every other view sample sees all of the light or none of it, and takes
   * the hard shadow of its centre. Default on.
   */
  vtkSetMacro(RestrictToSilhouettes, bool);
  vtkGetMacro(RestrictToSilhouettes, bool);
  vtkBooleanMacro(RestrictToSilhouettes, bool);
  ///@}

  ///@{
  /**
   * Soft: temporal jitter (section 4.2). While the view, the lights, the
   * casters and these settings stay as they were, each frame turns the light
   * samples (any rotation for a sphere, about the axis for a disc or a
   * directional light's cone, the square's symmetries) and averages its
   * visibility with the frames before, up to MaximumFramesAccumulated; a
   * frame after any change starts again, unturned. Default on.
   */
  vtkSetMacro(Jitter, bool);
  vtkGetMacro(Jitter, bool);
  vtkBooleanMacro(Jitter, bool);
  vtkSetClampMacro(MaximumFramesAccumulated, int, 1, 1024);
  vtkGetMacro(MaximumFramesAccumulated, int);
  ///@}

  ///@{
  /**
   * Smooth shading without light leaks at shadow borders (section 6): the
   * receivers' shading normals bent towards their faces', so that Phong
   * shading fades to black before the triangles that face away from a light
   * (which the exact shadow darkens) instead of ending in a jagged line of
   * them. Changes VTK's own Phong shading of surfaces with point normals
   * drawn by vtkOpenGLPolyDataMapper (vtkAliasFreeBentNormals). Default off.
   */
  vtkSetMacro(BentNormals, bool);
  vtkGetMacro(BentNormals, bool);
  vtkBooleanMacro(BentNormals, bool);
  ///@}

  ///@{
  /**
   * Seed of the light samples' positions. Default 1.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Most memory, in MiB, the lists, masks and lookup tables of one frame and
   * the casters' triangles and edges (about 740 bytes a triangle soft, 220
   * hard) may take; a frame that needs more is drawn unshadowed, with an
   * error. Default 2048: about 2.8M caster triangles soft, 9M hard, at
   * 512x512.
   */
  vtkSetClampMacro(MemoryLimit, double, 1.0, 65536.0);
  vtkGetMacro(MemoryLimit, double);
  ///@}

  ///@{
  /**
   * Results of the last frame: bytes of the buffers and caster geometry the
   * technique holds (an estimate, made before they are allocated), the view
   * samples stored in lists (over every light), and the longest list.
   */
  vtkGetMacro(MemoryBytes, double);
  vtkGetMacro(NumberOfViewSamples, vtkIdType);
  vtkGetMacro(LongestList, int);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkAliasFreeShadowPass();
  ~vtkAliasFreeShadowPass() override;

  bool RenderShadowMaps(const vtkRenderState* s) override;
  bool RenderScreenSpace(const vtkRenderState* s) override;
  Traits GetTraits() const override;
  ReceiverCode GetReceiverCode() override;
  ReceiverShading GetReceiverShading(const vtkShadowShaderSources& sources) override;
  void SetReceiverShadingUniforms(vtkShaderProgram* program, vtkProp* prop) override;
  void ReceiversDrawn() override;

  int Variant = Soft;
  int NumberOfLightSamples = 256;
  int LightShape = Sphere;
  double LightScale[3] = { 1.0, 1.0, 1.0 };
  bool FitToViewSamples = true;
  bool RestrictToSilhouettes = true;
  bool Jitter = true;
  int MaximumFramesAccumulated = 64;
  bool BentNormals = false;
  unsigned int Seed = 1;
  double MemoryLimit = 2048.0;
  double MemoryBytes = 0.0;
  vtkIdType NumberOfViewSamples = 0;
  int LongestList = 0;

private:
  vtkAliasFreeShadowPass(const vtkAliasFreeShadowPass&) = delete;
  void operator=(const vtkAliasFreeShadowPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
  bool RenderLight(const vtkRenderState* s, int slot);
  // One frustum (a light's, or a cube face's) in the paper's stages.
  struct FrustumPass;
  bool RenderFrustum(const vtkRenderState* s, int slot, const vtkShadowFrustum& view, bool first);
  void BeginFrustum(
    const vtkRenderState* s, int slot, const vtkShadowFrustum& view, bool first, FrustumPass& pass);
  bool FitFrustumToViewSamples(FrustumPass& pass);
  void BuildLists(FrustumPass& pass);
  void BuildDepthLevels(FrustumPass& pass);
  void PrepareLightSamples(FrustumPass& pass);
  bool TestCasters(FrustumPass& pass);
  void Resolve(FrustumPass& pass);
  /// Whether the casters keep their edges: soft, restricted to silhouettes.
  bool KeepsEdges() const { return this->Variant == Soft && this->RestrictToSilhouettes; }
};

#endif
