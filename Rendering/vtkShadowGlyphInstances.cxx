// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowGlyphInstances.h"

#include "vtkBitArray.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositeDataSetRange.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkDataSet.h"
#include "vtkGlyph3DMapper.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRange.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <vector>

namespace
{
// The most points the instances' mesh may have (16.8 million: a quarter
// GiB of points, and techniques keep several times that per face).
constexpr double MaximumPoints = 1 << 24;

// The point data array the mapper reads for `index` (vtkGlyph3DMapper::SCALE,
// ...), by name or by attribute, as vtkAlgorithm::GetInputArrayToProcess() finds it.
vtkDataArray* MapperArray(vtkGlyph3DMapper* mapper, int index, vtkDataSet* input)
{
  vtkInformation* info = mapper->GetInputArrayInformation(index);
  vtkPointData* points = input->GetPointData();
  if (info && info->Has(vtkDataObject::FIELD_NAME()))
  {
    return points->GetArray(info->Get(vtkDataObject::FIELD_NAME()));
  }
  if (info && info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    return points->GetAttribute(info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
  }
  return nullptr;
}

// The sources by index: the mapper's source connections, or the top-level
// children of its source table tree. Entries that are not polydata are null.
std::vector<vtkPolyData*> Sources(vtkGlyph3DMapper* mapper)
{
  std::vector<vtkPolyData*> sources;
  if (mapper->GetUseSourceTableTree())
  {
    if (vtkDataObjectTree* tree = mapper->GetSourceTableTree())
    {
      for (vtkDataObject* child : vtk::Range(tree, vtk::DataObjectTreeOptions::None))
      {
        sources.push_back(vtkPolyData::SafeDownCast(child));
      }
    }
    return sources;
  }
  const int count = std::max(1, mapper->GetNumberOfInputConnections(1));
  for (int i = 0; i < count; ++i)
  {
    sources.push_back(mapper->GetNumberOfInputConnections(1) > i ? mapper->GetSource(i) : nullptr);
  }
  return sources;
}

// One instance's transform, as vtkOpenGLGlyph3DMapper builds it: the
// point's translation, the orientation's rotation, the scale.
glm::dmat4 InstanceTransform(vtkGlyph3DMapper* mapper, vtkDataSet* input, vtkIdType id,
  vtkDataArray* orientations, vtkDataArray* scales)
{
  double x[3];
  input->GetPoint(id, x);
  glm::dmat4 transform(1.0);
  transform[3] = glm::dvec4(x[0], x[1], x[2], 1.0);
  if (orientations)
  {
    double o[4] = { 0.0, 0.0, 0.0, 0.0 };
    orientations->GetTuple(id, o);
    glm::dquat turn(1.0, 0.0, 0.0, 0.0); // w, x, y, z
    switch (mapper->GetOrientationMode())
    {
      case vtkGlyph3DMapper::ROTATION:
        // Angles in degrees about z, then x, then y: qz * qx * qy.
        turn = glm::angleAxis(glm::radians(o[2]), glm::dvec3(0.0, 0.0, 1.0)) *
          glm::angleAxis(glm::radians(o[0]), glm::dvec3(1.0, 0.0, 0.0)) *
          glm::angleAxis(glm::radians(o[1]), glm::dvec3(0.0, 1.0, 0.0));
        break;
      case vtkGlyph3DMapper::QUATERNION:
        turn = glm::dquat(o[0], o[1], o[2], o[3]);
        break;
      default: // DIRECTION: x turned onto the vector, half a turn about their bisector
        if (o[1] == 0.0 && o[2] == 0.0)
        {
          turn = o[0] < 0.0 ? glm::dquat(0.0, 0.0, 1.0, 0.0) : turn;
        }
        else
        {
          const glm::dvec3 v(o[0], o[1], o[2]);
          const glm::dvec3 half = glm::normalize((v + glm::dvec3(glm::length(v), 0.0, 0.0)) * 0.5);
          turn = glm::dquat(0.0, half.x, half.y, half.z);
        }
        break;
    }
    const glm::dmat3 rotation = glm::mat3_cast(turn);
    for (int c = 0; c < 3; ++c)
    {
      transform[c] = glm::dvec4(rotation[c], 0.0);
    }
  }
  if (mapper->GetScaling())
  {
    glm::dvec3 scale(1.0);
    if (scales)
    {
      const double* s = scales->GetTuple(id);
      const int components = scales->GetNumberOfComponents();
      if (mapper->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_MAGNITUDE)
      {
        scale = glm::dvec3(vtkMath::Norm(s, components));
      }
      else if (mapper->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_COMPONENTS && components == 3)
      {
        scale = glm::dvec3(s[0], s[1], s[2]);
      }
      if (mapper->GetClamping() && mapper->GetScaleMode() != vtkGlyph3DMapper::NO_DATA_SCALING)
      {
        const double* range = mapper->GetRange();
        const double span = range[1] != range[0] ? range[1] - range[0] : 1.0;
        scale = (glm::clamp(scale, glm::dvec3(range[0]), glm::dvec3(range[1])) - range[0]) / span;
      }
    }
    scale *= mapper->GetScaleFactor();
    for (int c = 0; c < 3; ++c)
    {
      transform[c] *= scale[c] != 0.0 ? scale[c] : 1.0e-10;
    }
  }
  return transform;
}

// Everything `source` draws, placed by each of `transforms`, appended to `out`.
void AppendInstances(vtkPolyData* source, const std::vector<glm::dmat4>& transforms,
  vtkPoints* points, std::array<vtkCellArray*, 4> out)
{
  const vtkIdType count = source->GetNumberOfPoints();
  std::vector<glm::dvec4> corners(static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p[3];
    source->GetPoint(i, p);
    corners[i] = glm::dvec4(p[0], p[1], p[2], 1.0);
  }
  const std::array<vtkCellArray*, 4> in = { { source->GetVerts(), source->GetLines(),
    source->GetPolys(), source->GetStrips() } };
  vtkNew<vtkIdList> shifted;
  for (const glm::dmat4& transform : transforms)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    for (const glm::dvec4& corner : corners)
    {
      const glm::dvec4 p = transform * corner;
      points->InsertNextPoint(p.x, p.y, p.z);
    }
    for (size_t k = 0; k < in.size(); ++k)
    {
      if (!in[k] || in[k]->GetNumberOfCells() == 0)
      {
        continue;
      }
      vtkSmartPointer<vtkCellArrayIterator> cell;
      cell.TakeReference(in[k]->NewIterator());
      for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
      {
        vtkIdList* ids = cell->GetCurrentCell();
        shifted->SetNumberOfIds(ids->GetNumberOfIds());
        for (vtkIdType j = 0; j < ids->GetNumberOfIds(); ++j)
        {
          shifted->SetId(j, ids->GetId(j) + first);
        }
        out[k]->InsertNextCell(shifted);
      }
    }
  }
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkShadowGlyphInstances::Build(vtkGlyph3DMapper* mapper)
{
  const std::vector<vtkPolyData*> sources = Sources(mapper);
  // Each source's instances' transforms, over every leaf of the input.
  std::vector<std::vector<glm::dmat4>> placed(sources.size());
  auto collect = [&](vtkDataSet* input)
  {
    // The mapper masks with bit arrays only.
    auto* mask = mapper->GetMasking()
      ? vtkBitArray::SafeDownCast(MapperArray(mapper, vtkGlyph3DMapper::MASK, input))
      : nullptr;
    vtkDataArray* index = mapper->GetSourceIndexing()
      ? MapperArray(mapper, vtkGlyph3DMapper::SOURCE_INDEX, input)
      : nullptr;
    vtkDataArray* orientations =
      mapper->GetOrient() ? MapperArray(mapper, vtkGlyph3DMapper::ORIENTATION, input) : nullptr;
    vtkDataArray* scales =
      mapper->GetScaling() && mapper->GetScaleMode() != vtkGlyph3DMapper::NO_DATA_SCALING
      ? MapperArray(mapper, vtkGlyph3DMapper::SCALE, input)
      : nullptr;
    // Arrays the mapper refuses (wrong component counts) draw nothing.
    const int wanted = mapper->GetOrientationMode() == vtkGlyph3DMapper::QUATERNION ? 4 : 3;
    if (orientations && orientations->GetNumberOfComponents() != wanted)
    {
      return;
    }
    const vtkIdType count = input->GetNumberOfPoints();
    for (vtkIdType id = 0; id < count; ++id)
    {
      if (mask && mask->GetValue(id) == 0)
      {
        continue;
      }
      int which = 0;
      if (index && sources.size() > 1)
      {
        const double* value = index->GetTuple(id);
        which = vtkMath::ClampValue(
          static_cast<int>(vtkMath::Norm(value, index->GetNumberOfComponents())), 0,
          static_cast<int>(sources.size()) - 1);
      }
      if (sources[which])
      {
        placed[which].push_back(InstanceTransform(mapper, input, id, orientations, scales));
      }
    }
  };
  vtkDataObject* input = mapper->GetInputDataObject(0, 0);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    for (vtkDataObject* leaf : vtk::Range(composite))
    {
      if (auto* data = vtkDataSet::SafeDownCast(leaf))
      {
        collect(data);
      }
    }
  }
  else if (auto* data = vtkDataSet::SafeDownCast(input))
  {
    collect(data);
  }

  double total = 0.0;
  for (size_t k = 0; k < sources.size(); ++k)
  {
    total +=
      sources[k] ? static_cast<double>(placed[k].size()) * sources[k]->GetNumberOfPoints() : 0.0;
  }
  if (total > MaximumPoints)
  {
    vtkErrorWithObjectMacro(mapper,
      "its " << total << " instanced points exceed the " << MaximumPoints
             << " the shadow techniques take as one mesh: its glyphs cast through the light's "
                "depth map only (as lines and points do), not as faces.");
    return nullptr;
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkCellArray> verts, lines, polys, strips;
  for (size_t k = 0; k < sources.size(); ++k)
  {
    if (sources[k] && !placed[k].empty())
    {
      AppendInstances(sources[k], placed[k], points, { { verts, lines, polys, strips } });
    }
  }
  if (points->GetNumberOfPoints() == 0)
  {
    return nullptr;
  }
  mesh->SetPoints(points);
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  mesh->SetPolys(polys);
  mesh->SetStrips(strips);
  return mesh;
}

//------------------------------------------------------------------------------
bool vtkShadowGlyphInstances::DrawsFacesOnly(vtkGlyph3DMapper* mapper)
{
  bool faces = false;
  for (vtkPolyData* source : Sources(mapper))
  {
    if (!source)
    {
      continue;
    }
    if (source->GetNumberOfLines() + source->GetNumberOfVerts() > 0)
    {
      return false;
    }
    faces = faces || source->GetNumberOfPolys() + source->GetNumberOfStrips() > 0;
  }
  return faces;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkShadowGlyphInstances::Get(vtkGlyph3DMapper* mapper)
{
  vtkMTimeType time = mapper->GetMTime();
  if (vtkDataObject* input = mapper->GetInputDataObject(0, 0))
  {
    time = std::max(time, input->GetMTime());
  }
  for (vtkPolyData* source : Sources(mapper))
  {
    time = source ? std::max(time, source->GetMTime()) : time;
  }
  if (mapper->GetUseSourceTableTree() && mapper->GetSourceTableTree())
  {
    time = std::max(time, mapper->GetSourceTableTree()->GetMTime());
  }
  Entry& entry = this->Entries[mapper];
  if (entry.Mapper != mapper || entry.Time != time)
  {
    entry.Mapper = mapper;
    entry.Time = time;
    entry.Mesh = Build(mapper);
  }
  return entry.Mesh;
}

//------------------------------------------------------------------------------
void vtkShadowGlyphInstances::Prune()
{
  for (auto it = this->Entries.begin(); it != this->Entries.end();)
  {
    it = it->second.Mapper ? std::next(it) : this->Entries.erase(it);
  }
}
