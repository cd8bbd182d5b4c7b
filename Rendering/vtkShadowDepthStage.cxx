// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowDepthStage.h"

#include "vtkShaderProgram.h"
#include "vtkShadowMapperCode.h"

namespace
{
const char* const SpriteDepthTag = "//VTK::SoftShadow::SpriteDepth";
}

//------------------------------------------------------------------------------
void vtkShadowDepthStage::PreReplace(vtkShadowShaderSources& sources)
{
  // Clipping and depth code come before the lighting code. A shader without
  // the tag (a custom one) still draws its depth, only slower.
  vtkShadowShaderSources::Before(sources.Fragment, vtkShadowMapperCode::LightImpl,
    std::string(SpriteDepthTag) + "\n  gl_FragData[0] = vec4(1.0);\n  return;");
}

//------------------------------------------------------------------------------
void vtkShadowDepthStage::PostReplace(vtkShadowShaderSources& sources)
{
  // Known only once the mapper has written its representation's code.
  const bool flatten = this->LightSpace && vtkShadowMapperCode::MovesDepthOnly(sources.Fragment);
  vtkShaderProgram::Substitute(
    sources.Fragment, SpriteDepthTag, flatten ? "gl_FragDepth = gl_FragCoord.z;" : "", false);
}
