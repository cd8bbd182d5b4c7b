#include "vtkShadowShaderHooks.h"

#include "vtkAbstractMapper.h"
#include "vtkObjectFactory.h"
#include "vtkShaderProgram.h"
#include "vtkShadowStage.h"

#include "vtkShadowCubeLayersGS.h"

vtkStandardNewMacro(vtkShadowShaderHooks);

vtkShadowShaderHooks::vtkShadowShaderHooks() = default;
vtkShadowShaderHooks::~vtkShadowShaderHooks() = default;

//------------------------------------------------------------------------------
void vtkShadowShaderHooks::SetStage(vtkShadowStage* stage, const float (*faceFromFirst)[16])
{
  if (stage != this->Stage || faceFromFirst != this->FaceFromFirst)
  {
    this->Stage = stage;
    this->FaceFromFirst = faceFromFirst;
    this->StageTime.Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkShadowShaderHooks::PreReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper,
  vtkProp* prop)
{
  if (!this->Stage)
  {
    return true;
  }
  vtkShadowShaderSources sources(vertexShader, geometryShader, fragmentShader, mapper, prop);
  if (this->FaceFromFirst)
  {
    // Edges or wide lines already use the one geometry shader slot.
    if (geometryShader.empty())
    {
      geometryShader = vtkShadowCubeLayersGS;
    }
    else
    {
      sources.AddMiss("it has a geometry shader of its own (edges or wide lines), so it casts "
                      "into one face of a point light's cube map only; turn SinglePassCubeMaps "
                      "off for such scenes");
    }
  }
  this->Stage->PreReplace(sources);
  this->Report(sources);
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowShaderHooks::PostReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper* mapper,
  vtkProp* prop)
{
  if (this->Stage)
  {
    vtkShadowShaderSources sources(vertexShader, geometryShader, fragmentShader, mapper, prop);
    this->Stage->PostReplace(sources);
    this->Report(sources);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowShaderHooks::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (this->FaceFromFirst)
  {
    program->SetUniformMatrix4x4v(
      "vtkShadowFaceFromFirst", 6, const_cast<float*>(&this->FaceFromFirst[0][0]));
  }
  if (this->Stage)
  {
    this->Stage->SetUniforms(program, prop);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowShaderHooks::Report(vtkShadowShaderSources& sources)
{
  const std::string mapper = sources.Mapper ? sources.Mapper->GetClassName() : "(no mapper)";
  for (const std::string& what : sources.GetMisses())
  {
    if (this->Reported.insert({ mapper, what }).second)
    {
      vtkWarningMacro(<< mapper << ": " << what << ".");
    }
  }
}

//------------------------------------------------------------------------------
void vtkShadowShaderHooks::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Stage: " << (this->Stage ? "active" : "(none)") << "\n";
  os << indent << "Layered: " << (this->FaceFromFirst ? "yes" : "no") << "\n";
}
