// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// `omni` in vtkShadowTechniqueCatalog: its variants and parameters.
#include "vtkShadowTechniqueCatalogInternals.h"

#include "vtkOmnidirectionalShadowPass.h"

namespace vtkShadowCatalog
{
Technique Omni()
{
  return { "omni",
    "vtkOmnidirectionalShadowPass: point lights' cube maps of squared distances (Gerasimov, "
    "GPU Gems ch. 12), filtered; spot and directional lights as hard with 4-tap PCF",
    { { "poisson", "blocker search and rotated Poisson-disk PCF sized by the light's radius" },
      { "pcf4", "the chapter's 4-tap PCF" }, { "hard", "one tap" } },
    {
      BindClamped<vtkOmnidirectionalShadowPass, int>("pcf_radius", Integer,
        "pcf4: distance between the taps, in texels",
        VTK_SHADOW_CLAMPED(vtkOmnidirectionalShadowPass, PCFRadius)),
      BindClamped<vtkOmnidirectionalShadowPass, int>("taps", Integer,
        "poisson: taps of the blocker search and of the filter",
        VTK_SHADOW_CLAMPED(vtkOmnidirectionalShadowPass, PoissonTaps)),
      Bind<vtkSoftShadowPass, bool>("single_pass_cube_maps", Boolean, Any(),
        "draw the six cube faces in one layered pass (else six passes, as the paper)",
        &vtkSoftShadowPass::SetSinglePassCubeMaps, &vtkSoftShadowPass::GetSinglePassCubeMaps),
    },
    [](const std::string& variant)
    {
      auto pass = vtkSmartPointer<vtkOmnidirectionalShadowPass>::New();
      if (variant == "pcf4")
      {
        pass->SetFilterToPCF4();
      }
      else if (variant == "hard")
      {
        pass->SetFilterToHard();
      }
      else
      {
        pass->SetFilterToPoisson();
      }
      return pass;
    } };
}
}
