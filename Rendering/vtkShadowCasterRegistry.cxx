#include "vtkShadowCasterRegistry.h"

#include "vtkActor.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
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
void vtkShadowCasterRegistry::Update(vtkRenderer* renderer)
{
  this->Props.clear();
  this->Casters.clear();
  vtkCollectionSimpleIterator it;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility())
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
    auto* composite = vtkCompositeDataSet::SafeDownCast(input);
    auto* compositeMapper = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
    if (!composite || !compositeMapper)
    {
      continue;
    }
    vtkCompositeDataDisplayAttributes* attributes =
      compositeMapper->GetCompositeDataDisplayAttributes();
    vtkSmartPointer<vtkCompositeDataIterator> block;
    block.TakeReference(composite->NewIterator());
    for (block->InitTraversal(); !block->IsDoneWithTraversal(); block->GoToNextItem())
    {
      auto* data = vtkPolyData::SafeDownCast(block->GetCurrentDataObject());
      if (!data ||
        (attributes && attributes->HasBlockVisibility(data) &&
          !attributes->GetBlockVisibility(data)))
      {
        continue;
      }
      caster.Data = data;
      caster.FlatIndex = block->GetCurrentFlatIndex();
      this->Casters.push_back(caster);
    }
  }
}
