// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSoftShadowsMeshCheck.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArrayRange.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSoftShadowsVTKVersion.h"

#include <algorithm> // for std::upper_bound
#include <atomic>    // for std::atomic
#include <cmath>     // for std::isfinite
#include <sstream>   // for std::ostringstream

vtkStandardNewMacro(vtkSoftShadowsMeshCheck);

namespace
{
// Lowers `first` to `i` if `i` is smaller, from any thread.
void KeepFirst(std::atomic<vtkIdType>& first, vtkIdType i)
{
  vtkIdType current = first.load();
  while (i < current && !first.compare_exchange_weak(current, i))
  {
  }
}

// The first value index in [0, n) for which bad(value) holds; n if none.
template <typename Range, typename Predicate>
vtkIdType FindFirst(const Range& values, Predicate bad)
{
  const vtkIdType n = static_cast<vtkIdType>(values.size());
  std::atomic<vtkIdType> first(n);
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      if (begin >= first.load())
      {
        return;
      }
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (bad(values[i]))
        {
          KeepFirst(first, i);
          return;
        }
      }
    });
  return first.load();
}

// Points: the first coordinate that is NaN or infinite.
struct FindNonFinite
{
  vtkIdType FirstBad = -1;

  template <typename Array>
  void operator()(Array* array)
  {
    const auto values = vtk::DataArrayValueRange(array);
    using T = typename decltype(values)::ValueType;
    const vtkIdType i = FindFirst(values, [](T x) { return !std::isfinite(x); });
    this->FirstBad = i < static_cast<vtkIdType>(values.size()) ? i / 3 : -1;
  }
};

const char* const CellKinds[4] = { "vertex", "line", "polygon", "triangle strip" };
// The fewest points vtkPolyData::BuildCells() takes for each kind.
const vtkIdType MinimumCellSizes[4] = { 1, 2, 3, 3 };

// One of the four cell arrays: offsets that describe the connectivity, and
// point ids in range. Writes the problem, if any, to `problem`.
struct CheckCells
{
  template <typename State>
  void operator()(State& state, vtkIdType numPoints, vtkIdType firstCellId, const char* kind,
    vtkIdType minimumSize, std::string& problem)
  {
    const auto offsets = vtk::DataArrayValueRange<1>(state.GetOffsets());
    const auto ids = vtk::DataArrayValueRange<1>(state.GetConnectivity());
    using Id = typename decltype(ids)::ValueType;
    std::ostringstream out;
    const vtkIdType numOffsets = static_cast<vtkIdType>(offsets.size());
    const vtkIdType numIds = static_cast<vtkIdType>(ids.size());
    if (numOffsets == 0 || offsets[0] != 0 || offsets[numOffsets - 1] != numIds)
    {
      out << "The " << kind << " cells' offsets do not describe their connectivity (" << numOffsets
          << " offsets, " << numIds << " point ids).";
      problem = out.str();
      return;
    }
    // Each cell's size: negative when offsets decrease.
    std::atomic<vtkIdType> firstShort(numOffsets);
    vtkSMPTools::For(1, numOffsets,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const vtkIdType size = offsets[i] - offsets[i - 1];
          if (size < 0 || size < minimumSize)
          {
            KeepFirst(firstShort, i);
            return;
          }
        }
      });
    if (firstShort.load() < numOffsets)
    {
      const vtkIdType c = firstShort.load() - 1;
      const vtkIdType size = offsets[c + 1] - offsets[c];
      if (size < 0)
      {
        out << "The offsets of " << kind << " cell " << firstCellId + c << " decrease (from "
            << offsets[c] << " to " << offsets[c + 1] << ").";
      }
      else
      {
        out << "Cell " << firstCellId + c << " (a " << kind << ") has " << size
            << " points; VTK's cells of that kind have at least " << minimumSize << ".";
      }
      problem = out.str();
      return;
    }
    const vtkIdType bad =
      FindFirst(ids, [numPoints](Id id) { return id < 0 || vtkIdType(id) >= numPoints; });
    if (bad < numIds)
    {
      // The cell whose ids hold index `bad`: the last offset not above it.
      const auto cell =
        std::upper_bound(offsets.begin(), offsets.end(), Id(bad)) - offsets.begin() - 1;
      out << "Cell " << firstCellId + cell << " (a " << kind << ") uses point id " << ids[bad]
          << ", but the mesh has " << numPoints << " points"
          << (numPoints > 0 ? " (ids 0 to " + std::to_string(numPoints - 1) + ")." : ".");
      problem = out.str();
    }
  }
};

// Attribute arrays shorter than the points or cells they belong to.
std::string CheckAttributes(vtkFieldData* data, vtkIdType expected, const char* what)
{
  for (int i = 0; data && i < data->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = data->GetAbstractArray(i);
    if (array && array->GetNumberOfTuples() < expected)
    {
      std::ostringstream out;
      out << "The " << what << " data array '" << (array->GetName() ? array->GetName() : "")
          << "' has " << array->GetNumberOfTuples() << " values, one for each of " << expected
          << " " << what << "s expected.";
      return out.str();
    }
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
std::string vtkSoftShadowsMeshCheck::FindProblem(vtkPolyData* mesh, bool cellSizes)
{
  if (!mesh)
  {
    return "There is no mesh (a null vtkPolyData).";
  }
  vtkPoints* points = mesh->GetPoints();
  const vtkIdType numPoints = points ? points->GetNumberOfPoints() : 0;
  std::ostringstream out;

  // Points before cells: an id check needs the count, a NaN spoils every test.
  if (points && points->GetData()->GetNumberOfComponents() != 3)
  {
    out << "The points have " << points->GetData()->GetNumberOfComponents()
        << " components; points have 3.";
    return out.str();
  }
  if (numPoints > 0)
  {
    FindNonFinite finder;
    if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(
          points->GetData(), finder))
    {
      finder.FirstBad = -1; // integer coordinates are always finite
    }
    if (finder.FirstBad >= 0)
    {
      double p[3];
      points->GetPoint(finder.FirstBad, p);
      out << "Point " << finder.FirstBad << " of the input is not finite (" << p[0] << ", " << p[1]
          << ", " << p[2]
          << "): NaN and infinite coordinates are not supported; remove them first.";
      return out.str();
    }
  }

  // vtkPolyData numbers its cells verts, lines, polys, then strips.
  vtkCellArray* const arrays[4] = { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(),
    mesh->GetStrips() };
  vtkIdType firstCellId = 0;
  for (int k = 0; k < 4; ++k)
  {
    if (!arrays[k])
    {
      continue;
    }
    const auto cells = vtkSoftShadowsVTKVersion::VisitableCells(arrays[k]);
    std::string problem;
    cells->Visit(CheckCells{}, numPoints, firstCellId, CellKinds[k],
      cellSizes ? MinimumCellSizes[k] : 0, problem);
    if (!problem.empty())
    {
      return problem;
    }
    firstCellId += cells->GetNumberOfCells();
  }

  std::string problem = CheckAttributes(mesh->GetPointData(), numPoints, "point");
  if (problem.empty())
  {
    problem = CheckAttributes(mesh->GetCellData(), firstCellId, "cell");
  }
  return problem;
}

//------------------------------------------------------------------------------
void vtkSoftShadowsMeshCheck::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
