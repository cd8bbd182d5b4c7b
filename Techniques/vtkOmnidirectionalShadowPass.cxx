// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOmnidirectionalShadowPass.h"

#include "vtkObjectFactory.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowSampling.h"

#include "vtkOmniPoissonFS.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkOmnidirectionalShadowPass);

vtkOmnidirectionalShadowPass::vtkOmnidirectionalShadowPass()
{
  // Section 12.3.4: shade only visible fragments.
  this->DepthPrePass = true;
}
vtkOmnidirectionalShadowPass::~vtkOmnidirectionalShadowPass() = default;

//------------------------------------------------------------------------------
vtkSoftShadowPass::Traits vtkOmnidirectionalShadowPass::GetTraits() const
{
  Traits traits;
  traits.PointLights = true;
  return traits;
}

//------------------------------------------------------------------------------
bool vtkOmnidirectionalShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  // Bilinear 2D maps for spot and directional lights; cube maps are nearest.
  return this->RenderLightDepthMaps(s, true);
}

//------------------------------------------------------------------------------
int vtkOmnidirectionalShadowPass::GetPCFRadius() const
{
  // The framework's lookups: 4-tap PCF of 2D maps, and PCF4's cube spacing.
  return this->Filter == Hard ? 0 : this->PCFRadius;
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::ReceiverCode vtkOmnidirectionalShadowPass::GetReceiverCode()
{
  // Spot and directional lights, and the other filters: the framework's.
  ReceiverCode code;
  if (this->Filter != Poisson)
  {
    return code;
  }
  const auto& lights = this->Maps->GetLights();
  const bool cubes = std::any_of(
    lights.begin(), lights.end(), [](const vtkShadowMapManager::Light& l) { return l.Point; });
  code.Declarations = cubes ? vtkOmniPoissonFS : "";
  code.Visibility = [this](int slot)
  {
    const auto& light = this->Maps->GetLights()[slot];
    if (!light.Point)
    {
      return this->GetDefaultVisibility(slot);
    }
    // The first point light's expression computes every cube's visibility
    // in one loop, so the shader holds one copy of the lookup whatever the
    // number of point lights: written once per light, llvmpipe's compile
    // time grew from 1.5 s at 6 lights to 33 s at 8.
    const std::string m = std::to_string(light.MapIndex);
    return this->IsFirstPointLight(slot)
      ? "vtkOmniPoissonAll(vtkShadowPositionWC, vtkShadowNormalWC, " + m + ")"
      : "omniVisibility[" + m + "]";
  };
  code.Uniforms = [this](vtkShaderProgram* program)
  {
    if (!program->IsUniformUsed("omniTaps"))
    {
      return;
    }
    static const std::vector<glm::vec2> disc = vtkShadowSampling::PoissonDisk(32, 11, true, false);
    program->SetUniform2fv("omniPoisson", 32, &disc[0].x);
    program->SetUniformi("omniTaps", this->PoissonTaps);
    for (const auto& light : this->Maps->GetLights())
    {
      if (light.Point)
      {
        const std::string name = "omniLightRadius[" + std::to_string(light.MapIndex) + "]";
        program->SetUniformf(name.c_str(), static_cast<float>(light.Radius));
      }
    }
  };
  return code;
}

//------------------------------------------------------------------------------
void vtkOmnidirectionalShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* names[] = { "Hard", "PCF4", "Poisson" };
  os << indent << "Filter: " << names[this->Filter] << "\n";
  os << indent << "PCFRadius: " << this->PCFRadius << "\n";
  os << indent << "PoissonTaps: " << this->PoissonTaps << "\n";
}
