// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowMapperTwins.h"

#include "vtkActor.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"

#include <cstring>

namespace
{
// Draws dropped after this many draws without them: a scene's casters are
// drawn every frame, a few draws a frame.
const unsigned long KeptDraws = 64;

// The mapper of an actor that a twin can draw as VTK would, or null.
vtkMapper* TwinnableMapper(vtkProp* prop)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  if (!actor || std::strcmp(actor->GetClassName(), "vtkOpenGLActor") != 0 || actor->GetTexture() ||
    actor->GetBackfaceProperty() || actor->GetProperty()->GetNumberOfTextures() > 0)
  {
    return nullptr;
  }
  // A polydata mapper, or PyVista's vtkDataSetMapper, which draws polydata
  // as a polydata mapper would; small meshes only.
  vtkMapper* mapper = actor->GetMapper();
  auto* input = mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  if (!input || input->GetNumberOfPoints() > vtkShadowMapperTwins::GetMaximumPoints() ||
    (std::strcmp(mapper->GetClassName(), "vtkOpenGLPolyDataMapper") != 0 &&
      std::strcmp(mapper->GetClassName(), "vtkDataSetMapper") != 0))
  {
    return nullptr;
  }
  vtkShaderProperty* shaders = actor->GetShaderProperty();
  auto* replacing = vtkOpenGLShaderProperty::SafeDownCast(shaders);
  if (shaders->HasVertexShaderCode() || shaders->HasFragmentShaderCode() ||
    shaders->HasGeometryShaderCode() ||
    (replacing && !replacing->GetAllShaderReplacements().empty()))
  {
    return nullptr;
  }
  return mapper;
}
}

vtkShadowMapperTwins::vtkShadowMapperTwins() = default;
vtkShadowMapperTwins::~vtkShadowMapperTwins() = default;

//------------------------------------------------------------------------------
bool vtkShadowMapperTwins::RenderOpaqueGeometry(
  vtkProp* prop, vtkRenderer* renderer, const void* stage)
{
  vtkMapper* mapper = TwinnableMapper(prop);
  if (!mapper)
  {
    return false;
  }
  Twin& twin = this->Twins[{ mapper, stage }];
  if (!twin.Mapper || twin.Original != mapper)
  {
    twin = Twin();
    twin.Original = mapper;
    twin.Mapper = vtkSmartPointer<vtkOpenGLPolyDataMapper>::New();
  }
  if (twin.Copied != mapper->GetMTime())
  {
    // The input connection, colouring, clipping planes and pieces; the
    // offsets of coincident topology are the mapper's own. (Not
    // vtkOpenGLPolyDataMapper's own copy: its selection arrays play no part
    // here, and VTK 9.1's copies the deprecated shader code, with warnings.)
    twin.Mapper->vtkPolyDataMapper::ShallowCopy(mapper);
    if (!vtkPolyDataMapper::SafeDownCast(mapper)) // a vtkDataSetMapper of polydata
    {
      twin.Mapper->SetInputConnection(mapper->GetInputConnection(0, 0));
    }
    twin.Mapper->SetStatic(mapper->GetStatic());
    double factor = 0.0, units = 0.0;
    mapper->GetRelativeCoincidentTopologyPolygonOffsetParameters(factor, units);
    twin.Mapper->SetRelativeCoincidentTopologyPolygonOffsetParameters(factor, units);
    mapper->GetRelativeCoincidentTopologyLineOffsetParameters(factor, units);
    twin.Mapper->SetRelativeCoincidentTopologyLineOffsetParameters(factor, units);
    mapper->GetRelativeCoincidentTopologyPointOffsetParameter(units);
    twin.Mapper->SetRelativeCoincidentTopologyPointOffsetParameter(units);
    twin.Copied = mapper->GetMTime();
  }
  twin.LastDraw = this->Draws;

  // What vtkActor::RenderOpaqueGeometry() does for such an actor, with the twin.
  auto* actor = static_cast<vtkActor*>(prop);
  if (actor->HasOpaqueGeometry())
  {
    vtkProperty* property = actor->GetProperty();
    property->Render(actor, renderer);
    actor->Render(renderer, twin.Mapper);
    property->PostRender(actor, renderer);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowMapperTwins::EndDraw()
{
  ++this->Draws;
  for (auto it = this->Twins.begin(); it != this->Twins.end();)
  {
    if (!it->second.Original || this->Draws - it->second.LastDraw > KeptDraws)
    {
      it = this->Twins.erase(it); // its buffers go with it
    }
    else
    {
      ++it;
    }
  }
}

//------------------------------------------------------------------------------
void vtkShadowMapperTwins::ReleaseGraphicsResources(vtkWindow* w)
{
  for (auto& twin : this->Twins)
  {
    twin.second.Mapper->ReleaseGraphicsResources(w);
  }
  this->Twins.clear();
}
