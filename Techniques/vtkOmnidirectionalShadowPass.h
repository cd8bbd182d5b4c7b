// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOmnidirectionalShadowPass
 * @brief   Omnidirectional shadows for point lights (Gerasimov, GPU Gems
 *          ch. 12, "Omnidirectional Shadow Mapping"), soft.
 *
 * Technique `omni`. Point lights get the framework's cube maps of squared
 * distances (six 90-degree faces, in one layered pass or six, float or
 * RGBA8-packed, multiplicative bias), looked up with the light-to-fragment
 * direction, filtered by the variant:
 *
 *  - Hard: one tap;
 *  - PCF4: the chapter's 4-tap percentage-closer filter (section 12.4), taps
 *    PCFRadius texels apart;
 *  - Poisson (default, beyond the chapter): a blocker search and a
 *    percentage-closer filter over Poisson-disk taps rotated per pixel,
 *    sized by the light's radius (vtkSoftShadowPass::SetRadius): the
 *    penumbra w = (d_receiver - d_blocker) * w_light / d_blocker.
 *
 * Spot and directional lights in the same scene get the framework's 2D maps
 * with a 4-tap bilinear PCF, as `hard` with PCF radius 1. The chapter's
 * depth-only pre-pass is on (vtkSoftShadowPass::DepthPrePass).
 */

#ifndef vtkOmnidirectionalShadowPass_h
#define vtkOmnidirectionalShadowPass_h

#include "vtkSoftShadowPass.h"
#include "vtkSoftShadowsTechniquesModule.h" // for export macro

class VTKSOFTSHADOWSTECHNIQUES_EXPORT vtkOmnidirectionalShadowPass : public vtkSoftShadowPass
{
public:
  static vtkOmnidirectionalShadowPass* New();
  vtkTypeMacro(vtkOmnidirectionalShadowPass, vtkSoftShadowPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Filters
  {
    Hard = 0,
    PCF4 = 1,
    Poisson = 2
  };

  ///@{
  /**
   * How point lights' cube maps are filtered. Default Poisson.
   */
  vtkSetClampMacro(Filter, int, Hard, Poisson);
  vtkGetMacro(Filter, int);
  void SetFilterToHard() { this->SetFilter(Hard); }
  void SetFilterToPCF4() { this->SetFilter(PCF4); }
  void SetFilterToPoisson() { this->SetFilter(Poisson); }
  ///@}

  ///@{
  /**
   * PCF4: distance between the four taps, in texels. Default 1.
   */
  vtkSetClampMacro(PCFRadius, int, 1, 8);
  vtkGetMacro(PCFRadius, int);
  ///@}

  ///@{
  /**
   * Poisson: taps of the blocker search and of the filter, 1 to 32.
   * Default 16.
   */
  vtkSetClampMacro(PoissonTaps, int, 1, 32);
  vtkGetMacro(PoissonTaps, int);
  ///@}

protected:
  vtkOmnidirectionalShadowPass();
  ~vtkOmnidirectionalShadowPass() override;

  bool RenderShadowMaps(const vtkRenderState* s) override;
  Traits GetTraits() const override;
  int GetPCFRadius() const override;
  ReceiverCode GetReceiverCode() override;

  int Filter = Poisson;
  int PCFRadius = 1;
  int PoissonTaps = 16;

private:
  vtkOmnidirectionalShadowPass(const vtkOmnidirectionalShadowPass&) = delete;
  void operator=(const vtkOmnidirectionalShadowPass&) = delete;
};

#endif
