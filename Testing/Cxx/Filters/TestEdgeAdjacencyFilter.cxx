// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// vtkEdgeAdjacencyFilter: hand-checked small meshes (tetrahedron, open square,
// fin, Moebius strip), every output edge against an independent edge map on
// generated meshes, and boundary / non-manifold counts against vtkFeatureEdges,
// including a mesh large enough to be built in several OpenMesh chunks.

#include "MeshFilterTestUtilities.h"

#include "vtkEdgeAdjacencyFilter.h"
#include "vtkFenceSource.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkUnsignedCharArray.h"

#include <map>
#include <random>

namespace
{
using namespace meshtest;

// Faces of every edge, computed the simplest way: (face, runs it from the
// smaller point id to the larger) in face order.
using EdgeKey = std::pair<vtkIdType, vtkIdType>;
std::map<EdgeKey, std::vector<std::pair<vtkIdType, vtkIdType>>> ExpectedEdges(vtkPolyData* mesh)
{
  std::map<EdgeKey, std::vector<std::pair<vtkIdType, vtkIdType>>> edges;
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType n;
  const vtkIdType* ids;
  vtkIdType face = 0;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids); ++face)
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      const vtkIdType u = ids[k], v = ids[(k + 1) % n];
      edges[{ std::min(u, v), std::max(u, v) }].emplace_back(face, u);
    }
  }
  return edges;
}

// Every output edge against ExpectedEdges: the same set, faces (first two in
// cell data, all of them for non-manifold edges), the line's direction,
// types, orientation flags, and normals. Faces are cells: triangle meshes only.
void CheckAgainstExpected(vtkPolyData* mesh, vtkEdgeAdjacencyFilter* filter, const char* label)
{
  vtkPolyData* out = filter->GetOutput();
  const auto expected = ExpectedEdges(mesh);
  MESH_CHECK_EQUAL(out->GetNumberOfLines(), static_cast<vtkIdType>(expected.size()),
    std::string(label) + ": number of edges");
  auto* types = vtkUnsignedCharArray::SafeDownCast(out->GetCellData()->GetArray("EdgeType"));
  auto* consistent =
    vtkUnsignedCharArray::SafeDownCast(out->GetCellData()->GetArray("ConsistentOrientation"));
  auto* faceIds = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("FaceIds"));
  auto* normals = vtkFloatArray::SafeDownCast(out->GetCellData()->GetArray("FaceNormals"));
  vtkFieldData* field = out->GetFieldData();
  auto* moreEdges = vtkIdTypeArray::SafeDownCast(field->GetArray("NonManifoldEdgeIds"));
  auto* moreOffsets = vtkIdTypeArray::SafeDownCast(field->GetArray("NonManifoldFaceOffsets"));
  auto* moreFaces = vtkIdTypeArray::SafeDownCast(field->GetArray("NonManifoldFaceIds"));
  MESH_CHECK(types && consistent && faceIds && normals && moreEdges && moreOffsets && moreFaces,
    std::string(label) + ": output arrays");
  if (!(types && consistent && faceIds && normals && moreEdges && moreOffsets && moreFaces))
  {
    return;
  }
  MESH_CHECK_EQUAL(faceIds->GetNumberOfComponents(), 2, "FaceIds components");
  MESH_CHECK_EQUAL(normals->GetNumberOfComponents(), 6, "FaceNormals components");

  std::map<EdgeKey, vtkIdType> seen;
  vtkIdType nonManifold = 0;
  vtkIdType errors = 0;
  for (vtkIdType e = 0; e < out->GetNumberOfLines() && errors < 5; ++e)
  {
    vtkIdType n;
    const vtkIdType* line;
    out->GetLines()->GetCellAtId(e, n, line);
    const EdgeKey key{ std::min(line[0], line[1]), std::max(line[0], line[1]) };
    const auto found = expected.find(key);
    if (found == expected.end() || seen.count(key))
    {
      MESH_CHECK(false,
        std::string(label) + ": unexpected or repeated edge " + std::to_string(line[0]) + "-" +
          std::to_string(line[1]));
      ++errors;
      continue;
    }
    seen[key] = e;
    const auto& faces = found->second;
    const vtkIdType count = static_cast<vtkIdType>(faces.size());
    const int type = count == 1 ? 0 : (count == 2 ? 1 : 2);
    const bool runsAsFirst = line[0] == faces[0].second;
    const bool opposite = count == 2 && faces[1].second != faces[0].second;
    bool ok = types->GetValue(e) == type && runsAsFirst &&
      consistent->GetValue(e) == ((count == 1 || opposite) ? 1 : 0) &&
      faceIds->GetTypedComponent(e, 0) == faces[0].first &&
      faceIds->GetTypedComponent(e, 1) == (count > 1 ? faces[1].first : -1);
    double n0[3], n1[3], got[6];
    vtkIdType pts;
    const vtkIdType* tri;
    mesh->GetCellPoints(faces[0].first, pts, tri);
    TriangleNormal(mesh, tri[0], tri[1], tri[2], n0);
    if (count > 1)
    {
      mesh->GetCellPoints(faces[1].first, pts, tri);
      TriangleNormal(mesh, tri[0], tri[1], tri[2], n1);
    }
    else
    {
      n1[0] = -n0[0], n1[1] = -n0[1], n1[2] = -n0[2];
    }
    normals->GetTuple(e, got);
    ok = ok && Near(got, n0, 3, 1e-6) && Near(got + 3, n1, 3, 1e-6);
    if (count > 2)
    {
      // All faces, in face order, in the field data.
      const vtkIdType i = nonManifold++;
      ok = ok && i < moreEdges->GetNumberOfValues() && moreEdges->GetValue(i) == e &&
        moreOffsets->GetValue(i + 1) - moreOffsets->GetValue(i) == count;
      for (vtkIdType k = 0; ok && k < count; ++k)
      {
        ok = moreFaces->GetValue(moreOffsets->GetValue(i) + k) == faces[k].first;
      }
    }
    if (!ok)
    {
      MESH_CHECK(false,
        std::string(label) + ": edge " + std::to_string(line[0]) + "-" + std::to_string(line[1]) +
          " (cell " + std::to_string(e) + ") differs");
      ++errors;
    }
  }
  MESH_CHECK_EQUAL(moreEdges->GetNumberOfValues(), nonManifold,
    std::string(label) + ": non-manifold edges in field data");
}

void CheckCounts(vtkEdgeAdjacencyFilter* filter, vtkIdType border, vtkIdType manifold,
  vtkIdType nonManifold, vtkIdType inconsistent, const char* label)
{
  MESH_CHECK_EQUAL(filter->GetNumberOfBorderEdges(), border, std::string(label) + ": border");
  MESH_CHECK_EQUAL(filter->GetNumberOfManifoldEdges(), manifold, std::string(label) + ": manifold");
  MESH_CHECK_EQUAL(
    filter->GetNumberOfNonManifoldEdges(), nonManifold, std::string(label) + ": non-manifold");
  MESH_CHECK_EQUAL(
    filter->GetNumberOfInconsistentEdges(), inconsistent, std::string(label) + ": inconsistent");
}

vtkSmartPointer<vtkEdgeAdjacencyFilter> Run(vtkPolyData* mesh)
{
  auto filter = vtkSmartPointer<vtkEdgeAdjacencyFilter>::New();
  filter->SetInputData(mesh);
  filter->Update();
  return filter;
}

void TestTetrahedron()
{
  auto mesh = Tetrahedron();
  auto filter = Run(mesh);
  CheckCounts(filter, 0, 6, 0, 0, "tetrahedron");
  CheckAgainstExpected(mesh, filter, "tetrahedron");
  // By hand: edge 0-1 is run 1->0 by face 0 (0 2 1) and 0->1 by face 1 (0 1 3).
  vtkPolyData* out = filter->GetOutput();
  const double s = 1.0 / std::sqrt(3.0);
  bool found01 = false, found12 = false;
  for (vtkIdType e = 0; e < out->GetNumberOfLines(); ++e)
  {
    vtkIdType n;
    const vtkIdType* line;
    out->GetLines()->GetCellAtId(e, n, line);
    double normals[6];
    out->GetCellData()->GetArray("FaceNormals")->GetTuple(e, normals);
    if (line[0] == 1 && line[1] == 0)
    {
      const double expected[6] = { 0, 0, -1, 0, -1, 0 };
      found01 = Near(normals, expected, 6, 1e-7);
    }
    if (line[0] == 2 && line[1] == 1)
    {
      // Run 2->1 by face 0, 1->2 by face 3 (1 2 3, normal (1 1 1)/sqrt 3).
      const double expected[6] = { 0, 0, -1, s, s, s };
      found12 = Near(normals, expected, 6, 1e-7);
    }
  }
  MESH_CHECK(found01 && found12, "tetrahedron: edges 1->0 and 2->1 with their normals");
  MESH_CHECK(out->GetPoints() == mesh->GetPoints(), "the input's points, shared");
}

void TestOpenSquare()
{
  auto mesh = OpenSquare();
  auto filter = Run(mesh);
  CheckCounts(filter, 4, 1, 0, 0, "open square");
  CheckAgainstExpected(mesh, filter, "open square");
  // The border edge 0->1: face 0, normal (0 0 1), and the negated normal second.
  vtkPolyData* out = filter->GetOutput();
  bool found = false;
  for (vtkIdType e = 0; e < out->GetNumberOfLines(); ++e)
  {
    vtkIdType n;
    const vtkIdType* line;
    out->GetLines()->GetCellAtId(e, n, line);
    if (line[0] == 0 && line[1] == 1)
    {
      double normals[6];
      out->GetCellData()->GetArray("FaceNormals")->GetTuple(e, normals);
      const double expected[6] = { 0, 0, 1, 0, 0, -1 };
      found = Near(normals, expected, 6, 0.0) &&
        out->GetCellData()->GetArray("FaceIds")->GetComponent(e, 1) == -1;
    }
  }
  MESH_CHECK(found, "open square: border edge 0->1");
}

void TestFin()
{
  auto mesh = Fin();
  auto filter = Run(mesh);
  CheckCounts(filter, 6, 0, 1, 0, "fin");
  CheckAgainstExpected(mesh, filter, "fin");
  vtkFieldData* field = filter->GetOutput()->GetFieldData();
  MESH_CHECK_EQUAL(field->GetArray("NonManifoldEdgeIds")->GetNumberOfTuples(), 1, "fin: one");
  MESH_CHECK_EQUAL(field->GetArray("NonManifoldFaceIds")->GetNumberOfTuples(), 3, "fin: faces");
}

void TestMoebius()
{
  const int segments = 8;
  auto mesh = Moebius(segments);
  auto filter = Run(mesh);
  // V - E + F = 0: 2N points, 2N faces, 4N edges: the 2N long edges are the
  // one boundary loop, N rungs and N diagonals inside; the rung 0-1 where the
  // strip closes is run the same way by both its faces.
  CheckCounts(filter, 2 * segments, 2 * segments, 0, 1, "Moebius strip");
  CheckAgainstExpected(mesh, filter, "Moebius strip");
  MESH_CHECK(filter->GetNumberOfRefusedFaces() >= 1,
    "Moebius strip: OpenMesh refuses the face that closes it (the fallback is exercised)");
}

void CompareWithFeatureEdges(vtkPolyData* mesh, const char* label)
{
  auto filter = Run(mesh);
  vtkIdType boundary = -1, nonManifold = -1;
  FeatureEdgeCounts(mesh, boundary, nonManifold);
  MESH_CHECK_EQUAL(filter->GetNumberOfBorderEdges(), boundary,
    std::string(label) + ": boundary vs vtkFeatureEdges");
  MESH_CHECK_EQUAL(filter->GetNumberOfNonManifoldEdges(), nonManifold,
    std::string(label) + ": non-manifold vs vtkFeatureEdges");
  CheckAgainstExpected(mesh, filter, label);
}

// A sphere with holes, fins on some edges and repeated faces: border,
// non-manifold and inconsistent edges everywhere.
vtkSmartPointer<vtkPolyData> DamagedSphere(int theta, int phi, unsigned seed)
{
  auto sphere = Sphere(theta, phi);
  vtkNew<vtkPoints> points;
  points->DeepCopy(sphere->GetPoints());
  vtkNew<vtkCellArray> polys;
  std::mt19937 random(seed);
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* in = sphere->GetPolys();
  for (in->InitTraversal(); in->GetNextCell(n, ids);)
  {
    const unsigned r = random() % 20;
    if (r == 0)
    {
      continue; // a hole
    }
    polys->InsertNextCell(n, ids);
    if (r == 1)
    {
      // A fin on the face's first edge.
      double p[3], q[3];
      points->GetPoint(ids[0], p);
      points->GetPoint(ids[1], q);
      const vtkIdType tip = points->InsertNextPoint(
        0.5 * (p[0] + q[0]) * 1.2, 0.5 * (p[1] + q[1]) * 1.2, 0.5 * (p[2] + q[2]) * 1.2);
      const vtkIdType fin[3] = { ids[0], ids[1], tip };
      polys->InsertNextCell(3, fin);
    }
    else if (r == 2)
    {
      polys->InsertNextCell(n, ids); // the same face twice
    }
    else if (r == 3)
    {
      const vtkIdType flipped[3] = { ids[0], ids[2], ids[1] };
      polys->InsertNextCell(3, flipped); // and once more, turned round
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

// More than 2 x 2^17 faces: built in several OpenMesh chunks, with fins,
// repeated and flipped faces whose edges cross from the last chunk to the first.
void TestChunks()
{
  auto grid = Grid(370, 360);
  vtkPoints* points = grid->GetPoints();
  vtkCellArray* polys = grid->GetPolys();
  const vtkIdType first = polys->GetNumberOfCells();
  // Faces of the first rows, copied at the end (the last chunk).
  for (vtkIdType c = 0; c < 400; c += 7)
  {
    vtkIdType n;
    const vtkIdType* ids;
    polys->GetCellAtId(c, n, ids);
    const std::vector<vtkIdType> face(ids, ids + n);
    if (c % 3 == 0)
    {
      const vtkIdType tip = points->InsertNextPoint(double(c), -1.0, 1.0);
      const vtkIdType fin[3] = { face[0], face[1], tip };
      polys->InsertNextCell(3, fin);
    }
    else if (c % 3 == 1)
    {
      polys->InsertNextCell(3, face.data());
    }
    else
    {
      const vtkIdType flipped[3] = { face[0], face[2], face[1] };
      polys->InsertNextCell(3, flipped);
    }
  }
  grid->Modified();
  MESH_CHECK(first >= 2 * (vtkIdType(1) << 17), "the grid is large enough for two chunks");
  CompareWithFeatureEdges(grid, "chunked grid");
  auto filter = Run(grid);
  MESH_CHECK(filter->GetNumberOfInconsistentEdges() > 0, "chunked grid: inconsistent edges");
  MESH_CHECK(filter->GetNumberOfNonManifoldEdges() > 0, "chunked grid: non-manifold edges");
}
}

int TestEdgeAdjacencyFilter(int, char*[])
{
  TestTetrahedron();
  TestOpenSquare();
  TestFin();
  TestMoebius();

  CompareWithFeatureEdges(Sphere(40, 30), "sphere");
  CompareWithFeatureEdges(Grid(50, 40), "grid");
  CompareWithFeatureEdges(Grid(30, 30, 0.5), "roof");
  CompareWithFeatureEdges(Moebius(100), "Moebius strip, 100 segments");
  CompareWithFeatureEdges(DamagedSphere(60, 40, 1), "damaged sphere");
  CompareWithFeatureEdges(DamagedSphere(30, 20, 2), "damaged sphere 2");
  {
    vtkNew<vtkFenceSource> fence;
    fence->Update();
    CompareWithFeatureEdges(fence->GetOutput(), "fence");
  }
  TestChunks();

  if (meshtest::Failures())
  {
    std::fprintf(stderr, "TestEdgeAdjacencyFilter: %d failures\n", meshtest::Failures());
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
