// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowGeometry.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkShaderProgram.h"
#include "vtkShadowVTKVersion.h"

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
void vtkShadowGeometry::SetHalfFloat(bool half)
{
  if (half != this->HalfFloat)
  {
    this->HalfFloat = half;
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
    this->Primitives = 0;
  }
  this->BoundProgram = nullptr;
  this->VAO->ShaderProgramChanged();
  if (!this->Input)
  {
    return;
  }
  this->UploadTime = this->Input->GetMTime();
  const int divisor = this->Kind == Primitive::TriangleInstances ? 1 : 0;
  auto bind = [this, program, divisor]()
  {
    this->VAO->Bind();
    for (const Attribute& a : this->Attributes)
    {
      if (!program->IsAttributeUsed(a.Name.c_str()))
      {
        continue;
      }
      const int bytes = a.Half ? 2 : 4;
      this->VAO->AddAttributeArrayWithDivisor(program, a.Buffer, a.Name, 0, bytes * a.Components,
        a.Half ? VTK_UNSIGNED_SHORT : VTK_FLOAT, a.Components, false, divisor, false);
      const auto index = static_cast<GLuint>(program->FindAttributeArray(a.Name.c_str()));
      if (a.Half)
      {
        // VTK knows no half floats: the same buffer (still bound), read as such.
        glVertexAttribPointer(
          index, a.Components, GL_HALF_FLOAT, GL_FALSE, bytes * a.Components, nullptr);
      }
      // VTK sets only divisors above 0; a primitive changed may leave one.
      glVertexAttribDivisor(index, divisor);
    }
    this->VAO->Release();
    this->BoundProgram = program;
  };
  if (current && !this->MissesAttributes(program))
  {
    bind(); // another program of this geometry: its buffers serve
    return;
  }

  // The primitives' corners and cells, in order: every attribute expanded
  // alike (point data per corner, cell data per primitive).
  const bool lines = this->Kind == Primitive::LinesAdjacency;
  const vtkIdType size = this->CornersPerPrimitive();
  std::vector<vtkIdType> corners;
  std::vector<vtkIdType> faces;
  vtkCellArray* cells = lines ? this->Input->GetLines() : this->Input->GetPolys();
  // Cell ids run through vertices, lines, polygons and strips.
  vtkIdType cellId =
    this->Input->GetNumberOfVerts() + (lines ? 0 : this->Input->GetNumberOfLines());
  const vtkIdType numberOfPoints = this->Input->GetNumberOfPoints();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  bool reported = current; // the skipped cells were reported at the first upload
  for (cells->InitTraversal(); cells->GetNextCell(n, ids); ++cellId)
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
    if (!this->PerFace())
    {
      corners.insert(corners.end(), ids, ids + n);
    }
    faces.push_back(cellId);
  }
  this->Primitives = static_cast<int>(faces.size());
  const std::vector<vtkIdType>& tuples = this->PerFace() ? faces : corners;

  // Attributes the shaders do not use are neither uploaded nor bound; those
  // another program of this geometry uploaded stay.
  for (const Source& source : this->GetSources())
  {
    if (!program->IsAttributeUsed(source.Name.c_str()) || this->HasAttribute(source.Name))
    {
      continue;
    }
    Attribute attribute;
    attribute.Name = source.Name;
    attribute.Components = source.Components;
    attribute.Half = this->HalfFloat && source.Array->GetDataType() == VTK_UNSIGNED_SHORT;
    attribute.Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    attribute.Buffer->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    auto upload = [&](auto kind)
    {
      using Value = decltype(kind);
      std::vector<Value> values;
      values.reserve(tuples.size() * source.Components);
      for (vtkIdType id : tuples)
      {
        for (int c = 0; c < source.Components; ++c)
        {
          values.push_back(static_cast<Value>(source.Array->GetComponent(id, source.First + c)));
        }
      }
      if (!values.empty())
      {
        attribute.Buffer->Upload(values, vtkOpenGLBufferObject::ArrayBuffer);
      }
    };
    if (attribute.Half)
    {
      upload(static_cast<unsigned short>(0)); // the bits as they are
    }
    else
    {
      upload(0.0f);
    }
    this->Attributes.push_back(attribute);
  }
  bind();
}

//------------------------------------------------------------------------------
std::vector<vtkShadowGeometry::Source> vtkShadowGeometry::GetSources() const
{
  std::vector<Source> sources;
  if (this->Input->GetPoints() && !this->PerFace())
  {
    sources.push_back({ "vtkShadowVertexMC", this->Input->GetPoints()->GetData(), 0, 3 });
  }
  vtkFieldData* data = this->PerFace() ? static_cast<vtkFieldData*>(this->Input->GetCellData())
                                       : this->Input->GetPointData();
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = data->GetArray(a);
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
  // An attribute's values: one a corner, or one a face.
  const vtkIdType count = this->PerFace()
    ? this->Primitives
    : static_cast<vtkIdType>(this->Primitives) * this->CornersPerPrimitive();
  vtkIdType bytes = 0;
  for (const Attribute& a : this->Attributes)
  {
    bytes += (a.Half ? 2 : 4) * a.Components * count;
  }
  return bytes;
}

//------------------------------------------------------------------------------
bool vtkShadowGeometry::Draw(vtkOpenGLRenderWindow* context, const glm::dmat4& worldToClip)
{
  return this->Draw(context, worldToClip, this->ModelToWorld, this->Uniforms);
}

//------------------------------------------------------------------------------
bool vtkShadowGeometry::Draw(vtkOpenGLRenderWindow* context, const glm::dmat4& worldToClip,
  const glm::dmat4& placement, const std::function<void(vtkShaderProgram*)>& uniforms)
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
  if (this->Primitives == 0)
  {
    return true;
  }
  const glm::mat4 modelToClip(worldToClip * placement);
  const glm::mat4 modelToWorld(placement);
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
  if (uniforms)
  {
    uniforms(program);
  }
  this->VAO->Bind();
  // In batches, each waited for once the next is queued: a software
  // rasterizer otherwise queues every batch's binned primitives at once.
  const int batch = this->BatchSize > 0 && this->Kind != Primitive::TriangleInstances
    ? this->BatchSize
    : this->Primitives;
  GLsync before = nullptr;
  for (int first = 0; first < this->Primitives; first += batch)
  {
    const int count = std::min(batch, this->Primitives - first);
    switch (this->Kind)
    {
      case Primitive::Triangles:
        glDrawArrays(GL_TRIANGLES, 3 * first, 3 * count);
        break;
      case Primitive::TriangleInstances:
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, count);
        break;
      case Primitive::TrianglePoints:
        glDrawArrays(GL_POINTS, first, count);
        break;
      case Primitive::LinesAdjacency:
        glDrawArrays(GL_LINES_ADJACENCY, 4 * first, 4 * count);
        break;
    }
    if (count < this->Primitives)
    {
      GLsync queued = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
      if (before)
      {
        glClientWaitSync(before, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(10) * 1000000000);
        glDeleteSync(before);
      }
      before = queued;
    }
  }
  if (before)
  {
    glDeleteSync(before);
  }
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
