// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowCasterRegistry.h"

#include "vtkCleanPolyData.h"
#include "vtkNew.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkDataSetMapper.h"
#include "vtkGlyph3DMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkProperty.h"
#include "vtkRange.h"
#include "vtkRenderer.h"
#include "vtkShadowGlyphInstances.h"
#include "vtkShadowMatrices.h"
#include "vtkShadowVTKVersion.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowsMeshCheck.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <string> // for std::string

//------------------------------------------------------------------------------
glm::dvec3 vtkShadowCaster::PointToModel(const glm::dvec3& world) const
{
  return glm::dvec3(this->WorldToModel * glm::dvec4(world, 1.0));
}

//------------------------------------------------------------------------------
glm::dvec3 vtkShadowCaster::DirectionToModel(const glm::dvec3& world) const
{
  return glm::normalize(glm::dvec3(this->WorldToModel * glm::dvec4(world, 0.0)));
}

//------------------------------------------------------------------------------
glm::dvec4 vtkShadowCaster::LightToModel(const glm::dvec4& light) const
{
  const glm::dvec3 xyz(light);
  return light.w == 0.0 ? glm::dvec4(this->DirectionToModel(xyz), 0.0)
                        : glm::dvec4(this->PointToModel(xyz), 1.0);
}

//------------------------------------------------------------------------------
vtkShadowCasterRegistry::vtkShadowCasterRegistry()
  : Glyphs(new vtkShadowGlyphInstances)
{
}

vtkShadowCasterRegistry::~vtkShadowCasterRegistry() = default;

//------------------------------------------------------------------------------
void vtkShadowCasterRegistry::AddBlocks(vtkDataObject* node, bool visible, bool opaque,
  unsigned int& flatIndex, vtkCompositeDataDisplayAttributes* attributes,
  const vtkShadowCaster& actor)
{
  // Flat indices count every node, empty ones too, depth first, as the
  // composite mapper's do; a block's visibility and opacity are inherited
  // by its children, and its own replace them.
  const unsigned int index = flatIndex++;
  if (!node)
  {
    return;
  }
  if (attributes && attributes->HasBlockVisibility(node))
  {
    visible = attributes->GetBlockVisibility(node);
  }
  if (attributes && attributes->HasBlockOpacity(node))
  {
    opaque = attributes->GetBlockOpacity(node) >= 1.0;
  }
  if (auto* tree = vtkDataObjectTree::SafeDownCast(node))
  {
    // Its direct children, empty ones too.
    for (vtkDataObject* child : vtk::Range(tree, vtk::DataObjectTreeOptions::None))
    {
      this->AddBlocks(child, visible, opaque, flatIndex, attributes, actor);
    }
    return;
  }
  auto* data = vtkPolyData::SafeDownCast(node);
  if (data && visible)
  {
    vtkShadowCaster block = actor;
    block.Data = data;
    block.FlatIndex = index;
    this->AddCaster(block, opaque);
  }
}

//------------------------------------------------------------------------------
void vtkShadowCasterRegistry::AddCaster(vtkShadowCaster caster, bool opaque)
{
  Checked& check = this->Checks[caster.Data];
  if (check.Data != caster.Data || check.Time != caster.Data->GetMTime())
  {
    check.Data = caster.Data;
    check.Time = caster.Data->GetMTime();
    const std::string problem = vtkSoftShadowsMeshCheck::FindProblem(caster.Data);
    check.Valid = problem.empty();
    if (!check.Valid)
    {
      vtkErrorWithObjectMacro(caster.Actor,
        "casts no shadow: its mapper's input is not a mesh the shadow techniques can read: "
          << problem.c_str());
    }
  }
  if (!check.Valid)
  {
    ++this->Refused;
    return;
  }
  vtkPolyData* data = caster.Data;
  caster.Faces = caster.Faces && data->GetNumberOfPolys() + data->GetNumberOfStrips() > 0;
  if (!opaque)
  {
    this->Translucent.push_back(caster);
    return;
  }
  // Lines and vertices, or faces not drawn filled, cast through the depth map.
  if (!caster.Faces || data->GetNumberOfLines() + data->GetNumberOfVerts() > 0)
  {
    this->FacesOnly = false;
  }
  this->Casters.push_back(caster);
}

//------------------------------------------------------------------------------
void vtkShadowCasterRegistry::Update(vtkRenderer* renderer)
{
  this->Props.clear();
  this->Casters.clear();
  this->DepthMapProps.clear();
  this->Translucent.clear();
  for (auto it = this->Checks.begin(); it != this->Checks.end();)
  {
    it = it->second.Data ? std::next(it) : this->Checks.erase(it);
  }
  this->Glyphs->Prune();
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    // A light's or camera's own picture casts no shadow (a light's cone
    // would shadow the light); its parts are actors of its own, which the
    // shadow shaders' hooks never reach, so drawing them into light-space
    // maps would only shade them there and change how they draw after.
    if (!prop->GetVisibility() || prop->IsA("vtkLightActor") || prop->IsA("vtkCameraActor"))
    {
      continue;
    }
    // A prop without bounds yet (a mapper without input) draws nothing: the
    // renderer's culler leaves it out, and so do light-space draws, where
    // VTK's mapper would report its missing input every time.
    const double* bounds = prop->GetBounds();
    if (bounds && !vtkMath::AreBoundsInitialized(bounds))
    {
      continue;
    }
    // A prop with a refused part casts nothing: light-space draws would
    // send the bad ids to the GPU through VTK's mapper.
    const int refused = this->Refused;
    const size_t casters = this->Casters.size(), translucent = this->Translucent.size();
    this->FacesOnly = true;
    this->AddActors(prop);
    if (this->Refused != refused)
    {
      this->Casters.resize(casters);
      this->Translucent.resize(translucent);
      continue;
    }
    this->Props.push_back(prop);
    if (!this->FacesOnly)
    {
      this->DepthMapProps.push_back(prop);
    }
  }
}

//------------------------------------------------------------------------------
void vtkShadowCasterRegistry::AddActors(vtkProp* prop)
{
  // The actors `prop` draws: itself, an assembly's visible parts (their
  // matrices composed along the path), or the parts a composite prop lists
  // (vtkAxesActor's, placed by their own matrices). Props that are not
  // actors (image slices, volumes, 2D props) draw what no caster lists.
  vtkNew<vtkPropCollection> parts;
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkAssemblyNode* node = path->GetLastNode();
    vtkProp* leaf = node->GetViewProp();
    if (!leaf->GetVisibility())
    {
      continue;
    }
    if (auto* actor = vtkActor::SafeDownCast(leaf))
    {
      this->AddActor(prop, actor, node->GetMatrix() ? node->GetMatrix() : actor->GetMatrix());
      continue;
    }
    // Asked what it draws, a composite prop places its parts (vtkAxesActor
    // does so only when drawn or asked, which the renderer does later).
    leaf->HasTranslucentPolygonalGeometry();
    parts->RemoveAllItems();
    leaf->GetActors(parts);
    bool listed = false;
    vtkCollectionSimpleIterator it;
    parts->InitTraversal(it);
    while (vtkProp* part = parts->GetNextProp(it))
    {
      auto* actor = vtkActor::SafeDownCast(part);
      if (part != leaf && actor && actor->GetVisibility())
      {
        this->AddActor(prop, actor, actor->GetMatrix());
        listed = true;
      }
    }
    this->FacesOnly = this->FacesOnly && listed;
  }
}

//------------------------------------------------------------------------------
void vtkShadowCasterRegistry::AddActor(vtkProp* prop, vtkActor* actor, vtkMatrix4x4* matrix)
{
  vtkShadowCaster caster;
  caster.Prop = prop;
  caster.Actor = actor;
  caster.ModelToWorld = vtkShadowMatrices::FromVTK(matrix);
  caster.WorldToModel = glm::inverse(caster.ModelToWorld);
  // Faces are drawn filled by the Surface representation, except by the
  // mappers that draw each point as an imposter whatever the cells.
  vtkMapper* mapper = actor->GetMapper();
  caster.Faces = actor->GetProperty()->GetRepresentation() == VTK_SURFACE && mapper &&
    !mapper->IsA("vtkOpenGLSphereMapper") && !mapper->IsA("vtkOpenGLStickMapper") &&
    !mapper->IsA("vtkPointGaussianMapper");
  const bool opaque = actor->HasOpaqueGeometry() != 0;

  // Glyph mappers: every instance, placed as the mapper places it.
  if (auto* glyphs = vtkGlyph3DMapper::SafeDownCast(mapper))
  {
    if (!this->BuildGlyphInstances)
    {
      this->FacesOnly =
        this->FacesOnly && caster.Faces && vtkShadowGlyphInstances::DrawsFacesOnly(glyphs);
      return;
    }
    if (vtkPolyData* instances = this->Glyphs->Get(glyphs))
    {
      caster.Data = instances;
      this->AddCaster(caster, opaque);
    }
    else
    {
      // Without a source VTK's mapper draws a line; too many instances
      // (reported) cast as VTK draws them, through the depth map.
      this->FacesOnly = false;
    }
    return;
  }
  // Polydata mappers, and vtkDataSetMapper (PyVista's add_mesh() draws
  // with it), which draws polydata as they do and other datasets' surfaces
  // through a polydata mapper of its own, made at its first render.
  vtkMapper* drawing = vtkPolyDataMapper::SafeDownCast(mapper);
  if (auto* datasetMapper = vtkDataSetMapper::SafeDownCast(mapper))
  {
    drawing = vtkPolyData::SafeDownCast(datasetMapper->GetInputDataObject(0, 0))
      ? static_cast<vtkMapper*>(datasetMapper)
      : datasetMapper->GetPolyDataMapper();
  }
  if (!drawing)
  {
    this->FacesOnly = false; // a mapper of its own kind (molecules, ...)
    return;
  }
  // The input is up to date: the renderer asked the mappers for bounds.
  vtkDataObject* input = drawing->GetInputDataObject(0, 0);
  if (auto* data = vtkPolyData::SafeDownCast(input))
  {
    caster.Data = data;
    this->AddCaster(caster, opaque);
    return;
  }
  // Composite mappers draw every block unless display attributes (which
  // may be unset) say otherwise.
  if (vtkCompositeDataSet::SafeDownCast(input) &&
    vtkShadowVTKVersion::CompositeMapper::SafeDownCast(drawing))
  {
    auto* attributes = vtkShadowVTKVersion::CompositeDisplayAttributes(drawing);
    unsigned int flatIndex = 0;
    this->AddBlocks(input, true, opaque && actor->GetProperty()->GetOpacity() >= 1.0, flatIndex,
      attributes, caster);
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkShadowCasterRegistry::MergedFaces(vtkPolyData* data)
{
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(data);
  clean->SetTolerance(1.0e-6); // of the bounding box's diagonal
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOff();
  clean->ConvertStripsToPolysOff();
  clean->Update();
  auto faces = vtkSmartPointer<vtkPolyData>::New();
  faces->SetPoints(clean->GetOutput()->GetPoints());
  faces->SetPolys(clean->GetOutput()->GetPolys());
  faces->SetStrips(clean->GetOutput()->GetStrips());
  return faces;
}
