// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowShaderHooks.h"

#include "vtkAbstractMapper.h"
#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapperCode.h"
#include "vtkShadowStage.h"
#include "vtkShadowVTKVersion.h"

#include "vtkShadowCubeLayersGS.h"

#include <cstdlib>
#include <functional>

namespace
{
// A shader cache of its own, only to learn why a program failed: VTK's
// vtkShaderProgram::CompileShader() reports it by vtkErrorMacro (the whole
// numbered source, then OpenGL's log), which an ErrorEvent observer on the
// program receives instead of the output window. The window's cache creates
// its programs inside ReadyShaderProgram(), before anyone could observe
// them; this one observes each program it creates. Same text replacements,
// same compile, VTK's code.
class vtkShadowShaderLog : public vtkShadowObservedShaderCache
{
public:
  static vtkShadowShaderLog* New();
  vtkTypeMacro(vtkShadowShaderLog, vtkOpenGLShaderCache);
  std::vector<std::string> Errors;

protected:
  void Created(vtkShaderProgram* program) override
  {
    vtkNew<vtkCallbackCommand> keep;
    keep->SetClientData(&this->Errors);
    keep->SetCallback(
      [](vtkObject*, unsigned long, void* errors, void* text) {
        static_cast<std::vector<std::string>*>(errors)->emplace_back(
          static_cast<const char*>(text));
      });
    program->AddObserver(vtkCommand::ErrorEvent, keep);
  }
};
vtkStandardNewMacro(vtkShadowShaderLog);

// "ERROR: In file, line N\nvtkShaderProgram (0x...): Links failed: error: ...\n\n"
// without VTK's prefixes.
std::string MessageBody(std::string text)
{
  const auto header = text.find('\n');
  text = header == std::string::npos ? text : text.substr(header + 1);
  const auto object = text.find("): ");
  text = object == std::string::npos ? text : text.substr(object + 3);
  const std::string links = "Links failed: ";
  if (text.compare(0, links.size(), links) == 0)
  {
    text = text.substr(links.size());
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  return text;
}

bool DebugShaders()
{
  const char* value = std::getenv("SOFTSHADOWS_DEBUG_SHADERS");
  return value && *value && std::string(value) != "0";
}

// Whether the sources the hooks see are those the mapper compiles: a
// vtkOpenGLPolyDataMapper (and its subclasses, which edit before calling
// it) compiles right after the render passes' PostReplace, unless its
// actor's shader property has replacements of its own to make after them.
bool FinalAfterHooks(vtkAbstractMapper* mapper, vtkProp* prop)
{
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
  {
    return false;
  }
  auto* actor = vtkActor::SafeDownCast(prop);
  auto* property =
    actor ? vtkOpenGLShaderProperty::SafeDownCast(actor->GetShaderProperty()) : nullptr;
  if (property)
  {
    for (const auto& replacement : property->GetAllShaderReplacements())
    {
      if (!replacement.first.ReplaceFirst)
      {
        return false;
      }
    }
  }
  return true;
}
}

vtkStandardNewMacro(vtkShadowShaderHooks);

vtkShadowShaderHooks::vtkShadowShaderHooks() = default;
vtkShadowShaderHooks::~vtkShadowShaderHooks() = default;

//------------------------------------------------------------------------------
void vtkShadowShaderHooks::SetStage(vtkShadowStage* stage, const float (*faceFromFirst)[16])
{
  this->Stage = stage;
  this->FaceFromFirst = faceFromFirst;
  if (!stage)
  {
    return; // between draws: no mapper builds through these hooks
  }
  // The mappers build their programs again only when the code would change:
  // another stage, another key, layered or not.
  std::string key;
  const bool keyed = stage->GetCodeKey(key);
  key += faceFromFirst ? "\nlayered" : "\nflat";
  if (!keyed || stage != this->KeyedStage || key != this->Key)
  {
    this->StageTime.Modified();
  }
  this->KeyedStage = keyed ? stage : nullptr;
  this->Key = keyed ? key : std::string();
}

//------------------------------------------------------------------------------
void vtkShadowShaderHooks::Attach(const vtkRenderState* s)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  if (window != this->Window)
  {
    this->Compiled.clear(); // compiled in another window's context
    this->Window = window;
  }
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
  if (!this->Stage)
  {
    return true;
  }
  vtkShadowShaderSources sources(vertexShader, geometryShader, fragmentShader, mapper, prop);
  const std::string vertex = vertexShader, geometry = geometryShader, fragment = fragmentShader;
  this->Stage->PostReplace(sources);
  this->Report(sources);
  if (!this->Window || !FinalAfterHooks(mapper, prop))
  {
    return true;
  }

  // Three hashes combined, as boost::hash_combine does, rather than one of a
  // concatenated copy.
  size_t hash = 0;
  for (const std::string* source : { &vertexShader, &geometryShader, &fragmentShader })
  {
    hash ^= std::hash<std::string>()(*source) + 0x9e3779b9 + (hash << 6) + (hash >> 2);
  }
  auto known = this->Compiled.find(hash);
  if (known != this->Compiled.end() && known->second)
  {
    return true;
  }
  if (known == this->Compiled.end())
  {
    std::string log, details;
    const bool compiles = this->Compiles(sources, &log, &details);
    this->Compiled[hash] = compiles;
    if (compiles)
    {
      return true;
    }
    vtkObject* owner = this->Owner ? this->Owner : this;
    std::string message = "The shader of " + this->Stage->GetName() + " for " +
      (mapper ? mapper->GetClassName() : "a mapper") +
      " does not compile or link: " + log.substr(0, log.find('\n')) +
      "; it is drawn without shadows.";
    if (DebugShaders())
    {
      message += "\n" + details;
    }
    else
    {
      message += " (SOFTSHADOWS_DEBUG_SHADERS=1 shows its source.)";
    }
    vtkErrorWithObjectMacro(owner, << message);
  }
  // As the mapper's code was before the stage's: plain VTK drawing.
  vertexShader = vertex;
  geometryShader = geometry;
  fragmentShader = fragment;
  for (std::string* source : { &vertexShader, &geometryShader, &fragmentShader })
  {
    vtkShaderProgram::Substitute(*source, vtkShadowMapperCode::ShadowDec, "", false);
    vtkShaderProgram::Substitute(*source, vtkShadowMapperCode::ShadowImpl, "", false);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowShaderHooks::ReleaseGraphicsResources(vtkWindow* w)
{
  // The window's cache forgets its programs: the next build compiles again.
  this->Compiled.clear();
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
bool vtkShadowShaderHooks::Compiles(
  const vtkShadowShaderSources& sources, std::string* log, std::string* details)
{
  // Through the window's own cache, where the mapper finds it compiled next,
  // with VTK's warning display off for that one call: a failure there prints
  // the whole numbered source.
  const int display = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  vtkShaderProgram* program = this->Window->GetShaderCache()->ReadyShaderProgram(
    sources.Vertex.c_str(), sources.Fragment.c_str(), sources.Geometry.c_str());
  vtkObject::SetGlobalWarningDisplay(display);
  if (program)
  {
    return true;
  }
  // Why: the same compile again, its errors observed (the numbered source
  // of a shader that does not compile, then OpenGL's log; a link's log).
  vtkNew<vtkShadowShaderLog> again;
  again->ReadyShaderProgram(
    sources.Vertex.c_str(), sources.Fragment.c_str(), sources.Geometry.c_str());
  again->ReleaseGraphicsResources(this->Window);
  this->Window->GetShaderCache()->ClearLastShaderBound(); // in case it bound one after all
  details->clear();
  for (const std::string& error : again->Errors)
  {
    *details += MessageBody(error) + "\n";
  }
  *log = again->Errors.empty() ? std::string("(no log)") : MessageBody(again->Errors.back());
  return false;
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
