// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// `reference` in vtkShadowTechniqueCatalog: its variants and parameters.
#include "vtkShadowTechniqueCatalogInternals.h"

#include "vtkReferenceShadowPass.h"

namespace vtkShadowCatalog
{
Technique Reference()
{
  return { "reference",
    "vtkReferenceShadowPass: ground truth, the average of many hard shadow maps drawn from "
    "points sampled over each light (slow)",
    { { "disc", "points on a disc across the light's axis (SPEC's reference)" },
      { "sphere",
        "points in the light's sphere, uniform over its disc from every side, as the "
        "ray-cast truth" } },
    {
      BindClamped<vtkReferenceShadowPass, int>("samples", Integer,
        "light samples (shadow maps) per light, rounded down to a square",
        VTK_SHADOW_CLAMPED(vtkReferenceShadowPass, NumberOfSamples)),
      Bind<vtkReferenceShadowPass, unsigned int>("seed", Integer, Between(0.0, 2147483647.0),
        "seed of the light sample jitter", &vtkReferenceShadowPass::SetSeed,
        &vtkReferenceShadowPass::GetSeed),
    },
    [](const std::string& variant)
    {
      auto pass = vtkSmartPointer<vtkReferenceShadowPass>::New();
      pass->SetSampling(
        variant == "sphere" ? vtkReferenceShadowPass::Sphere : vtkReferenceShadowPass::Disc);
      return pass;
    } };
}
}
