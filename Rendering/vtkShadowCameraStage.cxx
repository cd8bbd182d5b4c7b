// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowCameraStage.h"

#include "vtkShaderProgram.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowMapperCode.h"

#include "vtkShadowSurfaceFS.h"

#include <algorithm>
#include <array>
#include <iomanip>
#include <sstream>

//------------------------------------------------------------------------------
void vtkShadowCameraStage::Begin(const vtkShadowDrawSetup& setup)
{
  this->Targets = static_cast<int>(setup.Colours.size());
}

//------------------------------------------------------------------------------
void vtkShadowCameraStage::PreReplace(vtkShadowShaderSources& sources)
{
  using namespace vtkShadowMapperCode;
  vtkShadowShaderSources::Before(sources.Fragment, LightDec, ShadowDec);
  sources.Require(sources.Fragment, LightImpl,
    std::string(ShadowImpl) + "\n  return;\n  " + LightImpl, "the camera pass");
}

//------------------------------------------------------------------------------
void vtkShadowCameraStage::PostReplace(vtkShadowShaderSources& sources)
{
  // Without lighting the mapper declares no view-space position: such
  // fragments write what the background holds.
  std::string dec, impl;
  if (this->Targets > 0 && sources.IsLit())
  {
    dec = std::string(vtkShadowSurfaceFS) + "\n" + this->Code->Declarations;
    impl = sources.GetSurfaceCode() + this->Code->Implementation;
  }
  else
  {
    impl = this->UnlitCode();
  }
  sources.Require(sources.Fragment, vtkShadowMapperCode::ShadowDec, dec, "the camera pass");
  sources.Require(sources.Fragment, vtkShadowMapperCode::ShadowImpl, impl, "the camera pass");
}

//------------------------------------------------------------------------------
std::string vtkShadowCameraStage::UnlitCode() const
{
  std::ostringstream impl;
  // Exact: 9 significant digits round-trip a float.
  impl << std::scientific << std::setprecision(9);
  for (int i = 0; i < std::max(this->Targets, 1); ++i)
  {
    std::array<float, 4> clear{};
    if (this->Code && i < static_cast<int>(this->Code->ClearColours.size()))
    {
      clear = this->Code->ClearColours[i];
    }
    impl << "  gl_FragData[" << i << "] = vec4(" << clear[0] << ", " << clear[1] << ", " << clear[2]
         << ", " << clear[3] << ");\n";
  }
  return impl.str();
}

//------------------------------------------------------------------------------
bool vtkShadowCameraStage::GetCodeKey(std::string& key) const
{
  key = std::to_string(this->Targets);
  if (this->Code)
  {
    key += "\n" + this->Code->Declarations + "\n" + this->Code->Implementation;
  }
  key += "\n" + this->UnlitCode();
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowCameraStage::SetUniforms(vtkShaderProgram* program, vtkProp*)
{
  // Code from view coordinates may leave vtkShadowViewToWorld unused, so
  // every program gets both (an unused name is a failed lookup, no more).
  SetViewToWorld(program, this->Renderer);
  if (this->Code && this->Code->Uniforms)
  {
    this->Code->Uniforms(program);
  }
}
