// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowGeometry.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

vtkShadowGeometry::vtkShadowGeometry() = default;
vtkShadowGeometry::~vtkShadowGeometry() = default;

//------------------------------------------------------------------------------
std::shared_ptr<vtkShadowGeometry> vtkShadowGeometry::NewShared()
{
  return std::shared_ptr<vtkShadowGeometry>(new vtkShadowGeometry,
    [](vtkShadowGeometry* geometry)
    {
      geometry->ReleaseGraphicsResources(nullptr);
      delete geometry;
    });
}

//------------------------------------------------------------------------------
void vtkShadowGeometry::SetInput(vtkPolyData* data)
{
  if (data != this->Input)
  {
    this->Input = data;
    this->UploadTime = 0;
  }
}

//------------------------------------------------------------------------------
void vtkShadowGeometry::SetPrimitive(Primitive primitive)
{
  if (primitive != this->Kind)
  {
    this->Kind = primitive;
    this->UploadTime = 0;
  }
}

//------------------------------------------------------------------------------
void vtkShadowGeometry::SetShaders(
  const std::string& vertex, const std::string& fragment, const std::string& geometry)
{
  this->VertexShader = vertex;
  this->FragmentShader = fragment;
  this->GeometryShader = geometry;
}

//------------------------------------------------------------------------------
std::string vtkShadowGeometry::WithPrefix(const std::string& source, const std::string& prefix)
{
  const std::string tag = "//VTK::System::Dec";
  std::string text = source;
  text.insert(text.find(tag) + tag.size(), "\n" + prefix);
  return text;
}

//------------------------------------------------------------------------------
void vtkShadowGeometry::Upload(vtkShaderProgram* program)
{
  const bool current = this->Input && this->UploadTime >= this->Input->GetMTime() && this->VAO;
  if (current && program == this->BoundProgram)
  {
    return;
  }
  if (!this->VAO)
  {
    this->VAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  }
  if (!current)
  {
    this->Attributes.clear();
    this->Vertices = 0;
  }
  this->BoundProgram = nullptr;
  this->VAO->ShaderProgramChanged();
  if (!this->Input)
  {
    return;
  }
  this->UploadTime = this->Input->GetMTime();
  auto bind = [this, program]()
  {
    this->VAO->Bind();
    for (const Attribute& a : this->Attributes)
    {
      if (program->IsAttributeUsed(a.Name.c_str()))
      {
        this->VAO->AddAttributeArray(program, a.Buffer, a.Name, 0, sizeof(float) * a.Components,
          VTK_FLOAT, a.Components, false);
      }
    }
    this->VAO->Release();
    this->BoundProgram = program;
  };
  if (current && !this->MissesAttributes(program))
  {
    bind(); // another program of this geometry: its buffers serve
    return;
  }

  // The primitives' corners, in order: every attribute expanded alike.
  const bool lines = this->Kind == Primitive::LinesAdjacency;
  const vtkIdType size = lines ? 4 : 3;
  std::vector<vtkIdType> corners;
  vtkCellArray* cells = lines ? this->Input->GetLines() : this->Input->GetPolys();
  const vtkIdType numberOfPoints = this->Input->GetNumberOfPoints();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  bool reported = current; // the skipped cells were reported at the first upload
  for (cells->InitTraversal(); cells->GetNextCell(n, ids);)
  {
    if (n != size)
    {
      continue; // triangles (or 4-point lines) only
    }
    if (std::any_of(
          ids, ids + n, [numberOfPoints](vtkIdType id) { return id < 0 || id >= numberOfPoints; }))
    {
      if (!reported)
      {
        vtkGenericWarningMacro("vtkShadowGeometry: a cell names a point that does not exist; "
                               "it is skipped.");
        reported = true;
      }
      continue;
    }
    corners.insert(corners.end(), ids, ids + n);
  }
  this->Vertices = static_cast<int>(corners.size());

  // Attributes the shaders do not use are neither uploaded nor bound; those
  // another program of this geometry uploaded stay.
  for (const Source& source : this->GetSources())
  {
    if (!program->IsAttributeUsed(source.Name.c_str()) || this->HasAttribute(source.Name))
    {
      continue;
    }
    std::vector<float> values;
    values.reserve(corners.size() * source.Components);
    for (vtkIdType id : corners)
    {
      for (int c = 0; c < source.Components; ++c)
      {
        values.push_back(static_cast<float>(source.Array->GetComponent(id, source.First + c)));
      }
    }
    Attribute attribute;
    attribute.Name = source.Name;
    attribute.Components = source.Components;
    attribute.Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    attribute.Buffer->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    if (!values.empty())
    {
      attribute.Buffer->Upload(values, vtkOpenGLBufferObject::ArrayBuffer);
    }
    this->Attributes.push_back(attribute);
  }
  bind();
}

//------------------------------------------------------------------------------
std::vector<vtkShadowGeometry::Source> vtkShadowGeometry::GetSources() const
{
  std::vector<Source> sources;
  if (this->Input->GetPoints())
  {
    sources.push_back({ "vtkShadowVertexMC", this->Input->GetPoints()->GetData(), 0, 3 });
  }
  vtkPointData* pd = this->Input->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = pd->GetArray(a);
    if (!array || !array->GetName())
    {
      continue;
    }
    const int components = array->GetNumberOfComponents();
    if (components == 9)
    {
      for (int k = 0; k < 3; ++k)
      {
        sources.push_back({ std::string(array->GetName()) + std::to_string(k), array, 3 * k, 3 });
      }
    }
    else if (components >= 1 && components <= 4)
    {
      sources.push_back({ array->GetName(), array, 0, components });
    }
  }
  return sources;
}

//------------------------------------------------------------------------------
bool vtkShadowGeometry::HasAttribute(const std::string& name) const
{
  return std::any_of(this->Attributes.begin(), this->Attributes.end(),
    [&name](const Attribute& a) { return a.Name == name; });
}

//------------------------------------------------------------------------------
bool vtkShadowGeometry::MissesAttributes(vtkShaderProgram* program) const
{
  const std::vector<Source> sources = this->GetSources();
  return std::any_of(sources.begin(), sources.end(),
    [this, program](const Source& source)
    { return program->IsAttributeUsed(source.Name.c_str()) && !this->HasAttribute(source.Name); });
}

//------------------------------------------------------------------------------
vtkIdType vtkShadowGeometry::GetUploadedBytes() const
{
  vtkIdType bytes = 0;
  for (const Attribute& a : this->Attributes)
  {
    bytes += static_cast<vtkIdType>(sizeof(float)) * a.Components * this->Vertices;
  }
  return bytes;
}

//------------------------------------------------------------------------------
bool vtkShadowGeometry::Draw(vtkOpenGLRenderWindow* context, const glm::dmat4& worldToClip)
{
  if (!this->Input ||
    (this->Kind == Primitive::LinesAdjacency ? this->Input->GetNumberOfLines()
                                             : this->Input->GetNumberOfPolys()) == 0)
  {
    return true; // nothing to draw
  }
  vtkShaderProgram* program = context->GetShaderCache()->ReadyShaderProgram(
    this->VertexShader.c_str(), this->FragmentShader.c_str(), this->GeometryShader.c_str());
  if (!program)
  {
    return false;
  }
  this->Upload(program);
  if (this->Vertices == 0)
  {
    return true;
  }
  const glm::mat4 modelToClip(worldToClip * this->ModelToWorld);
  const glm::mat4 modelToWorld(this->ModelToWorld);
  if (program->IsUniformUsed("vtkShadowModelToClip"))
  {
    program->SetUniformMatrix4x4(
      "vtkShadowModelToClip", const_cast<float*>(glm::value_ptr(modelToClip)));
  }
  if (program->IsUniformUsed("vtkShadowModelToWorld"))
  {
    program->SetUniformMatrix4x4(
      "vtkShadowModelToWorld", const_cast<float*>(glm::value_ptr(modelToWorld)));
  }
  if (this->Uniforms)
  {
    this->Uniforms(program);
  }
  this->VAO->Bind();
  glDrawArrays(
    this->Kind == Primitive::LinesAdjacency ? GL_LINES_ADJACENCY : GL_TRIANGLES, 0, this->Vertices);
  this->VAO->Release();
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowGeometry::ReleaseGraphicsResources(vtkWindow*)
{
  for (Attribute& a : this->Attributes)
  {
    a.Buffer->ReleaseGraphicsResources();
  }
  this->Attributes.clear();
  if (this->VAO)
  {
    this->VAO->ReleaseGraphicsResources();
  }
  this->VAO = nullptr;
  this->BoundProgram = nullptr;
  this->UploadTime = 0;
}
