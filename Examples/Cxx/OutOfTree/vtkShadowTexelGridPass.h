// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowTexelGridPass
 * @brief   A debugging technique written outside the module: hard shadows
 *          with each light's shadow-map texels drawn on the receivers as a
 *          checkerboard, to see where a map's resolution runs out.
 *
 * It shows what a technique needs of the framework (docs/architecture.md,
 * "Writing a technique"): the light depth maps drawn by RenderShadowMaps(),
 * and its receiver code (GetReceiverCode()): a GLSL function of its own,
 * the expression that gives each light's visibility from the framework's
 * receiver code, and its own uniform. Point lights fall to the framework's
 * own cube lookup, unchecked.
 */

#ifndef vtkShadowTexelGridPass_h
#define vtkShadowTexelGridPass_h

#include "vtkSoftShadowPass.h"

class vtkShadowTexelGridPass : public vtkSoftShadowPass
{
public:
  static vtkShadowTexelGridPass* New();
  vtkTypeMacro(vtkShadowTexelGridPass, vtkSoftShadowPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * How much darker the odd texels are drawn, in [0, 1]. Default 0.35.
   */
  vtkSetClampMacro(Contrast, double, 0.0, 1.0);
  vtkGetMacro(Contrast, double);
  ///@}

protected:
  vtkShadowTexelGridPass();
  ~vtkShadowTexelGridPass() override;

  bool RenderShadowMaps(const vtkRenderState* s) override;
  Traits GetTraits() const override
  {
    Traits traits;
    traits.PointLights = true;
    return traits;
  }
  ReceiverCode GetReceiverCode() override;

  double Contrast = 0.35;

private:
  vtkShadowTexelGridPass(const vtkShadowTexelGridPass&) = delete;
  void operator=(const vtkShadowTexelGridPass&) = delete;
};

#endif
