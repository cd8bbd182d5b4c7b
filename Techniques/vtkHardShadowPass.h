// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkHardShadowPass
 * @brief   Plain shadow mapping: one depth map per light, slope-scaled bias,
 *          optional percentage-closer filtering.
 *
 * The baseline every soft technique is compared with (technique `hard`). It
 * adds nothing to the framework but its PCF kernel: the framework's depth
 * maps and hard lookup are the technique. Point lights get cube maps of
 * squared distances (Gerasimov, GPU Gems ch. 12), one tap or, with a PCF
 * radius, the chapter's 4-tap PCF with taps `PCFRadius` texels apart.
 *
 * @sa vtkSoftShadowPass
 */

#ifndef vtkHardShadowPass_h
#define vtkHardShadowPass_h

#include "vtkSoftShadowPass.h"
#include "vtkSoftShadowsTechniquesModule.h" // for export macro

class VTKSOFTSHADOWSTECHNIQUES_EXPORT vtkHardShadowPass : public vtkSoftShadowPass
{
public:
  static vtkHardShadowPass* New();
  vtkTypeMacro(vtkHardShadowPass, vtkSoftShadowPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Radius in texels of the square PCF kernel, whose footprint is (2r+1)^2
   * texels: (2r)^2 taps on texel corners when HardwareFiltering is on (each
   * a 2x2 bilinear comparison: tent weights), (2r+1)^2 binary taps when off.
   * 0 is a single tap (with HardwareFiltering, 2x2 bilinear PCF). Default 0:
   * the cheapest, and each wider kernel costs (2r)^2 lookups per light.
   */
  vtkSetClampMacro(PCFRadius, int, 0, 8);
  vtkGetMacro(PCFRadius, int);
  ///@}

  ///@{
  /**
   * Bilinear comparison filtering in the depth texture (GL_LINEAR with
   * GL_COMPARE_REF_TO_TEXTURE). Off gives exactly binary visibility per tap.
   * Default on.
   */
  vtkSetMacro(HardwareFiltering, bool);
  vtkGetMacro(HardwareFiltering, bool);
  vtkBooleanMacro(HardwareFiltering, bool);
  ///@}

protected:
  vtkHardShadowPass();
  ~vtkHardShadowPass() override;

  bool RenderShadowMaps(const vtkRenderState* s) override;
  int GetPCFRadius() const override { return this->PCFRadius; }
  Traits GetTraits() const override;

  int PCFRadius = 0;
  bool HardwareFiltering = true;

private:
  vtkHardShadowPass(const vtkHardShadowPass&) = delete;
  void operator=(const vtkHardShadowPass&) = delete;
};

#endif
