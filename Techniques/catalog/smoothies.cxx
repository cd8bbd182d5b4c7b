// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// `smoothies` in vtkShadowTechniqueCatalog: its variants and parameters.
#include "vtkShadowTechniqueCatalogInternals.h"

#include "vtkSmoothieShadowPass.h"

namespace vtkShadowCatalog
{
Technique Smoothies()
{
  return { "smoothies",
    "vtkSmoothieShadowPass: smoothies (Chan & Durand, as Volokh implements them): soft shadow "
    "edges from geometry extruded along the casters' silhouettes as seen from the light, "
    "outside a hard shadow-map umbra",
    {},
    {
      BindClamped<vtkSmoothieShadowPass, double>("thickness", Number,
        "fixed smoothie thickness in shadow-map texels, with the report's alpha / (1 - b/r); "
        "0 sizes it from the light's radius (the outer half of its penumbra)",
        VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, Thickness)),
      BindClamped<vtkSmoothieShadowPass, double>("penumbra_scale", Number,
        "sized from the radius: the soft edge's width over the outer half of the light's "
        "penumbra",
        VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, PenumbraScale)),
      BindClamped<vtkSmoothieShadowPass, int>("falloff", Integer,
        "how the shadow rises across a smoothie: 0 linearly (the report's alpha'), 1 as its "
        "square root, steepest at the umbra",
        VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, Falloff)),
      BindClamped<vtkSmoothieShadowPass, double>("max_thickness", Number,
        "widest smoothie, in shadow-map texels",
        VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, MaximumThickness)),
      BindClamped<vtkSmoothieShadowPass, int>("silhouette_search", Integer,
        "how silhouette edges are found: 1 the normal-cone tree, 0 brute force (the same edges)",
        VTK_SHADOW_CLAMPED(vtkSmoothieShadowPass, SilhouetteSearch)),
      Bind<vtkSmoothieShadowPass, bool>("build_on_gpu", Boolean, Any(),
        "build smoothie edges and corners in a geometry shader (true) or, per frustum, on the "
        "CPU",
        &vtkSmoothieShadowPass::SetBuildOnGPU, &vtkSmoothieShadowPass::GetBuildOnGPU),
    },
    [](const std::string&) { return vtkSmartPointer<vtkSmoothieShadowPass>::New(); } };
}
}
