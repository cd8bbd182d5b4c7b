// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// The three mesh-topology filters on bad or unusual input: empty meshes, NaN
// and infinite points, point ids out of range, broken cell arrays and short
// attribute arrays, degenerate and zero-area triangles, duplicate points,
// vertices and lines among the polygons, several parts, inconsistently
// oriented faces, polygons and strips to triangulate, bad lights, points that
// are neither float nor double. No crash; clear errors, warnings said once,
// empty outputs after an error.

#include "MeshFilterTestUtilities.h"

#include "vtkEdgeAdjacencyFilter.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkLightSilhouetteFilter.h"
#include "vtkPointData.h"
#include "vtkTopologyAwareMeshFilter.h"

#include <limits>
#include <map>
#include <set>
#include <sstream>

namespace
{
using namespace meshtest;

struct Filters
{
  vtkNew<vtkEdgeAdjacencyFilter> Adjacency;
  vtkNew<vtkTopologyAwareMeshFilter> Tam;
  vtkNew<vtkLightSilhouetteFilter> Silhouette;
  vtkNew<MessageLog> Log;

  Filters()
  {
    this->Log->Watch(this->Adjacency);
    this->Log->Watch(this->Tam);
    this->Log->Watch(this->Silhouette);
    this->Silhouette->SetLightPosition(3, 2, 1);
  }
  std::vector<vtkAlgorithm*> All()
  {
    return { this->Adjacency.GetPointer(), this->Tam.GetPointer(), this->Silhouette.GetPointer() };
  }
  void Run(vtkPolyData* mesh)
  {
    this->Log->Clear();
    for (vtkAlgorithm* filter : this->All())
    {
      filter->SetInputDataObject(mesh);
      filter->Update();
    }
  }
};

vtkPolyData* Output(vtkAlgorithm* filter)
{
  return vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
}

// A silhouette's lines as pairs of input point ids.
std::set<std::pair<vtkIdType, vtkIdType>> OrientedLines(vtkPolyData* silhouette)
{
  std::set<std::pair<vtkIdType, vtkIdType>> lines;
  for (vtkIdType i = 0; i < silhouette->GetNumberOfLines(); ++i)
  {
    vtkIdType n;
    const vtkIdType* line;
    silhouette->GetLines()->GetCellAtId(i, n, line);
    lines.emplace(line[0], line[1]);
  }
  return lines;
}

// Every filter reports an error containing `text`, and outputs nothing.
void ExpectError(vtkPolyData* mesh, const std::string& text, const std::string& label)
{
  Filters filters;
  filters.Run(mesh);
  int matching = 0;
  for (const std::string& error : filters.Log->Errors)
  {
    matching += error.find(text) != std::string::npos ? 1 : 0;
  }
  MESH_CHECK_EQUAL(matching, 3, label + ": one error a filter containing \"" + text + "\"");
  for (vtkAlgorithm* filter : filters.All())
  {
    vtkPolyData* out = Output(filter);
    MESH_CHECK(out && out->GetNumberOfPoints() == 0 && out->GetNumberOfCells() == 0,
      label + ": empty output of " + filter->GetClassName());
  }
  // A good mesh afterwards works again.
  filters.Run(Tetrahedron());
  MESH_CHECK(filters.Log->Errors.empty(), label + ": no error on the next, good mesh");
  MESH_CHECK_EQUAL(Output(filters.Adjacency)->GetNumberOfLines(), 6, label + ": recovered");
  for (vtkAlgorithm* filter : filters.All())
  {
    std::ostringstream printed;
    filter->Print(printed);
    MESH_CHECK(printed.str().find("Number") != std::string::npos ||
        printed.str().find("Bytes") != std::string::npos,
      label + ": PrintSelf of " + filter->GetClassName());
  }
}

void TestEmpty()
{
  ExpectError(vtkNew<vtkPolyData>().GetPointer(), "no points", "empty polydata");
  auto pointsOnly = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 } }, {});
  ExpectError(pointsOnly, "no polygons or triangle strips", "points only");
  auto linesOnly = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 } }, {});
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 1 };
  lines->InsertNextCell(2, line);
  linesOnly->SetLines(lines);
  ExpectError(linesOnly, "no polygons or triangle strips", "lines only");
  auto degenerateOnly = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 } }, { { 0, 0, 1 }, { 1, 1, 1 } });
  ExpectError(degenerateOnly, "no face with three distinct points", "degenerate faces only");
}

void TestNonFinite()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto withNan = Tetrahedron();
  withNan->GetPoints()->SetPoint(2, 0, nan, 0);
  ExpectError(withNan, "Point 2 of the input is not finite", "NaN point");
  auto withInf = Tetrahedron();
  withInf->GetPoints()->SetPoint(3, 0, 0, -inf);
  ExpectError(withInf, "Point 3 of the input is not finite", "infinite point");
  // A NaN in a point no face uses is still an error: the input is broken.
  auto unused = Tetrahedron();
  unused->GetPoints()->InsertNextPoint(nan, nan, nan);
  ExpectError(unused, "not finite", "unused NaN point");
}

// Point ids a mesh does not have, offsets that overrun the connectivity and
// attributes shorter than the points: refused before any is read.
void TestBrokenCells()
{
  auto pastEnd = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 1, 3 } });
  ExpectError(pastEnd, "Cell 1 (a polygon) uses point id 3, but the mesh has 3 points",
    "id = number of points");
  auto negative = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, -1, 2 } });
  ExpectError(negative, "uses point id -1", "negative id");
  auto far = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2000000000 } });
  ExpectError(far, "uses point id 2000000000", "id far out");

  // A strip's bad id is named with the strip's cell id (after the polygons).
  auto strip = Tetrahedron();
  vtkNew<vtkCellArray> strips;
  const vtkIdType ids[4] = { 0, 1, 2, 7 };
  strips->InsertNextCell(4, ids);
  strip->SetStrips(strips);
  ExpectError(strip, "Cell 4 (a triangle strip) uses point id 7", "strip id out of range");

  // Offsets that claim more ids than the connectivity holds.
  auto overrun = Tetrahedron();
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  for (vtkIdType value : { 0, 3, 9 })
  {
    offsets->InsertNextValue(value);
  }
  for (vtkIdType value : { 0, 1, 2, 0, 1, 3 })
  {
    connectivity->InsertNextValue(value);
  }
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  overrun->SetPolys(polys);
  ExpectError(overrun, "offsets do not describe their connectivity", "offsets overrun");

  auto shortNormals = Tetrahedron();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(2);
  shortNormals->GetPointData()->SetNormals(normals);
  ExpectError(shortNormals, "point data array 'Normals' has 2 values", "short point array");
}

void TestBadLight()
{
  vtkNew<vtkLightSilhouetteFilter> filter;
  vtkNew<MessageLog> log;
  log->Watch(filter);
  filter->SetInputData(Tetrahedron());
  filter->SetLightPosition(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  filter->Update();
  MESH_CHECK(log->ErrorContains("is not finite"), "NaN light: error");
  MESH_CHECK_EQUAL(filter->GetOutput()->GetNumberOfCells(), 0, "NaN light: empty output");
  log->Clear();
  filter->SetLightPosition(0, 0, 0);
  filter->PositionalOff();
  filter->Update();
  MESH_CHECK(log->ErrorContains("needs a direction"), "directional light without direction");
  log->Clear();
  filter->SetLightPosition(0, 0, 1);
  filter->Update();
  MESH_CHECK(log->Errors.empty() && filter->GetOutput()->GetNumberOfLines() == 3,
    "a good directional light after a bad one");
}

void TestDegenerate()
{
  // One good triangle, two that repeat a point, a two-point polygon, and a
  // zero-area triangle (three distinct but collinear points).
  auto mesh = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 2, 0, 0 }, { 3, 0, 0 } },
    { { 0, 1, 2 }, { 0, 0, 1 }, { 1, 2, 1 }, { 0, 1 }, { 1, 3, 4 } });
  Filters filters;
  filters.Run(mesh);
  MESH_CHECK(filters.Log->Errors.empty(), "degenerate faces: no error");
  MESH_CHECK_EQUAL(filters.Log->WarningsContaining("Dropped 3 degenerate faces"), 3,
    "degenerate faces: one warning a filter");
  // Edges: the good triangle's 3, the sliver's 3 (1-3, 3-4, 4-1).
  MESH_CHECK_EQUAL(Output(filters.Adjacency)->GetNumberOfLines(), 6, "degenerate: edges");
  MESH_CHECK_EQUAL(Output(filters.Tam)->GetNumberOfPolys(), 2, "degenerate: TAM faces");
  // The sliver's normal is zero; its cell id is 4 (after the dropped ones).
  auto* cells =
    vtkIdTypeArray::SafeDownCast(Output(filters.Tam)->GetCellData()->GetArray("InputCellIds"));
  MESH_CHECK(cells && cells->GetValue(0) == 0 && cells->GetValue(1) == 4, "degenerate: cell ids");
  double normals[9];
  Output(filters.Tam)->GetPointData()->GetArray("AdjacentNormals")->GetTuple(3, normals);
  const double zero[9] = { 0, 0, 0, 0, 0, 0, 0, 0, 0 };
  MESH_CHECK(Near(normals, zero, 9, 0.0), "zero-area face: zero normals");
  // A zero-area face never faces the light: its border edges still count,
  // the good triangle's three too.
  MESH_CHECK_EQUAL(Output(filters.Silhouette)->GetNumberOfLines(), 6, "degenerate: silhouette");
}

void TestDuplicatePoints()
{
  // Two triangles meeting along an edge whose points are repeated: matched by
  // id, they share nothing.
  auto mesh =
    MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 } },
      { { 0, 1, 2 }, { 3, 5, 4 } });
  Filters filters;
  filters.Run(mesh);
  vtkNew<vtkEdgeAdjacencyFilter> adjacency;
  adjacency->SetInputData(mesh);
  adjacency->Update();
  MESH_CHECK_EQUAL(adjacency->GetNumberOfBorderEdges(), 6, "duplicate points: 6 border edges");
  MESH_CHECK_EQUAL(Output(filters.Silhouette)->GetNumberOfLines(), 6, "duplicate points");
}

void TestMixedCells()
{
  // A vertex and two lines before the polygons: warned about once an update,
  // and face cell ids still count them.
  auto mesh = Tetrahedron();
  vtkNew<vtkCellArray> verts;
  const vtkIdType vertex = 0;
  verts->InsertNextCell(1, &vertex);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[3] = { 0, 1, 2 };
  lines->InsertNextCell(2, line);
  lines->InsertNextCell(3, line);
  mesh->SetVerts(verts);
  mesh->SetLines(lines);
  Filters filters;
  filters.Run(mesh);
  MESH_CHECK(filters.Log->Errors.empty(), "mixed cells: no error");
  MESH_CHECK_EQUAL(filters.Log->WarningsContaining("Ignored 1 vertex and 2 line cells"), 3,
    "mixed cells: one warning a filter");
  MESH_CHECK_EQUAL(static_cast<int>(filters.Log->Warnings.size()), 3, "mixed cells: no other");
  MESH_CHECK_EQUAL(Output(filters.Adjacency)->GetNumberOfLines(), 6, "mixed cells: edges");
  auto* cells =
    vtkIdTypeArray::SafeDownCast(Output(filters.Tam)->GetCellData()->GetArray("InputCellIds"));
  MESH_CHECK(cells && cells->GetValue(0) == 3 && cells->GetValue(3) == 6,
    "mixed cells: polygons are cells 3 to 6");
  MESH_CHECK_EQUAL(Output(filters.Silhouette)->GetNumberOfLines(), 3, "mixed cells: silhouette");
  // Updating again for a moved light: the silhouette's cached edge map is
  // reused, and its warning is not repeated.
  filters.Log->Clear();
  filters.Silhouette->SetLightPosition(3, 2, 1.5);
  filters.Silhouette->Update();
  MESH_CHECK(filters.Log->Warnings.empty(), "mixed cells: no new warning for a moved light");
}

void TestParts()
{
  // Two tetrahedra apart: twice everything.
  auto mesh = MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 5, 0, 0 },
                         { 6, 0, 0 }, { 5, 1, 0 }, { 5, 0, 1 } },
    { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 }, { 4, 6, 5 }, { 4, 5, 7 }, { 4, 7, 6 },
      { 5, 6, 7 } });
  Filters filters;
  filters.Silhouette->SetLightPosition(20, 20, 20);
  filters.Run(mesh);
  MESH_CHECK_EQUAL(Output(filters.Adjacency)->GetNumberOfLines(), 12, "two parts: edges");
  MESH_CHECK_EQUAL(filters.Adjacency->GetNumberOfManifoldEdges(), 12, "two parts: manifold");
  MESH_CHECK_EQUAL(Output(filters.Tam)->GetNumberOfPoints(), 24, "two parts: TAM");
  MESH_CHECK_EQUAL(Output(filters.Silhouette)->GetNumberOfLines(), 6, "two parts: silhouette");
}

void TestInconsistentOrientation()
{
  // Every seventh face of a sphere turned round.
  auto sphere = Sphere(30, 20);
  vtkNew<vtkCellArray> polys;
  vtkIdType n;
  const vtkIdType* ids;
  vtkIdType face = 0;
  std::map<std::pair<vtkIdType, vtkIdType>, int> direction; // +1 / -1 sum per edge
  for (sphere->GetPolys()->InitTraversal(); sphere->GetPolys()->GetNextCell(n, ids); ++face)
  {
    vtkIdType tri[3] = { ids[0], ids[1], ids[2] };
    if (face % 7 == 0)
    {
      std::swap(tri[1], tri[2]);
    }
    polys->InsertNextCell(3, tri);
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType u = tri[k], v = tri[(k + 1) % 3];
      direction[{ std::min(u, v), std::max(u, v) }] += u < v ? 1 : -1;
    }
  }
  sphere->SetPolys(polys);
  int inconsistent = 0;
  for (const auto& entry : direction)
  {
    inconsistent += entry.second != 0 ? 1 : 0;
  }
  Filters filters;
  filters.Run(sphere);
  MESH_CHECK(filters.Log->Errors.empty(), "flipped faces: no error");
  MESH_CHECK_EQUAL(filters.Adjacency->GetNumberOfInconsistentEdges(),
    static_cast<vtkIdType>(inconsistent), "flipped faces: inconsistent edges");
  MESH_CHECK_EQUAL(filters.Adjacency->GetNumberOfManifoldEdges(),
    static_cast<vtkIdType>(direction.size()), "flipped faces: all edges still manifold");
  // The flips change no silhouette: it is a property of the surface.
  auto clean = Sphere(30, 20);
  vtkNew<vtkLightSilhouetteFilter> reference;
  reference->SetInputData(clean);
  reference->SetLightPosition(3, 2, 1);
  reference->Update();
  MESH_CHECK(OrientedLines(Output(filters.Silhouette)) == OrientedLines(reference->GetOutput()),
    "flipped faces: the same silhouette, same orientation, as without flips");
}

void TestPolygonsAndStrips()
{
  // A concave L-shaped hexagon (cell 0), a quad (cell 1), and a strip of six
  // points (cell 2), all on z = 0 and facing +z.
  auto mesh =
    MakeMesh({ { 0, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 }, { 1, 1, 0 }, { 1, 2, 0 }, { 0, 2, 0 },
               { 3, 0, 0 }, { 4, 0, 0 }, { 4, 1, 0 }, { 3, 1, 0 }, { 5, 0, 0 }, { 5, 1, 0 },
               { 6, 0, 0 }, { 6, 1, 0 }, { 7, 0, 0 }, { 7, 1, 0 } },
      { { 0, 1, 2, 3, 4, 5 }, { 6, 7, 8, 9 } });
  vtkNew<vtkCellArray> strips;
  // Triangles (11 10 13), (13 10 12) turned, (13 12 15), (15 12 14) turned.
  const vtkIdType strip[6] = { 11, 10, 13, 12, 15, 14 };
  strips->InsertNextCell(6, strip);
  mesh->SetStrips(strips);
  vtkNew<vtkTopologyAwareMeshFilter> tam;
  tam->SetInputData(mesh);
  tam->PerFaceAttributesOn();
  tam->Update();
  vtkPolyData* out = tam->GetOutput();
  MESH_CHECK_EQUAL(out->GetNumberOfPolys(), 4 + 2 + 4, "triangles from a hexagon, quad, strip");
  auto* cells = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("InputCellIds"));
  bool ok = cells != nullptr;
  for (vtkIdType f = 0; ok && f < out->GetNumberOfPolys(); ++f)
  {
    vtkIdType n;
    const vtkIdType* tri;
    out->GetPolys()->GetCellAtId(f, n, tri);
    double normal[3];
    TriangleNormal(out, tri[0], tri[1], tri[2], normal);
    const double up[3] = { 0, 0, 1 };
    ok = Near(normal, up, 3, 1e-12) && cells->GetValue(f) == (f < 4 ? 0 : (f < 6 ? 1 : 2));
  }
  MESH_CHECK(ok, "every triangle faces +z, with its polygon's cell id");
  // The hexagon's area is kept: 3 unit squares.
  double area = 0.0;
  for (vtkIdType f = 0; f < 4; ++f)
  {
    vtkIdType n;
    const vtkIdType* tri;
    out->GetPolys()->GetCellAtId(f, n, tri);
    double p[3], q[3], r[3];
    out->GetPoint(tri[0], p);
    out->GetPoint(tri[1], q);
    out->GetPoint(tri[2], r);
    area += 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
  }
  MESH_CHECK(std::abs(area - 3.0) < 1e-12, "the concave hexagon, triangulated, covers 3");
}

void TestPointTypes()
{
  // Integer points take the generic path; float points the fast one.
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_INT);
  for (int i = 0; i < 4; ++i)
  {
    points->InsertNextPoint(i == 1 ? 1 : 0, i == 2 ? 1 : 0, i == 3 ? 1 : 0);
  }
  auto mesh = Tetrahedron();
  mesh->SetPoints(points);
  Filters filters;
  filters.Run(mesh);
  MESH_CHECK(filters.Log->Errors.empty(), "int points: no error");
  MESH_CHECK_EQUAL(Output(filters.Silhouette)->GetNumberOfLines(), 3, "int points: silhouette");
  MESH_CHECK_EQUAL(Output(filters.Silhouette)->GetPoints()->GetDataType(), VTK_INT,
    "the silhouette keeps the points' type");
  double normals[6];
  Output(filters.Adjacency)->GetCellData()->GetArray("FaceNormals")->GetTuple(0, normals);
  MESH_CHECK(std::abs(normals[0] * normals[0] + normals[1] * normals[1] + normals[2] * normals[2] -
               1.0) < 1e-6,
    "int points: unit normals");
}
}

int TestMeshFiltersRobustness(int, char*[])
{
  TestEmpty();
  TestNonFinite();
  TestBrokenCells();
  TestBadLight();
  TestDegenerate();
  TestDuplicatePoints();
  TestMixedCells();
  TestParts();
  TestInconsistentOrientation();
  TestPolygonsAndStrips();
  TestPointTypes();
  if (meshtest::Failures())
  {
    std::fprintf(stderr, "TestMeshFiltersRobustness: %d failures\n", meshtest::Failures());
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
