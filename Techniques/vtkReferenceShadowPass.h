// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReferenceShadowPass
 * @brief   Ground-truth soft shadows: the average of many hard shadow maps
 *          drawn from points sampled over each light.
 *
 * Technique `reference`. For each shadowed light it draws NumberOfSamples
 * depth maps, from points sampled over the light (spot and point lights,
 * each sample of a point light a whole cube map) or from directions within
 * its angular radius (directional lights), and averages their binary
 * visibility per pixel in a screen-space texture. Radius 0 draws one sample:
 * exactly `hard` without PCF. The points, with a fixed seed so that every
 * run gives the same image:
 *  - Disc (default, SPEC's reference): on a disc of the light's radius
 *    perpendicular to its axis (spot lights) or across the direction to the
 *    scene's centre (point lights), stratified (jittered on a grid mapped to
 *    the disc by Shirley's concentric mapping). Receivers beside the axis
 *    see that disc foreshortened, so their penumbrae come out too narrow
 *    across it.
 *  - Sphere: inside the sphere of the light's radius, spread so that every
 *    receiver, from whatever side it sees the light, sees them uniform over
 *    the sphere's disc (vtkShadowSampling::HaltonBall()): what the ray-cast
 *    truth integrates. Under a point light in a room, RMSE against the truth
 *    0.016 (disc) and 0.003 (sphere); docs/quality.md.
 *
 * Screen-space visibility belongs to the nearest opaque surface; translucent
 * surfaces receive the hard shadow of the light's centre.
 *
 * Slow by design: NumberOfSamples scene depth passes per light per frame;
 * after each the pass invokes vtkCommand::ProgressEvent with the frame's
 * fraction done (a double*), for progress reports.
 */

#ifndef vtkReferenceShadowPass_h
#define vtkReferenceShadowPass_h

#include "vtkSoftShadowPass.h"
#include "vtkSoftShadowsTechniquesModule.h" // for export macro

#include <memory> // for std::unique_ptr

class VTKSOFTSHADOWSTECHNIQUES_EXPORT vtkReferenceShadowPass : public vtkSoftShadowPass
{
public:
  static vtkReferenceShadowPass* New();
  vtkTypeMacro(vtkReferenceShadowPass, vtkSoftShadowPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of light samples (hard shadow maps) averaged per light. Rounded
   * down to a square for the Disc's stratification. Default 256.
   */
  vtkSetClampMacro(NumberOfSamples, int, 1, 4096);
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  ///@{
  /**
   * Where spot and point lights' samples lie: Disc or Sphere (see above).
   * Default Disc.
   */
  enum SamplingType
  {
    Disc = 0,
    Sphere = 1
  };
  vtkSetClampMacro(Sampling, int, Disc, Sphere);
  vtkGetMacro(Sampling, int);
  void SetSamplingToDisc() { this->SetSampling(Disc); }
  void SetSamplingToSphere() { this->SetSampling(Sphere); }
  ///@}

  ///@{
  /**
   * Seed of the sample jitter. Default 1.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

protected:
  vtkReferenceShadowPass();
  ~vtkReferenceShadowPass() override;

  bool RenderShadowMaps(const vtkRenderState* s) override;
  bool RenderScreenSpace(const vtkRenderState* s) override;
  Traits GetTraits() const override;

  int NumberOfSamples = 256;
  int Sampling = Disc;
  unsigned int Seed = 1;

private:
  vtkReferenceShadowPass(const vtkReferenceShadowPass&) = delete;
  void operator=(const vtkReferenceShadowPass&) = delete;

  /**
   * Draw one light sample's map (a cube for point lights) from `eye` along
   * `direction` and add its visibility, times `weight`, to light `slot`'s
   * screen-space texture.
   */
  bool AccumulateSample(const vtkRenderState* s, int slot, const double eye[3],
    const double direction[3], float weight);

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
