// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowStage.h"

#include "vtkCamera.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapperCode.h"
#include "vtkShadowMatrices.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>

vtkShadowStage::~vtkShadowStage() = default;

//------------------------------------------------------------------------------
void vtkShadowStage::SetViewToWorld(vtkShaderProgram* program, vtkRenderer* renderer)
{
  glm::mat4 viewToWorld(vtkShadowMatrices::ViewToWorld(renderer->GetActiveCamera()));
  program->SetUniformMatrix4x4("vtkShadowViewToWorld", glm::value_ptr(viewToWorld));
}

//------------------------------------------------------------------------------
std::string vtkShadowShaderSources::GetSurfaceCode() const
{
  const bool computed = this->Fragment.find("vec4 vertexVC") != std::string::npos;
  const bool shaded = this->Fragment.find("normalVCVSOutput") != std::string::npos;
  // What a stage does not read, the compiler drops.
  return std::string("  vec3 vtkShadowPositionVC = ") +
    (computed ? "vertexVC.xyz" : "vertexVCVSOutput.xyz") +
    ";\n"
    "  vec3 vtkShadowFaceVC;\n"
    "  bool vtkShadowFaceDefined = vtkShadowFace(vtkShadowPositionVC, " +
    (shaded ? "normalVCVSOutput" : "vec3(0.0, 0.0, 1.0)") + ", " +
    (vtkShadowMapperCode::MovesDepthOnly(this->Fragment) ? "true" : "false") +
    ", vtkShadowFaceVC);\n"
    "  vec3 vtkShadowNormalVC = normalize(vtkShadowFaceVC);\n"
    "  vec4 vtkShadowPositionWC = vtkShadowViewToWorld * vec4(vtkShadowPositionVC, 1.0);\n"
    "  vec3 vtkShadowNormalWC = normalize(mat3(vtkShadowViewToWorld) * vtkShadowFaceVC);\n";
}

//------------------------------------------------------------------------------
bool vtkShadowShaderSources::Before(
  std::string& source, const std::string& tag, const std::string& code)
{
  return vtkShaderProgram::Substitute(source, tag, code + "\n" + tag, false);
}

//------------------------------------------------------------------------------
bool vtkShadowShaderSources::Require(std::string& source, const std::string& tag,
  const std::string& code, const std::string& what, bool all)
{
  const bool found = vtkShaderProgram::Substitute(source, tag, code, all);
  if (!found)
  {
    this->AddMiss("its shader lacks the code the shadows edit for " + what +
      ", so its actors are drawn without it (a custom shader replacement, or mapper code other "
      "than vtkShadowMapperCode.h expects)");
  }
  return found;
}

//------------------------------------------------------------------------------
void vtkShadowShaderSources::AddFragmentExtension(const std::string& extension)
{
  this->Require(this->Fragment, vtkShadowMapperCode::SystemDec,
    std::string(vtkShadowMapperCode::SystemDec) + "\n#extension " + extension + " : enable",
    "the extension " + extension);
}

//------------------------------------------------------------------------------
bool vtkShadowShaderSources::IsLit() const
{
  return vtkShadowMapperCode::IsLit(this->Fragment);
}

//------------------------------------------------------------------------------
int vtkShadowShaderSources::CountTextures() const
{
  int count = 0;
  for (const std::string* source : { &this->Vertex, &this->Geometry, &this->Fragment })
  {
    const std::string& text = *source;
    auto skipSpace = [&](size_t i)
    {
      while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])))
      {
        ++i;
      }
      return i;
    };
    auto word = [&](size_t& i)
    {
      const size_t start = i;
      while (
        i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_'))
      {
        ++i;
      }
      return text.substr(start, i - start);
    };
    // "uniform [precision] [iu]sampler<kind> name [N];"
    for (size_t at = text.find("uniform"); at != std::string::npos;
         at = text.find("uniform", at + 7))
    {
      size_t i = skipSpace(at + 7);
      std::string type = word(i);
      if (type == "lowp" || type == "mediump" || type == "highp")
      {
        i = skipSpace(i);
        type = word(i);
      }
      if (type.find("sampler") == std::string::npos)
      {
        continue;
      }
      i = skipSpace(i);
      word(i);
      i = skipSpace(i);
      const bool array = i < text.size() && text[i] == '[';
      count += array ? std::max(1, std::atoi(text.c_str() + i + 1)) : 1;
    }
  }
  return count;
}
