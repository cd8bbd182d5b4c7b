// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// `contact` in vtkShadowTechniqueCatalog: its variants and parameters.
#include "vtkShadowTechniqueCatalogInternals.h"

#include "vtkContactHardeningShadowPass.h"

namespace vtkShadowCatalog
{
Technique Contact()
{
  return { "contact",
    "vtkContactHardeningShadowPass: contact-hardening soft shadows in screen space (Cherry & "
    "Kooima): a distance map of S and D, then S softened with a D-sized filter",
    { { "pcf", "the mean over a disc of D pixels on the receiver" },
      { "gaussian", "one separable Gaussian blur of D pixels" },
      { "multipass", "up to pass_limit Poisson-disk Gaussian blurs, D counting them down" } },
    {
      Bind<vtkContactHardeningShadowPass, bool>("use_light_size", Boolean, Any(),
        "size kernels from the light's radius, w = (d_receiver - d_blocker) * w_light / "
        "d_blocker; off uses dp and dm",
        &vtkContactHardeningShadowPass::SetUseLightSize,
        &vtkContactHardeningShadowPass::GetUseLightSize),
      BindClamped<vtkContactHardeningShadowPass, double>("dp", Number,
        "distance power Dp in D = (occluder distance)^Dp * Dm",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, DistancePower)),
      BindClamped<vtkContactHardeningShadowPass, double>("dm", Number,
        "distance multiplier Dm in D = (occluder distance)^Dp * Dm",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, DistanceMultiplier)),
      BindClamped<vtkContactHardeningShadowPass, int>("pass_limit", Integer,
        "most blur passes (multipass)",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, PassLimit)),
      BindClamped<vtkContactHardeningShadowPass, int>("min_kernel", Integer,
        "first kernel size in pixels when the kernel grows (multipass)",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, MinimumKernelSize)),
      BindClamped<vtkContactHardeningShadowPass, int>("max_kernel", Integer,
        "largest kernel size in pixels",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, MaximumKernelSize)),
      Bind<vtkContactHardeningShadowPass, bool>("growing_kernel", Boolean, Any(),
        "grow the kernel by 2 pixels a pass from min_kernel (multipass)",
        &vtkContactHardeningShadowPass::SetGrowingKernel,
        &vtkContactHardeningShadowPass::GetGrowingKernel),
      BindClamped<vtkContactHardeningShadowPass, int>("taps", Integer,
        "Poisson-disk taps per blur (multipass)",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, PoissonTaps)),
      Bind<vtkContactHardeningShadowPass, bool>("dilation", Boolean, Any(),
        "spread D to lit pixels near shadows: the outer penumbra (pass 3)",
        &vtkContactHardeningShadowPass::SetDilation, &vtkContactHardeningShadowPass::GetDilation),
      BindClamped<vtkContactHardeningShadowPass, int>("dilation_size", Integer,
        "dilation kernel size in pixels",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, DilationSize)),
      Bind<vtkContactHardeningShadowPass, bool>("early_out", Boolean, Any(),
        "D = 0 deep inside the umbra, so blurs skip it",
        &vtkContactHardeningShadowPass::SetUmbraEarlyOut,
        &vtkContactHardeningShadowPass::GetUmbraEarlyOut),
      BindClamped<vtkContactHardeningShadowPass, int>("early_out_size", Integer,
        "early-out neighbourhood in pixels (above max_kernel)",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, EarlyOutKernelSize)),
      BindClamped<vtkContactHardeningShadowPass, int>("resolution_divisor", Integer,
        "screen-space passes on buffers this many times smaller than the window on each axis; "
        "kernel sizes count their pixels",
        VTK_SHADOW_CLAMPED(vtkContactHardeningShadowPass, ResolutionDivisor)),
      Bind<vtkContactHardeningShadowPass, bool>("refine_unresolved", Boolean, Any(),
        "where the buffers cannot hold a penumbra (floors seen nearly edge-on), receivers "
        "filter their hard shadow again in light space over the penumbra's width",
        &vtkContactHardeningShadowPass::SetRefineUnresolved,
        &vtkContactHardeningShadowPass::GetRefineUnresolved),
      Bind<vtkContactHardeningShadowPass, bool>("debug_view", Boolean, Any(),
        "mark umbra (grey) and penumbra (dark) as in the paper's figure 4",
        &vtkContactHardeningShadowPass::SetDebugView, &vtkContactHardeningShadowPass::GetDebugView),
    },
    [](const std::string& variant)
    {
      auto pass = vtkSmartPointer<vtkContactHardeningShadowPass>::New();
      if (variant == "multipass")
      {
        pass->SetVariantToMultiPass();
      }
      else if (variant == "gaussian")
      {
        pass->SetVariantToGaussian();
      }
      else
      {
        pass->SetVariantToPCF();
      }
      return pass;
    } };
}
}
