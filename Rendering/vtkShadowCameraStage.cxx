// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowCameraStage.h"

#include "vtkShaderProgram.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowMapperCode.h"

#include "vtkShadowSurfaceFS.h"

#include <algorithm>

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
  // fragments write 0.
  std::string dec, impl;
  if (this->Targets > 0 && sources.IsLit())
  {
    dec = std::string(vtkShadowSurfaceFS) + "\n" + this->Code->Declarations;
    impl = sources.GetSurfaceCode() + this->Code->Implementation;
  }
  else
  {
    for (int i = 0; i < std::max(this->Targets, 1); ++i)
    {
      impl += "  gl_FragData[" + std::to_string(i) + "] = vec4(0.0);\n";
    }
  }
  sources.Require(sources.Fragment, vtkShadowMapperCode::ShadowDec, dec, "the camera pass");
  sources.Require(sources.Fragment, vtkShadowMapperCode::ShadowImpl, impl, "the camera pass");
}

//------------------------------------------------------------------------------
bool vtkShadowCameraStage::GetCodeKey(std::string& key) const
{
  key = std::to_string(this->Targets);
  if (this->Code)
  {
    key += "\n" + this->Code->Declarations + "\n" + this->Code->Implementation;
  }
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
