#include "vtkShadowShaderHooks.h"

#include "vtkAbstractMapper.h"
#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
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
void vtkShadowShaderHooks::Attach(const vtkRenderState* s)
{
  this->PreRender(s);
  vtkNew<vtkPropCollection> parts;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (vtkActor::SafeDownCast(prop))
    {
      continue;
    }
    parts->RemoveAllItems();
    prop->GetActors(parts);
    vtkCollectionSimpleIterator it;
    parts->InitTraversal(it);
    while (vtkProp* part = parts->GetNextProp(it))
    {
      vtkInformation* keys = part->GetPropertyKeys();
      if (part == prop || (keys && keys == prop->GetPropertyKeys()))
      {
        continue;
      }
      if (!keys)
      {
        vtkNew<vtkInformation> created;
        part->SetPropertyKeys(created);
        keys = created;
      }
      vtkInformationObjectBaseVectorKey* key = vtkOpenGLRenderPass::RenderPasses();
      bool registered = false;
      for (int k = 0; k < keys->Length(key); ++k)
      {
        registered = registered || keys->Get(key, k) == this;
      }
      if (!registered)
      {
        keys->Append(key, this);
        this->PartKeys.emplace_back(keys);
      }
    }
  }
}

void vtkShadowShaderHooks::Detach(const vtkRenderState* s)
{
  vtkInformationObjectBaseVectorKey* key = vtkOpenGLRenderPass::RenderPasses();
  for (vtkInformation* keys : this->PartKeys)
  {
    keys->Remove(key, this);
    if (keys->Length(key) == 0)
    {
      keys->Remove(key);
    }
  }
  this->PartKeys.clear();
  this->PostRender(s);
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
