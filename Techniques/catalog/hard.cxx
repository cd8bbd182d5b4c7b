// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// `hard` in vtkShadowTechniqueCatalog: its variants and parameters.
#include "vtkShadowTechniqueCatalogInternals.h"

#include "vtkHardShadowPass.h"

namespace vtkShadowCatalog
{
Technique Hard()
{
  return { "hard", "vtkHardShadowPass: one shadow map per light, percentage-closer filtering",
    { { "layered", "point lights' cube maps drawn in one layered pass" },
      { "sixpass", "point lights' cube maps drawn one face a pass, as in the paper" } },
    {
      BindClamped<vtkHardShadowPass, int>("pcf_radius", Integer,
        "radius in texels of the square PCF kernel: a (2r+1)^2-texel footprint; 0 is one tap",
        VTK_SHADOW_CLAMPED(vtkHardShadowPass, PCFRadius)),
      Bind<vtkHardShadowPass, bool>("hardware_filtering", Boolean, Any(),
        "bilinear depth-comparison filtering of every tap; off gives binary taps",
        &vtkHardShadowPass::SetHardwareFiltering, &vtkHardShadowPass::GetHardwareFiltering),
    },
    [](const std::string& variant)
    {
      auto pass = vtkSmartPointer<vtkHardShadowPass>::New();
      pass->SetSinglePassCubeMaps(variant != "sixpass");
      return pass;
    } };
}
}
