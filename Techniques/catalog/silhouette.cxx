// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// `silhouette` in vtkShadowTechniqueCatalog: its variants and parameters.
#include "vtkShadowTechniqueCatalogInternals.h"

#include "vtkSilhouetteShadowPass.h"

namespace vtkShadowCatalog
{
Technique Silhouette()
{
  return { "silhouette",
    "vtkSilhouetteShadowPass: silhouette-distance shadow maps (Valient & Bujnak): the signed "
    "distance to the nearest silhouette, drawn from topology aware meshes, anti-aliases the "
    "shadow map's edges and sizes penumbrae from the light's radius",
    { { "soft", "penumbrae from the light's radius, several samples (penumbra_samples)" },
      { "hard", "one sample: anti-aliased hard shadows" } },
    {
      BindClamped<vtkSilhouetteShadowPass, double>("expected_width", Number,
        "expected silhouette width in shadow-map texels; 0 sizes it from the light (twice the "
        "widest penumbra; 2 for hard shadows)",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, ExpectedWidth)),
      BindClamped<vtkSilhouetteShadowPass, double>("edge_width", Number,
        "texels over which a hard edge goes from lit to shadowed (its anti-aliasing)",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, EdgeWidth)),
      BindClamped<vtkSilhouetteShadowPass, double>("max_penumbra", Number,
        "soft: widest penumbra half-width kept, in texels (wider ones are clamped)",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, MaximumPenumbra)),
      BindClamped<vtkSilhouetteShadowPass, int>("penumbra_samples", Integer,
        "soft: samples a point in a penumbra takes, itself included (the paper's 4)",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, PenumbraSamples)),
      BindClamped<vtkSilhouetteShadowPass, double>("sample_spread", Number,
        "soft: distance of the samples around the point from it, in penumbra half-widths",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, SampleSpread)),
      BindClamped<vtkSilhouetteShadowPass, int>("overlap_samples", Integer,
        "soft: samples a point takes where another silhouette's penumbra overlaps its own, "
        "itself included (1: the paper's samples everywhere)",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, OverlapSamples)),
      BindClamped<vtkSilhouetteShadowPass, double>("overlap_spread", Number,
        "soft: distance of those samples from the point, in penumbra half-widths",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, OverlapSpread)),
      BindClamped<vtkSilhouetteShadowPass, int>("lookup_texels", Integer,
        "lookup texture texels per segment of eq. 4",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, LookupTexels)),
      BindClamped<vtkSilhouetteShadowPass, int>("lookup_rows", Integer,
        "soft: lookup texture rows, one penumbra width each",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, LookupRows)),
      BindClamped<vtkSilhouetteShadowPass, int>("silhouette_geometry", Integer,
        "how pass 2 covers the thick silhouette: 1 a rectangle around each silhouette edge "
        "(geometry shader), 0 each silhouette face grown about its incenter (the paper's eq. 2); "
        "the same map",
        VTK_SHADOW_CLAMPED(vtkSilhouetteShadowPass, SilhouetteGeometry)),
      Bind<vtkSilhouetteShadowPass, bool>("per_face_attributes", Boolean, Any(),
        "topology aware meshes once a face (instanced), not once a corner: a third of the "
        "memory (always so with silhouette_geometry 1)",
        &vtkSilhouetteShadowPass::SetPerFaceAttributes,
        &vtkSilhouetteShadowPass::GetPerFaceAttributes),
      Bind<vtkSilhouetteShadowPass, bool>("half_precision", Boolean, Any(),
        "topology aware meshes in 16-bit floats: half the memory, corners rounded",
        &vtkSilhouetteShadowPass::SetHalfPrecision, &vtkSilhouetteShadowPass::GetHalfPrecision),
      Bind<vtkSilhouetteShadowPass, bool>("drop_non_silhouette_faces", Boolean, Any(),
        "for casters that do not change shape: leave faces that can never be on a silhouette "
        "out of their topology aware meshes",
        &vtkSilhouetteShadowPass::SetDropNonSilhouetteFaces,
        &vtkSilhouetteShadowPass::GetDropNonSilhouetteFaces),
      Bind<vtkSilhouetteShadowPass, bool>("debug_view", Boolean, Any(),
        "show the signed distance map where receivers look it up (0.5 on a silhouette, "
        "darker on the occluder's side)",
        &vtkSilhouetteShadowPass::SetDebugView, &vtkSilhouetteShadowPass::GetDebugView),
    },
    [](const std::string& variant)
    {
      auto pass = vtkSmartPointer<vtkSilhouetteShadowPass>::New();
      if (variant == "hard")
      {
        pass->SetVariantToHard();
      }
      else
      {
        pass->SetVariantToSoft();
      }
      return pass;
    } };
}
}
