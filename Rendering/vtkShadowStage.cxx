#include "vtkShadowStage.h"

#include "vtkShaderProgram.h"
#include "vtkShadowMapperCode.h"

vtkShadowStage::~vtkShadowStage() = default;

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
