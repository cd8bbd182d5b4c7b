// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: any bytes as a mesh, through what a mesh meets on its way to
// the shadow techniques. The first byte picks the way in:
//   0-3  a VTP, OBJ, PLY or STL file (the rest of the bytes), read by the
//        softshadows program's ReadMeshFile() and, when it is accepted,
//        given normals as the program does;
//   4    a polydata built from the bytes with any point ids (a user's
//        pipeline), checked by vtkSoftShadowsMeshCheck.
// Either way the mesh then goes through the three topology filters, which
// must refuse what the check refuses. A refusal is an exception or a filter
// error; a crash, a hang or a sanitizer report is a bug.

#include "MeshFiles.h"

#include "vtkEdgeAdjacencyFilter.h"
#include "vtkLightSilhouetteFilter.h"
#include "vtkSoftShadowsMeshCheck.h"
#include "vtkTopologyAwareMeshFilter.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace
{
const softshadows::MeshFormat Formats[] = { softshadows::MeshFormat::VTP,
  softshadows::MeshFormat::OBJ, softshadows::MeshFormat::PLY, softshadows::MeshFormat::STL };

// Points on a small grid and cells of signed byte ids: ids out of range,
// negative, repeated, cells of any size, as a buggy pipeline makes them.
vtkSmartPointer<vtkPolyData> BuildMesh(const uint8_t* data, size_t size)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  if (size < 1)
  {
    return mesh;
  }
  const int numPoints = data[0] % 32;
  size_t i = 1;
  vtkNew<vtkPoints> points;
  for (int p = 0; p < numPoints && i + 3 <= size; ++p, i += 3)
  {
    points->InsertNextPoint(
      static_cast<int8_t>(data[i]), static_cast<int8_t>(data[i + 1]), static_cast<int8_t>(data[i + 2]));
  }
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> cells[4];
  while (i + 1 < size)
  {
    const int kind = data[i] >> 6;   // verts, lines, polys, strips
    const int count = data[i] & 0x7; // 0 to 7 ids
    ++i;
    vtkIdType ids[8];
    int n = 0;
    for (; n < count && i < size; ++n, ++i)
    {
      ids[n] = static_cast<int8_t>(data[i]);
    }
    cells[kind]->InsertNextCell(n, ids);
  }
  mesh->SetVerts(cells[0]);
  mesh->SetLines(cells[1]);
  mesh->SetPolys(cells[2]);
  mesh->SetStrips(cells[3]);
  return mesh;
}

void Filter(vtkPolyData* mesh)
{
  vtkNew<vtkEdgeAdjacencyFilter> adjacency;
  adjacency->SetInputData(mesh);
  adjacency->Update();
  vtkNew<vtkTopologyAwareMeshFilter> tam;
  tam->SetInputData(mesh);
  tam->Update();
  vtkNew<vtkLightSilhouetteFilter> silhouette;
  silhouette->SetInputData(mesh);
  silhouette->SetLightPosition(3, 2, 1);
  silhouette->Update();
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // Refusals are errors by design; printing each would slow fuzzing down.
  vtkObject::GlobalWarningDisplayOff();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const int way = data[0] % 5;
  if (way == 4)
  {
    vtkSmartPointer<vtkPolyData> mesh = BuildMesh(data + 1, size - 1);
    vtkSoftShadowsMeshCheck::FindProblem(mesh, true);
    Filter(mesh);
    return 0;
  }

  // The readers take file names: one scratch file a process.
  static const std::filesystem::path file = std::filesystem::temp_directory_path() /
    ("softshadows-fuzz-mesh-" + std::to_string(getpid()));
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  vtkSmartPointer<vtkPolyData> mesh;
  try
  {
    mesh = softshadows::ReadMeshFile(file, Formats[way]);
  }
  catch (const std::runtime_error&)
  {
    return 0; // the program's "cannot read FILE: ..." answer
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->Update();
  Filter(mesh);
  return 0;
}
