// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkLightSilhouetteFilter: silhouettes of the hand-checked meshes (edges and
// their orientation), lights given by vtkLight, every edge of larger meshes
// against a geometric test (all faces on one side of the plane through the
// edge and the light), and the normal-cone tree against brute force on random
// lights: the same edges, the same orientation, far fewer edges tested.

#include "MeshFilterTestUtilities.h"

#include "vtkEdgeAdjacencyFilter.h"
#include "vtkFenceSource.h"
#include "vtkLight.h"
#include "vtkLightSilhouetteFilter.h"
#include "vtkSphereSource.h"
#include "vtkSuperquadricSource.h"
#include "vtkTriangleFilter.h"

#include <map>
#include <random>
#include <set>

namespace
{
using namespace meshtest;
using Line = std::pair<vtkIdType, vtkIdType>;

// The output's lines (on the input's point ids), keyed by edge id.
std::map<vtkIdType, Line> Lines(vtkLightSilhouetteFilter* filter)
{
  std::map<vtkIdType, Line> lines;
  vtkPolyData* out = filter->GetOutput();
  vtkDataArray* edgeIds = out->GetCellData()->GetArray("EdgeIds");
  if (!edgeIds)
  {
    return lines;
  }
  for (vtkIdType i = 0; i < out->GetNumberOfLines(); ++i)
  {
    vtkIdType n;
    const vtkIdType* ids;
    out->GetLines()->GetCellAtId(i, n, ids);
    lines[static_cast<vtkIdType>(edgeIds->GetComponent(i, 0))] = { ids[0], ids[1] };
  }
  return lines;
}

// The oriented lines, without edge ids.
std::set<Line> LineSet(vtkLightSilhouetteFilter* filter)
{
  std::set<Line> set;
  for (const auto& entry : Lines(filter))
  {
    set.insert(entry.second);
  }
  return set;
}

vtkSmartPointer<vtkLightSilhouetteFilter> Run(
  vtkPolyData* mesh, double x, double y, double z, bool positional, int method)
{
  auto filter = vtkSmartPointer<vtkLightSilhouetteFilter>::New();
  filter->SetInputData(mesh);
  filter->SetLightPosition(x, y, z);
  filter->SetPositional(positional);
  filter->SetMethod(method);
  filter->Update();
  return filter;
}

void CheckLines(vtkPolyData* mesh, double x, double y, double z, bool positional,
  const std::set<Line>& expected, const std::string& label)
{
  for (int method :
    { vtkLightSilhouetteFilter::BRUTE_FORCE, vtkLightSilhouetteFilter::NORMAL_CONE_TREE })
  {
    auto filter = Run(mesh, x, y, z, positional, method);
    const std::string name = label + (method ? " (tree)" : " (brute force)");
    MESH_CHECK(LineSet(filter) == expected, name + ": silhouette lines");
    MESH_CHECK_EQUAL(filter->GetNumberOfSilhouetteEdges(), static_cast<vtkIdType>(expected.size()),
      name + ": count");
    MESH_CHECK(filter->GetOutput()->GetPoints() == mesh->GetPoints(), name + ": input's points");
  }
}

void TestTetrahedron()
{
  auto mesh = Tetrahedron();
  // Only face 3 (1 2 3) faces (2, 2, 2): its three edges, run as it runs them.
  CheckLines(mesh, 2, 2, 2, true, { { 1, 2 }, { 2, 3 }, { 3, 1 } }, "tetrahedron, light (2 2 2)");
  CheckLines(mesh, 0.1, 0.2, 1, false, { { 1, 2 }, { 2, 3 }, { 3, 1 } },
    "tetrahedron, directional light from about +z");
  // Only face 2 (0 3 2, normal -x) faces (-1, 0.3, 0.2).
  CheckLines(
    mesh, -1, 0.3, 0.2, true, { { 0, 3 }, { 3, 2 }, { 2, 0 } }, "tetrahedron, light at -x");
  // From inside, every face faces away: no silhouette.
  CheckLines(mesh, 0.1, 0.1, 0.1, true, {}, "tetrahedron, light inside");
}

void TestOpenSquare()
{
  auto mesh = OpenSquare();
  // Border edges always count, run with the faces on their left seen from
  // the light: as the faces run them from above, reversed from below.
  CheckLines(mesh, 0.3, 0.4, 1, true, { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } },
    "open square, light above");
  CheckLines(mesh, 0.3, 0.4, -1, true, { { 1, 0 }, { 2, 1 }, { 3, 2 }, { 0, 3 } },
    "open square, light below");
  // Corner 3 lifted: face 1 turns to (1, -1, 1)/sqrt 3 and, from (-5, 5, 0.5),
  // away from the light while face 0 faces it: the diagonal, run 2->0 as face 0 runs it.
  auto bent = OpenSquare();
  bent->GetPoints()->SetPoint(3, 0, 1, 1);
  CheckLines(
    bent, -5, 5, 0.5, true, { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 3, 2 }, { 0, 3 } }, "bent square");
}

void TestFins()
{
  // Three faces at 0, 120 and 240 degrees round the z axis lie on both sides
  // of any plane through it: the fin edge is never a silhouette.
  // Face 0 (0 1 2) faces (2, 0.1, 0.5), faces 1 (0 1 3) and 2 (1 0 4) face
  // away: their border edges run against their winding.
  CheckLines(Fin(), 2, 0.1, 0.5, true,
    { { 1, 2 }, { 2, 0 }, { 3, 1 }, { 0, 3 }, { 4, 0 }, { 1, 4 } }, "fin");
  // Three pages at 0, 45 and 90 degrees: on one side of the plane through the
  // spine and a light at 135 degrees, on both sides of one at 20 degrees.
  const double c = std::sqrt(0.5);
  auto book = MakeMesh({ { 0, 0, 0 }, { 0, 0, 1 }, { 1, 0, 0 }, { c, c, 0 }, { 0, 1, 0 } },
    { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 0, 4 } });
  // From 20 degrees, pages 0 (0 1 2) and 2 (1 0 4) face the light, page 1 does not.
  const std::set<Line> borders = { { 1, 2 }, { 2, 0 }, { 3, 1 }, { 0, 3 }, { 0, 4 }, { 4, 1 } };
  auto filter = Run(book, -2, 2, 0.5, true, vtkLightSilhouetteFilter::NORMAL_CONE_TREE);
  MESH_CHECK_EQUAL(filter->GetNumberOfSilhouetteEdges(), 7, "book, light at 135 degrees");
  filter = Run(book, 2, 0.73, 0.5, true, vtkLightSilhouetteFilter::NORMAL_CONE_TREE);
  MESH_CHECK(LineSet(filter) == borders, "book, light at 20 degrees: the borders only");
}

// Every edge of the mesh against the plane through it and the light: a
// silhouette edge when the third corners of all its faces lie on one side.
// Edges with a corner within round-off of that plane are skipped.
void CheckGeometry(vtkPolyData* mesh, const double light[4], vtkLightSilhouetteFilter* filter,
  const std::string& label)
{
  vtkNew<vtkEdgeAdjacencyFilter> adjacency;
  adjacency->SetInputData(mesh);
  adjacency->Update();
  vtkPolyData* edges = adjacency->GetOutput();
  const auto lines = Lines(filter);
  std::map<std::pair<vtkIdType, vtkIdType>, std::vector<vtkIdType>> opposite;
  vtkIdType n;
  const vtkIdType* ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    if (mesh->GetCellType(c) != VTK_TRIANGLE)
    {
      continue;
    }
    mesh->GetCellPoints(c, n, ids);
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType u = ids[k], v = ids[(k + 1) % 3];
      opposite[{ std::min(u, v), std::max(u, v) }].push_back(ids[(k + 2) % 3]);
    }
  }
  int errors = 0, skipped = 0;
  for (vtkIdType e = 0; e < edges->GetNumberOfLines() && errors < 5; ++e)
  {
    edges->GetLines()->GetCellAtId(e, n, ids);
    double u[3], v[3];
    mesh->GetPoint(ids[0], u);
    mesh->GetPoint(ids[1], v);
    const double a[3] = { v[0] - u[0], v[1] - u[1], v[2] - u[2] };
    const double b[3] = { light[0] - light[3] * u[0], light[1] - light[3] * u[1],
      light[2] - light[3] * u[2] };
    const double plane[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0] };
    const double scale = std::sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
    int positive = 0, negative = 0;
    bool tie = false;
    for (vtkIdType corner : opposite[{ std::min(ids[0], ids[1]), std::max(ids[0], ids[1]) }])
    {
      double x[3];
      mesh->GetPoint(corner, x);
      const double side =
        plane[0] * (x[0] - u[0]) + plane[1] * (x[1] - u[1]) + plane[2] * (x[2] - u[2]);
      const double size = std::sqrt((x[0] - u[0]) * (x[0] - u[0]) + (x[1] - u[1]) * (x[1] - u[1]) +
        (x[2] - u[2]) * (x[2] - u[2]));
      tie = tie || std::abs(side) <= 1e-9 * scale * size;
      (side > 0 ? positive : negative) += 1;
    }
    if (tie)
    {
      ++skipped;
      continue;
    }
    const bool silhouette = positive == 0 || negative == 0;
    if (silhouette != (lines.count(e) == 1))
    {
      MESH_CHECK(false,
        label + ": edge " + std::to_string(ids[0]) + "-" + std::to_string(ids[1]) +
          (silhouette ? " missing" : " should not be there"));
      ++errors;
    }
  }
  MESH_CHECK(skipped < edges->GetNumberOfLines() / 100 + 3, label + ": too many ties");
}

// Brute force and tree on random lights: the same lines, edge by edge.
void CompareMethods(
  vtkPolyData* mesh, int lights, unsigned seed, const std::string& label, bool geometry = true)
{
  vtkNew<vtkLightSilhouetteFilter> brute;
  brute->SetInputData(mesh);
  brute->SetMethodToBruteForce();
  vtkNew<vtkLightSilhouetteFilter> tree;
  tree->SetInputData(mesh);
  double bounds[6];
  mesh->GetBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double size =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  int differences = 0;
  for (int i = 0; i < lights; ++i)
  {
    // Directional, far, near, and inside the bounds, in turn.
    const double reach[4] = { 1.0, 5.0 * size, 1.2 * size, 0.4 * size };
    const int kind = i % 4;
    double light[4] = { uniform(random), uniform(random), uniform(random), kind ? 1.0 : 0.0 };
    for (int c = 0; c < 3; ++c)
    {
      light[c] = kind ? center[c] + reach[kind] * light[c] : light[c];
    }
    for (vtkLightSilhouetteFilter* filter : { brute.GetPointer(), tree.GetPointer() })
    {
      filter->SetLightPosition(light);
      filter->SetPositional(kind != 0);
      filter->Update();
    }
    if (Lines(brute) != Lines(tree))
    {
      ++differences;
    }
    if (geometry && i < 8)
    {
      CheckGeometry(mesh, light, tree, label + ", light " + std::to_string(i));
    }
  }
  MESH_CHECK_EQUAL(differences, 0, label + ": lights where brute force and tree differ");
  MESH_CHECK_EQUAL(brute->GetNumberOfTestedEdges(), brute->GetNumberOfEdges(),
    label + ": brute force tests every edge");
}

// Lights in the planes of faces (directional: along the face; positional: at
// a point of its plane), where the sign of a face's test is decided by
// round-off: the tree's float test must leave those faces to the exact one,
// and give the same lines as brute force.
void CompareGrazing(vtkPolyData* mesh, int lights, unsigned seed, const std::string& label)
{
  vtkNew<vtkLightSilhouetteFilter> brute;
  brute->SetInputData(mesh);
  brute->SetMethodToBruteForce();
  vtkNew<vtkLightSilhouetteFilter> tree;
  tree->SetInputData(mesh);
  std::mt19937 random(seed);
  std::uniform_int_distribution<vtkIdType> anyCell(0, mesh->GetNumberOfCells() - 1);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  int differences = 0, tested = 0;
  for (int i = 0; i < lights; ++i)
  {
    vtkIdType n;
    const vtkIdType* ids;
    mesh->GetCellPoints(anyCell(random), n, ids);
    if (n != 3)
    {
      continue;
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
    }
    const double a = uniform(random), b = uniform(random);
    const bool positional = i % 2 == 1;
    double light[3];
    for (int c = 0; c < 3; ++c)
    {
      const double along = a * (p[1][c] - p[0][c]) + b * (p[2][c] - p[0][c]);
      light[c] = positional ? p[0][c] + along : along;
    }
    for (vtkLightSilhouetteFilter* filter : { brute.GetPointer(), tree.GetPointer() })
    {
      filter->SetLightPosition(light);
      filter->SetPositional(positional);
      filter->Update();
    }
    differences += Lines(brute) != Lines(tree) ? 1 : 0;
    ++tested;
  }
  MESH_CHECK(tested > lights / 2, label + ": grazing lights tried");
  MESH_CHECK_EQUAL(differences, 0, label + ": grazing lights where brute force and tree differ");
}

vtkSmartPointer<vtkPolyData> Triangulated(vtkAlgorithm* source)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(source->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}

// Holes, fins, repeated and flipped faces, and faces of zero area.
vtkSmartPointer<vtkPolyData> DamagedSphere(unsigned seed)
{
  auto sphere = Sphere(48, 30);
  vtkNew<vtkPoints> points;
  points->DeepCopy(sphere->GetPoints());
  vtkNew<vtkCellArray> polys;
  std::mt19937 random(seed);
  vtkIdType n;
  const vtkIdType* ids;
  for (sphere->GetPolys()->InitTraversal(); sphere->GetPolys()->GetNextCell(n, ids);)
  {
    const unsigned r = random() % 16;
    const vtkIdType flipped[3] = { ids[0], ids[2], ids[1] };
    if (r == 0)
    {
      continue;
    }
    polys->InsertNextCell(3, r == 1 ? flipped : ids);
    if (r == 2)
    {
      double p[3];
      points->GetPoint(ids[0], p);
      const vtkIdType tip = points->InsertNextPoint(1.3 * p[0], 1.3 * p[1], 1.3 * p[2]);
      const vtkIdType fin[3] = { ids[0], ids[1], tip };
      polys->InsertNextCell(3, fin);
    }
    else if (r == 3)
    {
      polys->InsertNextCell(3, ids);
    }
    else if (r == 4)
    {
      // A sliver of zero area on the face's first edge.
      double p[3], q[3];
      points->GetPoint(ids[0], p);
      points->GetPoint(ids[1], q);
      const vtkIdType middle =
        points->InsertNextPoint(0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2]));
      const vtkIdType sliver[3] = { ids[1], ids[0], middle };
      polys->InsertNextCell(3, sliver);
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

void TestVtkLight()
{
  auto mesh = Sphere(24, 16);
  auto reference = Run(mesh, 2, 1, 3, true, vtkLightSilhouetteFilter::NORMAL_CONE_TREE);
  vtkNew<vtkLight> light;
  light->SetPositional(true);
  light->SetPosition(2, 1, 3);
  vtkNew<vtkLightSilhouetteFilter> filter;
  filter->SetInputData(mesh);
  filter->SetLight(light);
  filter->SetLightPosition(-7, 0, 0); // ignored while a vtkLight is set
  filter->Update();
  MESH_CHECK(Lines(filter) == Lines(reference), "positional vtkLight");
  // Directional: from the focal point toward the position.
  light->SetPositional(false);
  light->SetPosition(1, 2, 10);
  light->SetFocalPoint(1, 2, 0);
  filter->Update();
  auto directional = Run(mesh, 0, 0, 1, false, vtkLightSilhouetteFilter::BRUTE_FORCE);
  MESH_CHECK(Lines(filter) == Lines(directional), "directional vtkLight, followed when it changes");
  filter->SetLight(nullptr);
  filter->Update();
  auto back = Run(mesh, -7, 0, 0, true, vtkLightSilhouetteFilter::BRUTE_FORCE);
  MESH_CHECK(Lines(filter) == Lines(back), "back to LightPosition");
}

void TestCache()
{
  // A moved mesh is a new mesh: same result as a fresh filter.
  auto mesh = Sphere(30, 20);
  vtkNew<vtkLightSilhouetteFilter> filter;
  filter->SetInputData(mesh);
  filter->SetLightPosition(3, 0.5, 0.2);
  filter->Update();
  MESH_CHECK(filter->GetBuildTime() > 0.0, "first update builds");
  filter->SetLightPosition(3, 0.6, 0.2);
  filter->Update();
  MESH_CHECK(filter->GetBuildTime() == 0.0, "a moved light reuses the tree");
  vtkPoints* points = mesh->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    points->SetPoint(i, p[0] + 2.0, p[1], p[2] * 0.5);
  }
  points->Modified();
  filter->Update();
  auto fresh = Run(mesh, 3, 0.6, 0.2, true, vtkLightSilhouetteFilter::BRUTE_FORCE);
  MESH_CHECK(Lines(filter) == Lines(fresh), "modified input: rebuilt");
}

// The tree's last search tested fewer than a tenth of the edges.
void CheckPrunes(vtkLightSilhouetteFilter* filter, const std::string& label)
{
  MESH_CHECK(filter->GetNumberOfTestedEdges() * 10 < filter->GetNumberOfEdges(),
    label + ": the tree tests fewer than a tenth of the edges (" +
      std::to_string(filter->GetNumberOfTestedEdges()) + " of " +
      std::to_string(filter->GetNumberOfEdges()) + ")");
}

void TestPruning()
{
  // Large enough for the parallel walk; the tree tests a small part of the
  // edges for a light outside.
  auto mesh = Sphere(200, 100);
  auto filter = Run(mesh, 4, 3, 2, true, vtkLightSilhouetteFilter::NORMAL_CONE_TREE);
  MESH_CHECK(filter->GetNumberOfEdges() > (1 << 14), "sphere: parallel walk");
  CheckPrunes(filter, "sphere");
  CompareMethods(mesh, 24, 7, "large sphere", false);
  CompareGrazing(mesh, 24, 9, "large sphere");
}

// A mesh far from (0, 0, 0), as in world or geographic coordinates: the
// tree's float bounds are relative to the mesh, so it prunes as well as at
// the origin, and it still agrees with brute force edge for edge.
void TestFarFromOrigin()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(200);
  source->SetPhiResolution(100);
  source->SetCenter(1e6, -3e5, 2e5);
  source->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  source->Update();
  vtkPolyData* mesh = source->GetOutput();
  auto filter =
    Run(mesh, 1e6 + 4, -3e5 + 3, 2e5 + 2, true, vtkLightSilhouetteFilter::NORMAL_CONE_TREE);
  CheckPrunes(filter, "far sphere");
  CompareMethods(mesh, 24, 12, "far sphere", false);
  CompareGrazing(mesh, 24, 13, "far sphere");
  // Single precision points there: coarse steps of 1/16, faces of uneven
  // shape, and planes that only the exact test can tell apart.
  source->SetOutputPointsPrecision(vtkAlgorithm::SINGLE_PRECISION);
  source->SetThetaResolution(40);
  source->SetPhiResolution(30);
  source->Update();
  CompareMethods(source->GetOutput(), 24, 14, "far sphere, float points", false);
  CompareGrazing(source->GetOutput(), 24, 15, "far sphere, float points");
}
}

int TestLightSilhouetteFilter(int, char*[])
{
  TestTetrahedron();
  TestOpenSquare();
  TestFins();
  {
    // Moebius strip from (nearly) above: all 16 border edges; the seam (rung
    // 0-1, two faces running it the same way, lying flat there) is not a
    // silhouette. Slightly tilted, so no edge lies in a plane with the light.
    auto strip = Moebius(8);
    auto filter = Run(strip, 0.01, 0.02, 1, false, vtkLightSilhouetteFilter::NORMAL_CONE_TREE);
    const auto lines = LineSet(filter);
    int borders = 0;
    bool seam = false;
    for (const Line& line : lines)
    {
      const vtkIdType a = std::min(line.first, line.second), b = std::max(line.first, line.second);
      const bool rung = b == a + 1 && a % 2 == 0;
      const bool diagonal = (b - a == 3 && a % 2 == 0) || (a == 0 && b == 14);
      borders += (rung || diagonal) ? 0 : 1;
      seam = seam || (a == 0 && b == 1);
    }
    MESH_CHECK_EQUAL(borders, 16, "Moebius strip: border edges");
    MESH_CHECK(!seam, "Moebius strip: the flat seam is no silhouette");
    const double light[4] = { 0.01, 0.02, 1, 0 };
    CheckGeometry(strip, light, filter, "Moebius strip");
    CompareMethods(strip, 16, 3, "Moebius strip");
  }
  TestVtkLight();
  TestCache();

  CompareMethods(Sphere(40, 30), 24, 1, "sphere");
  {
    vtkNew<vtkSuperquadricSource> torus;
    torus->ToroidalOn();
    torus->SetThetaResolution(64);
    torus->SetPhiResolution(32);
    CompareMethods(Triangulated(torus), 24, 2, "torus");
  }
  {
    vtkNew<vtkFenceSource> fence;
    fence->Update();
    CompareMethods(fence->GetOutput(), 24, 4, "fence");
    CompareGrazing(fence->GetOutput(), 24, 10, "fence");
  }
  CompareMethods(Moebius(200), 24, 5, "Moebius strip, 200 segments");
  CompareMethods(Grid(30, 20, 0.4), 24, 6, "roof");
  CompareGrazing(Grid(30, 20, 0.4), 24, 11, "roof");
  CompareMethods(DamagedSphere(8), 24, 8, "damaged sphere");
  TestPruning();
  TestFarFromOrigin();

  if (meshtest::Failures())
  {
    std::fprintf(stderr, "TestLightSilhouetteFilter: %d failures\n", meshtest::Failures());
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
