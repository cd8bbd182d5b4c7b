// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowDistanceStage.h"

#include "vtkShaderProgram.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowMapperCode.h"
#include "vtkTextureObject.h"

#include "vtkShadowCubeDistanceFS.h"
#include "vtkShadowCubeLookupFS.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>

namespace
{
const char* const FaceDepthTag = "//VTK::SoftShadow::FaceDepth";
}

//------------------------------------------------------------------------------
void vtkShadowDistanceStage::Begin(const vtkShadowDrawSetup& setup)
{
  // Layered draws run the vertex shader for face 0; all faces share the eye.
  const auto& face = setup.Faces ? (*setup.Faces)[std::max(setup.CubeFace, 0)] : *setup.View;
  const glm::mat4 clipToView(glm::inverse(face.Projection));
  std::copy(glm::value_ptr(clipToView), glm::value_ptr(clipToView) + 16, this->FaceClipToView);
  this->FaceSize = static_cast<float>(setup.Colours[0]->GetWidth());
  this->FaceRange =
    this->Packed && !this->LinearDepth ? static_cast<float>(face.Far * face.Far) : 0.0f;
}

//------------------------------------------------------------------------------
void vtkShadowDistanceStage::PreReplace(vtkShadowShaderSources& sources)
{
  using namespace vtkShadowMapperCode;
  sources.Require(sources.Fragment, LightDec,
    std::string(vtkShadowCubeLookupFS) + "\n" + vtkShadowCubeDistanceFS + "\n" + LightDec,
    "cube-map distances");
  sources.Require(sources.Fragment, LightImpl,
    std::string("float vtkShadowWindowDepth = gl_FragCoord.z;\n  ") + FaceDepthTag +
      "\n  gl_FragData[0] = vtkShadowFaceDistance(vtkShadowWindowDepth);\n  return;\n  " +
      LightImpl,
    "cube-map distances");
}

//------------------------------------------------------------------------------
void vtkShadowDistanceStage::PostReplace(vtkShadowShaderSources& sources)
{
  // Imposters (sphere and stick mappers) ray-cast their surface and write
  // its depth before the lighting code: their distance is that surface's,
  // not their sprite's or box's. Points drawn as spheres and lines as tubes
  // move only their depth and are kept flat, as in the depth stage.
  std::string& fragment = sources.Fragment;
  const size_t tag = fragment.find(FaceDepthTag);
  const bool imposter = tag != std::string::npos &&
    fragment.rfind("gl_FragDepth =", tag) != std::string::npos &&
    !vtkShadowMapperCode::MovesDepthOnly(fragment);
  vtkShaderProgram::Substitute(
    fragment, FaceDepthTag, imposter ? "vtkShadowWindowDepth = gl_FragDepth;" : "", false);
}

//------------------------------------------------------------------------------
void vtkShadowDistanceStage::SetUniforms(vtkShaderProgram* program, vtkProp*)
{
  program->SetUniformMatrix4x4("vtkShadowFaceClipToView", this->FaceClipToView);
  program->SetUniformf("vtkShadowFaceSize", this->FaceSize);
  program->SetUniformf("vtkShadowFaceRange", this->FaceRange);
  program->SetUniformi("vtkShadowFaceLinear", this->LinearDepth ? 1 : 0);
  program->SetUniformf("vtkShadowFaceSlopeBias", this->SlopeBias);
}
