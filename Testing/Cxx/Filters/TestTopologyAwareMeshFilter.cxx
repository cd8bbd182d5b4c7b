// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkTopologyAwareMeshFilter: the TAM of the hand-checked meshes (tetrahedron,
// open square, fin, Moebius strip) vertex by vertex against neighbours found
// independently, the per-face and half-precision layouts, the byte counts, and
// the faces a rigid mesh can drop.

#include "MeshFilterTestUtilities.h"

#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkTopologyAwareMeshFilter.h"
#include "vtkUnsignedShortArray.h"

#include <glm/gtc/packing.hpp>

#include <map>

namespace
{
using namespace meshtest;

std::vector<std::vector<vtkIdType>> Triangles(vtkPolyData* mesh)
{
  std::vector<std::vector<vtkIdType>> triangles;
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    triangles.emplace_back(ids, ids + n);
  }
  return triangles;
}

// What face f stores for its edge k (corners k, k + 1), found by looking at
// every other face: the one neighbour's normal, negated when it runs the edge
// the same way; -n_f with no neighbour or more than one.
void ExpectedAdjacent(vtkPolyData* mesh, const std::vector<std::vector<vtkIdType>>& triangles,
  std::size_t f, int k, double out[3])
{
  const vtkIdType u = triangles[f][k], v = triangles[f][(k + 1) % 3];
  int count = 0;
  double normal[3] = { 0, 0, 0 };
  for (std::size_t g = 0; g < triangles.size(); ++g)
  {
    if (g == f)
    {
      continue;
    }
    for (int j = 0; j < 3; ++j)
    {
      const vtkIdType a = triangles[g][j], b = triangles[g][(j + 1) % 3];
      if ((a == u && b == v) || (a == v && b == u))
      {
        ++count;
        TriangleNormal(mesh, triangles[g][0], triangles[g][1], triangles[g][2], normal);
        if (a == u)
        {
          for (double& c : normal)
          {
            c = -c;
          }
        }
      }
    }
  }
  if (count != 1)
  {
    TriangleNormal(mesh, triangles[f][0], triangles[f][1], triangles[f][2], normal);
    for (double& c : normal)
    {
      c = -c;
    }
  }
  std::copy(normal, normal + 3, out);
}

// The default layout, every value of every vertex.
void CheckDefaultLayout(vtkPolyData* mesh, const char* label)
{
  vtkNew<vtkTopologyAwareMeshFilter> tam;
  tam->SetInputData(mesh);
  tam->Update();
  vtkPolyData* out = tam->GetOutput();
  const auto triangles = Triangles(mesh);
  const vtkIdType numFaces = static_cast<vtkIdType>(triangles.size());
  MESH_CHECK_EQUAL(
    out->GetNumberOfPoints(), 3 * numFaces, std::string(label) + ": 3 vertices a face");
  MESH_CHECK_EQUAL(out->GetNumberOfPolys(), numFaces, std::string(label) + ": faces");
  auto* position = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("Position"));
  auto* face = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("FacePositions"));
  auto* adjacent = vtkFloatArray::SafeDownCast(out->GetPointData()->GetArray("AdjacentNormals"));
  auto* cells = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("InputCellIds"));
  MESH_CHECK(position && face && adjacent && cells, std::string(label) + ": arrays");
  if (!(position && face && adjacent && cells))
  {
    return;
  }
  MESH_CHECK(out->GetPoints()->GetData() == position, "Position is the points' own array");
  MESH_CHECK(
    face->GetNumberOfComponents() == 9 && adjacent->GetNumberOfComponents() == 9, "9 components");
  int errors = 0;
  for (vtkIdType f = 0; f < numFaces && errors < 5; ++f)
  {
    bool ok = cells->GetValue(f) == f;
    vtkIdType n;
    const vtkIdType* poly;
    out->GetPolys()->GetCellAtId(f, n, poly);
    ok = ok && n == 3 && poly[0] == 3 * f && poly[1] == 3 * f + 1 && poly[2] == 3 * f + 2;
    double corners[9], normals[9];
    for (int j = 0; j < 3; ++j)
    {
      mesh->GetPoint(triangles[f][j], corners + 3 * j);
      ExpectedAdjacent(mesh, triangles, f, j, normals + 3 * j);
    }
    for (int j = 0; j < 3; ++j)
    {
      double got[9];
      position->GetTuple(3 * f + j, got);
      ok = ok && Near(got, corners + 3 * j, 3, 1e-6);
      face->GetTuple(3 * f + j, got);
      ok = ok && Near(got, corners, 9, 1e-6);
      adjacent->GetTuple(3 * f + j, got);
      ok = ok && Near(got, normals, 9, 1e-6);
    }
    if (!ok)
    {
      MESH_CHECK(false, std::string(label) + ": face " + std::to_string(f));
      ++errors;
    }
  }
}

void TestTetrahedron()
{
  auto mesh = Tetrahedron();
  CheckDefaultLayout(mesh, "tetrahedron");

  // By hand, face 0 (0 2 1): across 0-2 face 2 (normal -x), across 2-1
  // face 3 ((1 1 1)/sqrt 3), across 1-0 face 1 (normal -y).
  vtkNew<vtkTopologyAwareMeshFilter> tam;
  tam->SetInputData(mesh);
  tam->Update();
  const double s = 1.0 / std::sqrt(3.0);
  const double expected[9] = { -1, 0, 0, s, s, s, 0, -1, 0 };
  double got[9];
  for (int j = 0; j < 3; ++j)
  {
    tam->GetOutput()->GetPointData()->GetArray("AdjacentNormals")->GetTuple(j, got);
    MESH_CHECK(Near(got, expected, 9, 1e-7), "tetrahedron: face 0's adjacent normals");
  }

  // Bytes: 4 points (12 bytes) and 4 triangles (12 bytes) in; out 12 vertices
  // of 21 floats, or of 21 halves; per face 18 floats or halves a face.
  MESH_CHECK_EQUAL(tam->GetInputMeshBytes(), 96, "input bytes");
  MESH_CHECK_EQUAL(tam->GetTopologyAwareMeshBytes(), 12 * 84, "TAM bytes");
  MESH_CHECK(std::abs(tam->GetMemoryRatio() - 10.5) < 1e-12, "ratio 10.5");
  tam->HalfPrecisionOn();
  tam->Update();
  MESH_CHECK_EQUAL(tam->GetTopologyAwareMeshBytes(), 12 * 42, "half TAM bytes");
  tam->PerFaceAttributesOn();
  tam->Update();
  MESH_CHECK_EQUAL(tam->GetTopologyAwareMeshBytes(), 4 * 36, "half per-face TAM bytes");
  MESH_CHECK(std::abs(tam->GetMemoryRatio() - 1.5) < 1e-12, "ratio 1.5");
  tam->HalfPrecisionOff();
  tam->Update();
  MESH_CHECK_EQUAL(tam->GetTopologyAwareMeshBytes(), 4 * 72, "per-face TAM bytes");
}

void TestOpenSquare()
{
  auto mesh = OpenSquare();
  CheckDefaultLayout(mesh, "open square");
  vtkNew<vtkTopologyAwareMeshFilter> tam;
  tam->SetInputData(mesh);
  tam->Update();
  // Face 0 (0 1 2): two border edges (-n = -z) and the diagonal (face 1, +z).
  const double expected[9] = { 0, 0, -1, 0, 0, -1, 0, 0, 1 };
  double got[9];
  tam->GetOutput()->GetPointData()->GetArray("AdjacentNormals")->GetTuple(1, got);
  MESH_CHECK(Near(got, expected, 9, 0.0), "open square: face 0");
}

void TestFin()
{
  auto mesh = Fin();
  CheckDefaultLayout(mesh, "fin");
  // Every edge of a fin is a border or the shared non-manifold edge: -n_f.
  vtkNew<vtkTopologyAwareMeshFilter> tam;
  tam->SetInputData(mesh);
  tam->Update();
  const double s = std::sqrt(3.0) / 2.0;
  const double normals[3][3] = { { 0, 1, 0 }, { -s, -0.5, 0 }, { -s, 0.5, 0 } };
  for (int f = 0; f < 3; ++f)
  {
    double got[9];
    tam->GetOutput()->GetPointData()->GetArray("AdjacentNormals")->GetTuple(3 * f, got);
    for (int k = 0; k < 3; ++k)
    {
      const double negated[3] = { -normals[f][0], -normals[f][1], -normals[f][2] };
      MESH_CHECK(Near(got + 3 * k, negated, 3, 1e-7), "fin: -n_f on every edge");
    }
  }
}

void TestMoebius()
{
  const int segments = 8;
  auto mesh = Moebius(segments);
  CheckDefaultLayout(mesh, "Moebius strip");
  // Face 1 (0 3 1) and the last face (14 1 0) both run 1->0: each stores the
  // other's normal negated, as if turned to agree with it.
  vtkNew<vtkTopologyAwareMeshFilter> tam;
  tam->SetInputData(mesh);
  tam->Update();
  double last[3], got[9];
  TriangleNormal(mesh, 2 * segments - 2, 1, 0, last);
  tam->GetOutput()->GetPointData()->GetArray("AdjacentNormals")->GetTuple(3, got);
  const double expected[3] = { -last[0], -last[1], -last[2] };
  MESH_CHECK(Near(got + 6, expected, 3, 1e-6), "Moebius strip: the seam's neighbour, negated");
}

void TestHalfPrecision()
{
  auto mesh = Sphere(12, 8);
  vtkNew<vtkTopologyAwareMeshFilter> full;
  full->SetInputData(mesh);
  full->Update();
  vtkNew<vtkTopologyAwareMeshFilter> half;
  half->SetInputData(mesh);
  half->HalfPrecisionOn();
  half->Update();
  for (const char* name : { "Position", "FacePositions", "AdjacentNormals" })
  {
    auto* f = vtkFloatArray::SafeDownCast(full->GetOutput()->GetPointData()->GetArray(name));
    auto* h =
      vtkUnsignedShortArray::SafeDownCast(half->GetOutput()->GetPointData()->GetArray(name));
    MESH_CHECK(f && h && f->GetNumberOfValues() == h->GetNumberOfValues(),
      std::string("half precision: ") + name);
    if (!(f && h))
    {
      continue;
    }
    bool ok = true;
    for (vtkIdType i = 0; i < f->GetNumberOfValues(); ++i)
    {
      // Nearest half: within half a unit in the last place (2^-11 relative).
      const float value = f->GetValue(i);
      const float decoded = glm::unpackHalf1x16(h->GetValue(i));
      ok = ok && std::abs(decoded - value) <= std::abs(value) * (1.0f / 2048.0f) + 3e-8f;
    }
    MESH_CHECK(ok, std::string("half precision values: ") + name);
  }
  // Points stay float and match the float TAM.
  MESH_CHECK(half->GetOutput()->GetPoints()->GetDataType() == VTK_FLOAT, "float points");
  // Exact halves of exact values.
  vtkNew<vtkTopologyAwareMeshFilter> square;
  square->SetInputData(OpenSquare());
  square->HalfPrecisionOn();
  square->Update();
  auto* normals = vtkUnsignedShortArray::SafeDownCast(
    square->GetOutput()->GetPointData()->GetArray("AdjacentNormals"));
  MESH_CHECK(normals && normals->GetValue(2) == 0xbc00 && normals->GetValue(8) == 0x3c00 &&
      normals->GetValue(6) == 0 && normals->GetValue(0) == 0x8000,
    "half bits of -1, 1, 0 and -0 (the negated normal's zeros)");
}

void TestPerFace()
{
  auto mesh = Moebius(8);
  vtkNew<vtkTopologyAwareMeshFilter> perVertex;
  perVertex->SetInputData(mesh);
  perVertex->Update();
  vtkNew<vtkTopologyAwareMeshFilter> perFace;
  perFace->SetInputData(mesh);
  perFace->PerFaceAttributesOn();
  perFace->Update();
  vtkPolyData* out = perFace->GetOutput();
  MESH_CHECK(out->GetPoints() == mesh->GetPoints(), "per face: the input's points");
  MESH_CHECK_EQUAL(out->GetPointData()->GetNumberOfArrays(), 0, "per face: no point data");
  MESH_CHECK_EQUAL(out->GetNumberOfPolys(), mesh->GetNumberOfPolys(), "per face: faces");
  bool ok = true;
  for (vtkIdType f = 0; f < out->GetNumberOfPolys(); ++f)
  {
    vtkIdType n, m;
    const vtkIdType *a, *b;
    out->GetPolys()->GetCellAtId(f, n, a);
    mesh->GetPolys()->GetCellAtId(f, m, b);
    ok = ok && n == 3 && m == 3 && a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
    for (const char* name : { "FacePositions", "AdjacentNormals" })
    {
      double x[9], y[9];
      out->GetCellData()->GetArray(name)->GetTuple(f, x);
      perVertex->GetOutput()->GetPointData()->GetArray(name)->GetTuple(3 * f + 2, y);
      ok = ok && Near(x, y, 9, 0.0);
    }
  }
  MESH_CHECK(ok, "per face: the per-vertex values once a face");
}

void TestDropFaces()
{
  // A flat 4 x 4 grid: of its 32 faces, the 14 with a border edge stay.
  vtkNew<vtkTopologyAwareMeshFilter> tam;
  tam->SetInputData(Grid(4, 4));
  tam->DropNonSilhouetteFacesOn();
  tam->Update();
  MESH_CHECK_EQUAL(tam->GetNumberOfDroppedFaces(), 18, "flat grid: dropped faces");
  MESH_CHECK_EQUAL(tam->GetOutput()->GetNumberOfPolys(), 14, "flat grid: kept faces");
  MESH_CHECK_EQUAL(tam->GetOutput()->GetNumberOfPoints(), 3 * 14, "flat grid: kept vertices");
  // Folded along x = 2: the 6 faces on the ridge that had no border edge stay too.
  tam->SetInputData(Grid(4, 4, 0.5));
  tam->Update();
  MESH_CHECK_EQUAL(tam->GetNumberOfDroppedFaces(), 12, "roof: dropped faces");
  // Kept faces keep their input cell ids, in order.
  auto* cells =
    vtkIdTypeArray::SafeDownCast(tam->GetOutput()->GetCellData()->GetArray("InputCellIds"));
  bool increasing = cells && cells->GetNumberOfValues() == 20;
  for (vtkIdType i = 1; increasing && i < cells->GetNumberOfValues(); ++i)
  {
    increasing = cells->GetValue(i) > cells->GetValue(i - 1);
  }
  MESH_CHECK(increasing, "roof: input cell ids of the kept faces");
  // Closed and curved: nothing to drop. Off by default.
  tam->SetInputData(Sphere(16, 10));
  tam->Update();
  MESH_CHECK_EQUAL(tam->GetNumberOfDroppedFaces(), 0, "sphere: nothing dropped");
  vtkNew<vtkTopologyAwareMeshFilter> defaults;
  MESH_CHECK(!defaults->GetDropNonSilhouetteFaces() && !defaults->GetHalfPrecision() &&
      !defaults->GetPerFaceAttributes(),
    "options off by default");
}
}

int TestTopologyAwareMeshFilter(int, char*[])
{
  TestTetrahedron();
  TestOpenSquare();
  TestFin();
  TestMoebius();
  CheckDefaultLayout(Sphere(20, 12), "sphere");
  CheckDefaultLayout(Moebius(40), "Moebius strip, 40 segments");
  TestHalfPrecision();
  TestPerFace();
  TestDropFaces();
  if (meshtest::Failures())
  {
    std::fprintf(stderr, "TestTopologyAwareMeshFilter: %d failures\n", meshtest::Failures());
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
