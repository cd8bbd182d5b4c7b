// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// `aliasfree` in vtkShadowTechniqueCatalog: its variants and parameters.
#include "vtkShadowTechniqueCatalogInternals.h"

#include "vtkAliasFreeShadowPass.h"

namespace vtkShadowCatalog
{
Technique AliasFree()
{
  return { "aliasfree",
    "vtkAliasFreeShadowPass: alias-free shadow maps (Sintorn, Eisemann & Assarsson): shadows "
    "tested for exactly the points the camera sees, in OpenGL 4.3 compute; soft shadows as the "
    "fraction of light samples each triangle hides",
    { { "soft", "sample-based visibility of the light's sphere (or disc, rectangle, cone)" },
      { "hard", "alias-free hard shadows from the light's centre" } },
    {
      Bind<vtkAliasFreeShadowPass, int>("light_samples", Integer, Between(32, 1024),
        "soft: light samples per view sample (rounded up to 32s)",
        &vtkAliasFreeShadowPass::SetNumberOfLightSamples,
        &vtkAliasFreeShadowPass::GetNumberOfLightSamples),
      BindClamped<vtkAliasFreeShadowPass, int>("light_shape", Integer,
        "soft, spot lights: 0 a sphere of the radius, 1 a disc, 2 a square of side 2 radius, "
        "facing along the light's axis",
        VTK_SHADOW_CLAMPED(vtkAliasFreeShadowPass, LightShape)),
      BindVector3<vtkAliasFreeShadowPass>("light_scale", AtLeast(1.0e-3),
        "soft, spot lights: the shape's scale across the axis (x: the world's x made "
        "perpendicular to the axis, y: the axis crossed with it) and along it (z): an "
        "ellipsoid, an ellipse, a rectangle",
        &vtkAliasFreeShadowPass::SetLightScale, &vtkAliasFreeShadowPass::GetLightScale),
      Bind<vtkAliasFreeShadowPass, bool>("fit_to_view_samples", Boolean, Any(),
        "fit each light's map to the view samples it sees",
        &vtkAliasFreeShadowPass::SetFitToViewSamples, &vtkAliasFreeShadowPass::GetFitToViewSamples),
      Bind<vtkAliasFreeShadowPass, bool>("restrict_to_silhouettes", Boolean, Any(),
        "soft: test light samples only where silhouette edges cast penumbrae; elsewhere the "
        "light's centre decides",
        &vtkAliasFreeShadowPass::SetRestrictToSilhouettes,
        &vtkAliasFreeShadowPass::GetRestrictToSilhouettes),
      Bind<vtkAliasFreeShadowPass, bool>("jitter", Boolean, Any(),
        "soft: while nothing moves, turn the light samples every frame and average the frames",
        &vtkAliasFreeShadowPass::SetJitter, &vtkAliasFreeShadowPass::GetJitter),
      BindClamped<vtkAliasFreeShadowPass, int>("max_frames_accumulated", Integer,
        "soft, jitter: most frames averaged",
        VTK_SHADOW_CLAMPED(vtkAliasFreeShadowPass, MaximumFramesAccumulated)),
      Bind<vtkAliasFreeShadowPass, bool>("bent_normals", Boolean, Any(),
        "smooth shading without light leaks at shadow borders: surfaces' Phong normals bent "
        "towards their faces' so that they darken before the faces turned from the light",
        &vtkAliasFreeShadowPass::SetBentNormals, &vtkAliasFreeShadowPass::GetBentNormals),
      BindClamped<vtkAliasFreeShadowPass, double>("memory_limit", Number,
        "MiB the lists, masks, tables and the casters' triangles and edges may take; a frame "
        "needing more is drawn unshadowed",
        VTK_SHADOW_CLAMPED(vtkAliasFreeShadowPass, MemoryLimit)),
      Bind<vtkAliasFreeShadowPass, unsigned int>("seed", Integer, Between(0.0, 2147483647.0),
        "soft: seed of the light samples' positions", &vtkAliasFreeShadowPass::SetSeed,
        &vtkAliasFreeShadowPass::GetSeed),
    },
    [](const std::string& variant)
    {
      auto pass = vtkSmartPointer<vtkAliasFreeShadowPass>::New();
      if (variant == "hard")
      {
        pass->SetVariantToHard();
      }
      return pass;
    } };
}
}
