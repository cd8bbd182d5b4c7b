#include "vtkShadowCasterRegistry.h"

#include "vtkActor.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkMatrix4x4.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkShadowMatrices.h"
#include "vtkSmartPointer.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

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
void vtkShadowCasterRegistry::AddBlocks(vtkDataObject* node, bool visible, unsigned int& flatIndex,
  vtkCompositeDataDisplayAttributes* attributes, const vtkShadowCaster& actor)
{
  // Flat indices count every node, empty ones too, depth first, as the
  // composite mapper's do; a block's visibility is inherited by its children.
  const unsigned int index = flatIndex++;
  if (!node)
  {
    return;
  }
  if (attributes && attributes->HasBlockVisibility(node))
  {
    visible = attributes->GetBlockVisibility(node);
  }
  if (auto* tree = vtkDataObjectTree::SafeDownCast(node))
  {
    vtkSmartPointer<vtkDataObjectTreeIterator> child;
    child.TakeReference(tree->NewTreeIterator());
    child->TraverseSubTreeOff();
    child->VisitOnlyLeavesOff();
    child->SkipEmptyNodesOff();
    for (child->InitTraversal(); !child->IsDoneWithTraversal(); child->GoToNextItem())
    {
      this->AddBlocks(child->GetCurrentDataObject(), visible, flatIndex, attributes, actor);
    }
    return;
  }
  auto* data = vtkPolyData::SafeDownCast(node);
  if (data && visible)
  {
    vtkShadowCaster block = actor;
    block.Data = data;
    block.FlatIndex = index;
    this->Casters.push_back(block);
  }
}

//------------------------------------------------------------------------------
void vtkShadowCasterRegistry::Update(vtkRenderer* renderer)
{
  this->Props.clear();
  this->Casters.clear();
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
    this->Props.push_back(prop);

    auto* actor = vtkActor::SafeDownCast(prop);
    auto* mapper = actor ? vtkPolyDataMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!mapper)
    {
      continue;
    }
    vtkShadowCaster caster;
    caster.Prop = prop;
    caster.Actor = actor;
    caster.Opaque = actor->HasOpaqueGeometry() != 0;
    caster.ModelToWorld = vtkShadowMatrices::FromVTK(actor->GetMatrix());
    caster.WorldToModel = glm::inverse(caster.ModelToWorld);

    // The input is up to date: the renderer asked the mappers for bounds.
    vtkDataObject* input = mapper->GetInputDataObject(0, 0);
    if (auto* data = vtkPolyData::SafeDownCast(input))
    {
      caster.Data = data;
      this->Casters.push_back(caster);
      continue;
    }
    auto* compositeMapper = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
    if (vtkCompositeDataSet::SafeDownCast(input) && compositeMapper)
    {
      unsigned int flatIndex = 0;
      this->AddBlocks(
        input, true, flatIndex, compositeMapper->GetCompositeDataDisplayAttributes(), caster);
    }
  }
}
