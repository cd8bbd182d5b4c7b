// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the mesh-topology filter tests: small meshes checked by
// hand, generated larger ones, a log of a filter's errors and warnings, and a
// check macro that records failures and lets the test go on.

#ifndef MeshFilterTestUtilities_h
#define MeshFilterTestUtilities_h

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFeatureEdges.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

namespace meshtest
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

#define MESH_CHECK(condition, message)                                                             \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::fprintf(stderr, "%s:%d: check failed: %s: %s\n", __FILE__, __LINE__, #condition,        \
        std::string(message).c_str());                                                             \
      ++meshtest::Failures();                                                                      \
    }                                                                                              \
  } while (false)

#define MESH_CHECK_EQUAL(actual, expected, message)                                                \
  do                                                                                               \
  {                                                                                                \
    const auto meshActual = (actual);                                                              \
    const auto meshExpected = (expected);                                                          \
    if (!(meshActual == meshExpected))                                                             \
    {                                                                                              \
      std::fprintf(stderr, "%s:%d: %s: got %s, expected %s\n", __FILE__, __LINE__,                 \
        std::string(message).c_str(), std::to_string(meshActual).c_str(),                          \
        std::to_string(meshExpected).c_str());                                                     \
      ++meshtest::Failures();                                                                      \
    }                                                                                              \
  } while (false)

/// The errors and warnings a filter (and its executive) reports, kept
/// instead of printed.
class MessageLog : public vtkCommand
{
public:
  static MessageLog* New() { return new MessageLog; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  void Watch(vtkAlgorithm* filter)
  {
    filter->AddObserver(vtkCommand::ErrorEvent, this);
    filter->AddObserver(vtkCommand::WarningEvent, this);
    filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this);
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
  }
  bool ErrorContains(const std::string& text) const
  {
    for (const std::string& e : this->Errors)
    {
      if (e.find(text) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  int WarningsContaining(const std::string& text) const
  {
    int n = 0;
    for (const std::string& w : this->Warnings)
    {
      n += w.find(text) != std::string::npos ? 1 : 0;
    }
    return n;
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

/// A polydata of points and triangles (or any polygons).
inline vtkSmartPointer<vtkPolyData> MakeMesh(const std::vector<std::vector<double>>& points,
  const std::vector<std::vector<vtkIdType>>& polygons)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : points)
  {
    pts->InsertNextPoint(p[0], p[1], p[2]);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& polygon : polygons)
  {
    polys->InsertNextCell(static_cast<vtkIdType>(polygon.size()), polygon.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(pts);
  mesh->SetPolys(polys);
  return mesh;
}

/// Corners (0,0,0), (1,0,0), (0,1,0), (0,0,1); faces wound outward.
inline vtkSmartPointer<vtkPolyData> Tetrahedron()
{
  return MakeMesh({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
    { { 0, 2, 1 }, { 0, 1, 3 }, { 0, 3, 2 }, { 1, 2, 3 } });
}

/// The unit square on z = 0 as two triangles sharing the diagonal 0-2.
inline vtkSmartPointer<vtkPolyData> OpenSquare()
{
  return MakeMesh(
    { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 2, 3 } });
}

/// Three triangles on the edge 0-1 (the z axis), at 0, 120 and 240 degrees.
inline vtkSmartPointer<vtkPolyData> Fin()
{
  const double s = std::sqrt(3.0) / 2.0;
  return MakeMesh({ { 0, 0, 0 }, { 0, 0, 1 }, { 1, 0, 0 }, { -0.5, s, 0 }, { -0.5, -s, 0 } },
    { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 0, 4 } });
}

/// A Moebius strip of `segments` quads (two triangles each) around a circle
/// of radius 1, half width `width`: points 2 i and 2 i + 1 are the ends of
/// the cross-section at angle 2 pi i / segments, turned by half that angle.
/// The last quad joins the first one flipped: the rung 0-1 is run the same
/// way by its two faces.
inline vtkSmartPointer<vtkPolyData> Moebius(int segments, double width = 0.3)
{
  std::vector<std::vector<double>> points;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < segments; ++i)
  {
    const double t = 2.0 * pi * i / segments;
    for (double s : { -width, width })
    {
      const double r = 1.0 + s * std::cos(t / 2.0);
      points.push_back({ r * std::cos(t), r * std::sin(t), s * std::sin(t / 2.0) });
    }
  }
  std::vector<std::vector<vtkIdType>> triangles;
  for (vtkIdType i = 0; i < segments; ++i)
  {
    const vtkIdType a = 2 * i, b = 2 * i + 1;
    // The next cross-section; after the last one, the first one flipped.
    const vtkIdType c = i + 1 < segments ? 2 * i + 2 : 1;
    const vtkIdType d = i + 1 < segments ? 2 * i + 3 : 0;
    triangles.push_back({ a, c, d });
    triangles.push_back({ a, d, b });
  }
  return MakeMesh(points, triangles);
}

/// A flat grid of nx x ny unit quads on z = 0, each split along (i,j)-(i+1,j+1);
/// `fold` lifts every point by fold * |x - nx / 2| (a roof).
inline vtkSmartPointer<vtkPolyData> Grid(int nx, int ny, double fold = 0.0)
{
  std::vector<std::vector<double>> points;
  for (int j = 0; j <= ny; ++j)
  {
    for (int i = 0; i <= nx; ++i)
    {
      points.push_back({ double(i), double(j), fold * std::abs(i - nx / 2.0) });
    }
  }
  std::vector<std::vector<vtkIdType>> triangles;
  auto id = [nx](int i, int j) { return static_cast<vtkIdType>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
  {
    for (int i = 0; i < nx; ++i)
    {
      triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return MakeMesh(points, triangles);
}

inline vtkSmartPointer<vtkPolyData> Sphere(int theta, int phi)
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(theta);
  source->SetPhiResolution(phi);
  source->Update();
  return source->GetOutput();
}

/// Boundary and non-manifold edge counts by VTK's own vtkFeatureEdges.
inline void FeatureEdgeCounts(vtkPolyData* mesh, vtkIdType& boundary, vtkIdType& nonManifold)
{
  for (int pass = 0; pass < 2; ++pass)
  {
    vtkNew<vtkFeatureEdges> edges;
    edges->SetInputData(mesh);
    edges->FeatureEdgesOff();
    edges->ManifoldEdgesOff();
    edges->SetBoundaryEdges(pass == 0);
    edges->SetNonManifoldEdges(pass == 1);
    edges->ColoringOff();
    edges->Update();
    (pass == 0 ? boundary : nonManifold) = edges->GetOutput()->GetNumberOfLines();
  }
}

/// The unit normal of triangle (a, b, c) of `mesh`, by its winding.
inline void TriangleNormal(vtkPolyData* mesh, vtkIdType a, vtkIdType b, vtkIdType c, double n[3])
{
  double p[3], q[3], r[3];
  mesh->GetPoint(a, p);
  mesh->GetPoint(b, q);
  mesh->GetPoint(c, r);
  const double u[3] = { q[0] - p[0], q[1] - p[1], q[2] - p[2] };
  const double v[3] = { r[0] - p[0], r[1] - p[1], r[2] - p[2] };
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int k = 0; k < 3; ++k)
  {
    n[k] = length > 0 ? n[k] / length : 0.0;
  }
}

inline bool Near(const double* a, const double* b, int n, double tolerance)
{
  for (int k = 0; k < n; ++k)
  {
    if (!(std::abs(a[k] - b[k]) <= tolerance))
    {
      return false;
    }
  }
  return true;
}

/// The cell-data array `name` of `data` as vtkIdTypes, sorted (edge sets).
inline std::vector<vtkIdType> SortedIds(vtkPolyData* data, const char* name)
{
  std::vector<vtkIdType> ids;
  vtkDataArray* array = data->GetCellData()->GetArray(name);
  if (!array)
  {
    return ids;
  }
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    ids.push_back(static_cast<vtkIdType>(array->GetComponent(i, 0)));
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}
}

#endif
