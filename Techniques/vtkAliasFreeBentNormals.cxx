// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAliasFreeBentNormals.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolygon.h"
#include "vtkProperty.h"
#include "vtkShaderProgram.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowStage.h"
#include "vtkShadowVTKVersion.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtkAliasFreeBendFS.h"
#include "vtkAliasFreeBendVS.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

namespace
{
// One polydata's point -> adjacent faces' normals, as texture buffers.
struct Adjacency
{
  vtkSmartPointer<vtkOpenGLBufferObject> OffsetsBuffer, NormalsBuffer;
  vtkSmartPointer<vtkTextureObject> Offsets, Normals;
  bool Ready = false;
};

// Newell's normal of a face (model space); false for faces of no area.
bool FaceNormal(vtkPoints* points, vtkIdType count, const vtkIdType* ids, float normal[4])
{
  double n[3];
  vtkPolygon::ComputeNormal(points, static_cast<int>(count), ids, n);
  if (!(std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2])) ||
    n[0] * n[0] + n[1] * n[1] + n[2] * n[2] < 0.5)
  {
    return false; // ComputeNormal leaves a zero normal for degenerate faces
  }
  for (int k = 0; k < 3; ++k)
  {
    normal[k] = static_cast<float>(n[k]);
  }
  normal[3] = 0.0f;
  return true;
}

// Calls face(count, ids) for every polygon and strip triangle (wound as
// the strip's first).
template <typename Face>
void ForEachFace(vtkPolyData* data, const Face& face)
{
  vtkIdType count;
  const vtkIdType* ids;
  vtkCellArray* polys = data->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    face(count, ids);
  }
  vtkCellArray* strips = data->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(count, ids);)
  {
    for (vtkIdType i = 0; i + 2 < count; ++i)
    {
      const vtkIdType triangle[3] = { ids[i], ids[i + (i % 2 ? 2 : 1)], ids[i + (i % 2 ? 1 : 2)] };
      face(3, triangle);
    }
  }
}

void Build(vtkPolyData* data, Adjacency& adjacency, vtkOpenGLRenderWindow* context)
{
  vtkPoints* points = data->GetPoints();
  const vtkIdType n = data->GetNumberOfPoints();
  if (!points || n == 0)
  {
    return;
  }
  // Each face's normal once (none for faces of no area or bad ids), then a
  // counting sort: each point's entries, the normals at their offsets.
  std::vector<std::array<float, 4>> faceNormals;
  std::vector<bool> kept;
  std::vector<int> offsets(static_cast<size_t>(n) + 1, 0);
  ForEachFace(data,
    [&](vtkIdType count, const vtkIdType* ids)
    {
      std::array<float, 4> normal;
      const bool keep =
        std::all_of(ids, ids + count, [n](vtkIdType id) { return id >= 0 && id < n; }) &&
        FaceNormal(points, count, ids, normal.data());
      kept.push_back(keep);
      faceNormals.push_back(normal);
      for (vtkIdType k = 0; keep && k < count; ++k)
      {
        ++offsets[ids[k] + 1];
      }
    });
  for (vtkIdType i = 0; i < n; ++i)
  {
    offsets[i + 1] += offsets[i];
  }
  const int entries = offsets[n];
  if (entries == 0)
  {
    return;
  }
  std::vector<float> normals(4 * static_cast<size_t>(entries));
  std::vector<int> next(offsets.begin(), offsets.end() - 1);
  size_t face = 0;
  ForEachFace(data,
    [&](vtkIdType count, const vtkIdType* ids)
    {
      for (vtkIdType k = 0; kept[face] && k < count; ++k)
      {
        std::memcpy(&normals[4 * static_cast<size_t>(next[ids[k]]++)], faceNormals[face].data(),
          sizeof(float) * 4);
      }
      ++face;
    });

  adjacency.OffsetsBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  adjacency.OffsetsBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  adjacency.NormalsBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  adjacency.NormalsBuffer->SetType(vtkOpenGLBufferObject::TextureBuffer);
  adjacency.Offsets = vtkSmartPointer<vtkTextureObject>::New();
  adjacency.Offsets->SetContext(context);
  adjacency.Normals = vtkSmartPointer<vtkTextureObject>::New();
  adjacency.Normals->SetContext(context);
  adjacency.Offsets->SetInternalFormat(GL_R32I); // read as integers (isamplerBuffer)
  adjacency.Normals->SetInternalFormat(GL_RGBA32F);
  adjacency.Ready =
    adjacency.OffsetsBuffer->Upload(offsets, vtkOpenGLBufferObject::TextureBuffer) &&
    adjacency.NormalsBuffer->Upload(normals, vtkOpenGLBufferObject::TextureBuffer) &&
    adjacency.Offsets->CreateTextureBuffer(
      static_cast<unsigned int>(offsets.size()), 1, VTK_INT, adjacency.OffsetsBuffer) &&
    adjacency.Normals->CreateTextureBuffer(
      static_cast<unsigned int>(entries), 4, VTK_FLOAT, adjacency.NormalsBuffer);
}
}

struct vtkAliasFreeBentNormals::Internals
{
  vtkShadowCasterCache<Adjacency> Cache;
  Adjacency* Active = nullptr;

  void Deactivate()
  {
    if (this->Active)
    {
      this->Active->Offsets->Deactivate();
      this->Active->Normals->Deactivate();
      this->Active = nullptr;
    }
  }
};

//------------------------------------------------------------------------------
vtkAliasFreeBentNormals::vtkAliasFreeBentNormals()
  : Internal(new Internals)
{
}

vtkAliasFreeBentNormals::~vtkAliasFreeBentNormals() = default;

//------------------------------------------------------------------------------
bool vtkAliasFreeBentNormals::Applies(const vtkShadowShaderSources& sources)
{
  // Exactly vtkOpenGLPolyDataMapper: its vertex buffer is its input's points
  // in order (gl_VertexID is the point id); point normals (normalMC) give
  // the interpolated shading that leaks; a geometry shader of its own
  // (edges, wide lines) would need the outputs passed through.
  auto* actor = vtkActor::SafeDownCast(sources.Prop);
  return sources.Mapper &&
    std::strcmp(sources.Mapper->GetClassName(), "vtkOpenGLPolyDataMapper") == 0 && actor &&
    actor->GetProperty()->GetInterpolation() != VTK_PBR &&
    sources.Vertex.find("normalMC") != std::string::npos &&
    sources.Geometry.find("main") == std::string::npos;
}

//------------------------------------------------------------------------------
std::string vtkAliasFreeBentNormals::VertexDeclarations(int lights)
{
  return "#define ALIASFREE_BEND_LIGHTS " + std::to_string(lights) + "\n" + vtkAliasFreeBendVS;
}

std::string vtkAliasFreeBentNormals::VertexImplementation()
{
  return "  aliasfreeBend(vertexMC);\n";
}

std::string vtkAliasFreeBentNormals::FragmentDeclarations(int lights)
{
  return "#define ALIASFREE_BEND_LIGHTS " + std::to_string(lights) + "\n" + vtkAliasFreeBendFS;
}

std::string vtkAliasFreeBentNormals::PhongScale(int slot)
{
  return "aliasfreeBentScale(df, aliasfreeBendVSOutput[" + std::to_string(slot) + "])";
}

//------------------------------------------------------------------------------
void vtkAliasFreeBentNormals::SetUniforms(vtkShaderProgram* program, vtkProp* prop,
  const std::vector<glm::vec4>& lights, vtkOpenGLRenderWindow* context)
{
  if (!program->IsUniformUsed("aliasfreeBendReady"))
  {
    return;
  }
  Internals& in = *this->Internal;
  auto* actor = vtkActor::SafeDownCast(prop);
  auto* mapper = actor ? vtkPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
  vtkPolyData* data = mapper ? mapper->GetInput() : nullptr;
  Adjacency* adjacency = nullptr;
  if (data)
  {
    vtkShadowCaster key;
    key.Data = data;
    adjacency =
      &in.Cache.Get(key, [context](vtkPolyData* d, Adjacency& value) { Build(d, value, context); });
  }
  const bool ready = adjacency && adjacency->Ready;
  if (ready && adjacency != in.Active)
  {
    in.Deactivate();
    adjacency->Offsets->Activate();
    adjacency->Normals->Activate();
    in.Active = adjacency;
  }
  program->SetUniformi("aliasfreeBendReady", ready ? 1 : 0);
  if (ready)
  {
    program->SetUniformi("aliasfreeBendOffsets", adjacency->Offsets->GetTextureUnit());
    program->SetUniformi("aliasfreeBendNormals", adjacency->Normals->GetTextureUnit());
  }
  // VTK's matrices are row-major: glm's column-major reading transposes.
  glm::dmat4 modelToWorld(1.0);
  if (actor)
  {
    modelToWorld = glm::transpose(glm::make_mat4(actor->GetMatrix()->GetData()));
  }
  const glm::mat4 m(modelToWorld);
  const glm::mat3 normals(glm::transpose(glm::inverse(glm::dmat3(modelToWorld))));
  program->SetUniformMatrix4x4("aliasfreeBendModelToWorld", const_cast<float*>(glm::value_ptr(m)));
  program->SetUniformMatrix3x3(
    "aliasfreeBendNormalToWorld", const_cast<float*>(glm::value_ptr(normals)));
  if (!lights.empty())
  {
    program->SetUniform4fv("aliasfreeBendLights", static_cast<int>(lights.size()),
      reinterpret_cast<const float(*)[4]>(glm::value_ptr(lights[0])));
  }
}

//------------------------------------------------------------------------------
void vtkAliasFreeBentNormals::EndFrame(const vtkShadowCasterRegistry& casters)
{
  this->Internal->Deactivate();
  this->Internal->Cache.Prune(casters);
}

//------------------------------------------------------------------------------
void vtkAliasFreeBentNormals::ReleaseGraphicsResources(vtkWindow*)
{
  this->Internal->Deactivate();
  this->Internal->Cache.Clear();
}
