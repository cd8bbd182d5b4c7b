// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkFenceSource.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <utility> // for std::swap

vtkStandardNewMacro(vtkFenceSource);

namespace
{
// Appends an axis-aligned box as 12 triangles. Each face gets its own four
// points so that shading and shadow lookups see flat faces, not normals
// averaged across the box's edges.
void AppendBox(const double lo[3], const double hi[3], vtkPoints* points, vtkFloatArray* normals,
  vtkCellArray* triangles)
{
  for (int axis = 0; axis < 3; ++axis)
  {
    // u x v points along +axis, so (0,0) (1,0) (1,1) (0,1) in (u, v) turns
    // counter-clockwise seen from the +axis side.
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    for (int side = -1; side <= 1; side += 2)
    {
      static const int corners[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
      float normal[3] = { 0.0f, 0.0f, 0.0f };
      normal[axis] = static_cast<float>(side);
      vtkIdType ids[4];
      for (int c = 0; c < 4; ++c)
      {
        double p[3];
        p[axis] = side > 0 ? hi[axis] : lo[axis];
        p[u] = corners[c][0] ? hi[u] : lo[u];
        p[v] = corners[c][1] ? hi[v] : lo[v];
        ids[c] = points->InsertNextPoint(p);
        normals->InsertNextTypedTuple(normal);
      }
      if (side < 0)
      {
        std::swap(ids[1], ids[3]);
      }
      const vtkIdType first[3] = { ids[0], ids[1], ids[2] };
      const vtkIdType second[3] = { ids[0], ids[2], ids[3] };
      triangles->InsertNextCell(3, first);
      triangles->InsertNextCell(3, second);
    }
  }
}
}

//------------------------------------------------------------------------------
vtkFenceSource::vtkFenceSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
double vtkFenceSource::GetLength() const
{
  return this->NumberOfPickets * this->PicketWidth + (this->NumberOfPickets - 1) * this->Gap;
}

//------------------------------------------------------------------------------
int vtkFenceSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (this->PicketWidth <= 0.0 || this->Height <= 0.0 || this->Thickness <= 0.0)
  {
    vtkErrorMacro("PicketWidth, Height and Thickness must be > 0 (got "
      << this->PicketWidth << ", " << this->Height << ", " << this->Thickness << ").");
    return 0;
  }

  const int numberOfBoxes = this->NumberOfPickets + 2;
  vtkNew<vtkPoints> points;
  points->Allocate(numberOfBoxes * 24);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->Allocate(numberOfBoxes * 24 * 3);
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateEstimate(numberOfBoxes * 12, 3);

  const double halfLength = 0.5 * this->GetLength();
  for (int i = 0; i < this->NumberOfPickets; ++i)
  {
    const double x = -halfLength + i * (this->PicketWidth + this->Gap);
    const double lo[3] = { x, 0.0, 0.0 };
    const double hi[3] = { x + this->PicketWidth, this->Height, this->Thickness };
    AppendBox(lo, hi, points, normals, triangles);
  }

  for (double fraction : { 0.25, 0.75 })
  {
    const double y = fraction * this->Height;
    const double lo[3] = { -halfLength, y - 0.5 * this->PicketWidth, -this->Thickness };
    const double hi[3] = { halfLength, y + 0.5 * this->PicketWidth, 0.0 };
    AppendBox(lo, hi, points, normals, triangles);
  }

  output->SetPoints(points);
  output->GetPointData()->SetNormals(normals);
  output->SetPolys(triangles);
  return 1;
}

//------------------------------------------------------------------------------
void vtkFenceSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfPickets: " << this->NumberOfPickets << "\n";
  os << indent << "PicketWidth: " << this->PicketWidth << "\n";
  os << indent << "Gap: " << this->Gap << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "Thickness: " << this->Thickness << "\n";
}
