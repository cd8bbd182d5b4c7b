// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowTexelGridPass.h"

#include "vtkObjectFactory.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapManager.h"

vtkStandardNewMacro(vtkShadowTexelGridPass);

vtkShadowTexelGridPass::vtkShadowTexelGridPass() = default;
vtkShadowTexelGridPass::~vtkShadowTexelGridPass() = default;

//------------------------------------------------------------------------------
bool vtkShadowTexelGridPass::RenderShadowMaps(const vtkRenderState* s)
{
  // Nearest filtering: one texel, one square of the checkerboard.
  return this->RenderLightDepthMaps(s, false);
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::ReceiverCode vtkShadowTexelGridPass::GetReceiverCode()
{
  ReceiverCode code;
  // After the framework's receiver code: vtkShadowReceiverInMap() and
  // vtkShadowCompare() come from there.
  code.Declarations = R"(
uniform float texelGridContrast;

float vtkTexelGrid(sampler2DShadow map, int i, vec3 positionVC, vec3 normalVC)
{
  vec3 p;
  if (!vtkShadowReceiverInMap(i, positionVC, normalVC, p))
  {
    return 1.0;
  }
  ivec2 texel = ivec2(floor(p.xy * vec2(textureSize(map, 0))));
  return vtkShadowCompare(map, p, 0) * (1.0 - texelGridContrast * float((texel.x + texel.y) & 1));
}
)";
  code.Visibility = [this](int slot)
  {
    const auto& light = this->Maps->GetLights()[slot];
    if (light.Point)
    {
      return this->GetDefaultVisibility(slot);
    }
    return "vtkTexelGrid(vtkShadowMap[" + std::to_string(light.MapIndex) + "], " +
      std::to_string(slot) + ", vtkShadowPositionVC, vtkShadowNormalVC)";
  };
  code.Uniforms = [this](vtkShaderProgram* program)
  { program->SetUniformf("texelGridContrast", static_cast<float>(this->Contrast)); };
  return code;
}

//------------------------------------------------------------------------------
void vtkShadowTexelGridPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Contrast: " << this->Contrast << "\n";
}
