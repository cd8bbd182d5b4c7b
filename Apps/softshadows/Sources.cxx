// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "Sources.h"

#include "vtkFenceSource.h"

#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricTorus.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace softshadows
{
namespace
{
vtkSmartPointer<vtkPolyData> Output(vtkPolyDataAlgorithm* algorithm)
{
  algorithm->Update();
  return algorithm->GetOutput();
}

// Sphere and torus tessellations use half as many segments across as around,
// which keeps their facets roughly square.
int Across(int around)
{
  return std::max(3, around / 2);
}

vtkSmartPointer<vtkPolyData> MakePlane(const Json& p)
{
  const auto size = Components(p["size"], 2);
  const int resolution = p["resolution"].get<int>();
  // Point1 along +z and Point2 along +x make the normal +y.
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.5 * size[0], 0.0, -0.5 * size[1]);
  plane->SetPoint1(-0.5 * size[0], 0.0, 0.5 * size[1]);
  plane->SetPoint2(0.5 * size[0], 0.0, -0.5 * size[1]);
  plane->SetResolution(resolution, resolution);
  return Output(plane);
}

vtkSmartPointer<vtkPolyData> MakeSphere(const Json& p)
{
  const int resolution = p["resolution"].get<int>();
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(p["radius"].get<double>());
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(Across(resolution));
  return Output(sphere);
}

vtkSmartPointer<vtkPolyData> MakeCube(const Json& p)
{
  const auto size = Components(p["size"], 3);
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(size[0]);
  cube->SetYLength(size[1]);
  cube->SetZLength(size[2]);
  return Output(cube);
}

vtkSmartPointer<vtkPolyData> MakeCylinder(const Json& p)
{
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(p["radius"].get<double>());
  cylinder->SetHeight(p["height"].get<double>());
  cylinder->SetResolution(p["resolution"].get<int>());
  cylinder->SetCapping(p["capping"].get<bool>());
  return Output(cylinder);
}

vtkSmartPointer<vtkPolyData> MakeCone(const Json& p)
{
  vtkNew<vtkConeSource> cone;
  cone->SetRadius(p["radius"].get<double>());
  cone->SetHeight(p["height"].get<double>());
  cone->SetResolution(p["resolution"].get<int>());
  cone->SetCapping(p["capping"].get<bool>());
  cone->SetDirection(0.0, 1.0, 0.0);
  return Output(cone);
}

vtkSmartPointer<vtkPolyData> MakeTorus(const Json& p)
{
  const int resolution = p["resolution"].get<int>();
  vtkNew<vtkParametricTorus> torus;
  torus->SetRingRadius(p["ring_radius"].get<double>());
  torus->SetCrossSectionRadius(p["cross_section_radius"].get<double>());
  vtkNew<vtkParametricFunctionSource> surface;
  surface->SetParametricFunction(torus);
  surface->SetUResolution(resolution);
  surface->SetVResolution(Across(resolution));
  // vtkParametricTorus has its axis along z; lay it flat like the other sources.
  vtkNew<vtkTransform> flat;
  flat->RotateX(-90.0);
  vtkNew<vtkTransformPolyDataFilter> transform;
  transform->SetTransform(flat);
  transform->SetInputConnection(surface->GetOutputPort());
  return Output(transform);
}

// A (p, q) torus knot: a tube of radius `tube` around the curve winding p
// times around the y axis and q times through the hole of a torus of radii
// R and r. Its frame (the tangent, and the direction from the torus's core
// circle made normal to it) is periodic, so the quad mesh closes on itself
// without a seam: closed and manifold, every face shadowing another.
vtkSmartPointer<vtkPolyData> MakeKnot(const Json& params)
{
  const int p = params["p"].get<int>();
  const int q = params["q"].get<int>();
  const double ring = params["ring_radius"].get<double>();
  const double wind = params["winding_radius"].get<double>();
  const double tube = params["tube_radius"].get<double>();
  const int around = params["resolution"].get<int>();
  const int across = std::max(3, around / 16);
  auto curve = [&](double t)
  {
    const double w = ring + wind * std::cos(q * t);
    return std::array<double, 3>{ { w * std::cos(p * t), wind * std::sin(q * t),
      w * std::sin(p * t) } };
  };
  vtkNew<vtkPoints> points;
  points->SetNumberOfPoints(static_cast<vtkIdType>(around) * across);
  const double step = 2.0 * vtkMath::Pi() / around;
  for (int i = 0; i < around; ++i)
  {
    const double t = i * step;
    const auto c = curve(t);
    const auto ahead = curve(t + 1.0e-4);
    const auto behind = curve(t - 1.0e-4);
    double tangent[3] = { ahead[0] - behind[0], ahead[1] - behind[1], ahead[2] - behind[2] };
    vtkMath::Normalize(tangent);
    double normal[3] = { c[0] - ring * std::cos(p * t), c[1], c[2] - ring * std::sin(p * t) };
    const double along = vtkMath::Dot(normal, tangent);
    for (int k = 0; k < 3; ++k)
    {
      normal[k] -= along * tangent[k];
    }
    vtkMath::Normalize(normal);
    double binormal[3];
    vtkMath::Cross(tangent, normal, binormal);
    for (int j = 0; j < across; ++j)
    {
      const double a = 2.0 * vtkMath::Pi() * j / across;
      const double x = tube * std::cos(a), y = tube * std::sin(a);
      points->SetPoint(static_cast<vtkIdType>(i) * across + j,
        c[0] + x * normal[0] + y * binormal[0], c[1] + x * normal[1] + y * binormal[1],
        c[2] + x * normal[2] + y * binormal[2]);
    }
  }
  vtkNew<vtkCellArray> quads;
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < across; ++j)
    {
      auto id = [&](int a, int b)
      { return static_cast<vtkIdType>((a % around) * across + (b % across)); };
      const vtkIdType quad[4] = { id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) };
      quads->InsertNextCell(4, quad);
    }
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(quads);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->AutoOrientNormalsOn(); // outwards, whatever the frame's handedness
  return Output(normals);
}

vtkSmartPointer<vtkPolyData> MakeFence(const Json& p)
{
  vtkNew<vtkFenceSource> fence;
  fence->SetNumberOfPickets(p["pickets"].get<int>());
  fence->SetPicketWidth(p["picket_width"].get<double>());
  fence->SetGap(p["gap"].get<double>());
  fence->SetHeight(p["height"].get<double>());
  fence->SetThickness(p["thickness"].get<double>());
  return Output(fence);
}

// A sphere whose radius a sum of `waves` plane waves of frequency
// `frequency` (cycles across the unit sphere's diameter) in random directions
// and phases modulates by up to `bumps` times the radius: a lumpy, organic
// shape whose folds shadow each other. The same seed, the same shape.
vtkSmartPointer<vtkPolyData> MakeBlob(const Json& p)
{
  const int resolution = p["resolution"].get<int>();
  const double radius = p["radius"].get<double>();
  const double bumps = p["bumps"].get<double>();
  const double frequency = p["frequency"].get<double>();
  constexpr int Waves = 8;
  std::mt19937 random(p["seed"].get<unsigned int>());
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> uniform(0.0, 2.0 * vtkMath::Pi());
  std::array<std::array<double, 4>, Waves> waves{}; // direction, phase
  for (auto& wave : waves)
  {
    double direction[3] = { gaussian(random), gaussian(random), gaussian(random) };
    vtkMath::Normalize(direction);
    wave = { direction[0], direction[1], direction[2], uniform(random) };
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(Across(resolution));
  sphere->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->CopyStructure(sphere->GetOutput());
  vtkNew<vtkPoints> points;
  points->DeepCopy(sphere->GetOutput()->GetPoints());
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    double sum = 0.0;
    for (const auto& wave : waves)
    {
      sum += std::sin(vtkMath::Pi() * frequency * vtkMath::Dot(x, wave.data()) + wave[3]);
    }
    const double scale = radius * (1.0 + bumps * sum / std::sqrt(static_cast<double>(Waves)));
    points->SetPoint(i, scale * x[0], scale * x[1], scale * x[2]);
  }
  mesh->SetPoints(points);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  return Output(normals);
}

// A gyroid sheet cut by a ball: the triply periodic minimal surface
// g = sin x cos y + sin y cos z + sin z cos x = 0, `cells` periods across the
// ball's diameter, thickened to a sheet `thickness` of a period thick (about:
// |g| < pi * thickness, g's gradient being about 1 a radian), its surface
// extracted by vtkFlyingEdges3D from `resolution` samples across. A closed,
// dense isosurface of tunnels whose walls shadow each other, as scientific
// visualization draws them; about 10 * cells * resolution^2 triangles.
vtkSmartPointer<vtkPolyData> MakeGyroid(const Json& p)
{
  const double radius = p["radius"].get<double>();
  const int n = p["resolution"].get<int>();
  const double k = 2.0 * vtkMath::Pi() * p["cells"].get<double>() / (2.0 * radius);
  const double half = vtkMath::Pi() * p["thickness"].get<double>();
  // A sample beyond the ball on every side, so that its surface closes.
  const double extent = radius * (1.0 + 2.5 / n);
  const double spacing = 2.0 * extent / (n - 1);
  // The grid's coordinate along each axis, and its sine and cosine.
  std::vector<double> coordinates(n), sines(n), cosines(n);
  for (int i = 0; i < n; ++i)
  {
    coordinates[i] = -extent + i * spacing;
    sines[i] = std::sin(k * coordinates[i]);
    cosines[i] = std::cos(k * coordinates[i]);
  }
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(n, n, n);
  grid->SetOrigin(-extent, -extent, -extent);
  grid->SetSpacing(spacing, spacing, spacing);
  vtkNew<vtkFloatArray> field;
  field->SetNumberOfValues(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int z = 0; z < n; ++z)
  {
    for (int y = 0; y < n; ++y)
    {
      for (int x = 0; x < n; ++x, ++id)
      {
        // Both terms in world units: inside where both are negative.
        const double g = sines[x] * cosines[y] + sines[y] * cosines[z] + sines[z] * cosines[x];
        const double sheet = (std::abs(g) - half) / k;
        const double px = coordinates[x], py = coordinates[y], pz = coordinates[z];
        const double ball = std::sqrt(px * px + py * py + pz * pz) - radius;
        field->SetValue(id, static_cast<float>(std::max(sheet, ball)));
      }
    }
  }
  grid->GetPointData()->SetScalars(field);
  vtkNew<vtkFlyingEdges3D> surface;
  surface->SetInputData(grid);
  surface->SetValue(0, 0.0);
  surface->ComputeNormalsOn();
  surface->ComputeScalarsOff();
  return Output(surface);
}

const Range Segments = Range::Between(3, 1024);
}

//------------------------------------------------------------------------------
const std::vector<Source>& Sources()
{
  static const std::vector<Source> sources = {
    { "plane", "a rectangle on y = 0 facing +y, centred on the origin",
      {
        { "size", ValueType::Size2, Range::Positive(), 10.0, "extent along x and z" },
        { "resolution", ValueType::Integer, Range::Between(1, 1024), 1,
          "subdivisions along each side" },
      },
      MakePlane },
    { "sphere", "a sphere centred on the origin",
      {
        { "radius", ValueType::Number, Range::Positive(), 0.5, "radius" },
        { "resolution", ValueType::Integer, Segments, 32,
          "segments around the y axis (half as many from pole to pole)" },
      },
      MakeSphere },
    { "cube", "a box centred on the origin",
      {
        { "size", ValueType::Size3, Range::Positive(), 1.0, "edge lengths along x, y and z" },
      },
      MakeCube },
    { "cylinder", "a cylinder along y centred on the origin",
      {
        { "radius", ValueType::Number, Range::Positive(), 0.5, "radius" },
        { "height", ValueType::Number, Range::Positive(), 1.0, "length along y" },
        { "resolution", ValueType::Integer, Segments, 32, "segments around the axis" },
        { "capping", ValueType::Boolean, Range::Any(), true, "close both ends" },
      },
      MakeCylinder },
    { "cone", "a cone along y pointing up, its axis' midpoint on the origin",
      {
        { "radius", ValueType::Number, Range::Positive(), 0.5, "radius of the base" },
        { "height", ValueType::Number, Range::Positive(), 1.0, "base to apex along y" },
        { "resolution", ValueType::Integer, Segments, 32, "segments around the axis" },
        { "capping", ValueType::Boolean, Range::Any(), true, "close the base" },
      },
      MakeCone },
    { "torus", "a ring lying flat (axis y) centred on the origin",
      {
        { "ring_radius", ValueType::Number, Range::Positive(), 1.0,
          "from the axis to the centre of the tube" },
        { "cross_section_radius", ValueType::Number, Range::Positive(), 0.5, "radius of the tube" },
        { "resolution", ValueType::Integer, Segments, 48,
          "segments around the axis (half as many around the tube)" },
      },
      MakeTorus },
    { "knot", "a tube along a (p, q) torus knot lying flat (axis y), centred on the origin",
      {
        { "p", ValueType::Integer, Range::Between(1, 32), 2, "turns around the y axis" },
        { "q", ValueType::Integer, Range::Between(1, 32), 3, "turns through the hole" },
        { "ring_radius", ValueType::Number, Range::Positive(), 0.5,
          "from the axis to the torus the knot winds on" },
        { "winding_radius", ValueType::Number, Range::Positive(), 0.25,
          "radius of that torus's tube, which the knot winds around" },
        { "tube_radius", ValueType::Number, Range::Positive(), 0.1, "radius of the knot's tube" },
        { "resolution", ValueType::Integer, Range::Between(48, 16384), 384,
          "segments along the knot (a sixteenth as many around its tube)" },
      },
      MakeKnot },
    { "fence", "vtkFenceSource: pickets on two rails, standing on y = 0 along x",
      {
        { "pickets", ValueType::Integer, Range::Between(1, 1000), 7, "number of pickets" },
        { "picket_width", ValueType::Number, Range::Positive(), 0.1,
          "width of a picket along x, also the height of a rail" },
        { "gap", ValueType::Number, Range::AtLeast(0.0), 0.08, "space between pickets" },
        { "height", ValueType::Number, Range::Positive(), 1.0, "height of the pickets" },
        { "thickness", ValueType::Number, Range::Positive(), 0.05,
          "depth of a picket or rail along z" },
      },
      MakeFence },
    { "blob", "a lumpy sphere centred on the origin, its folds shadowing each other",
      {
        { "radius", ValueType::Number, Range::Positive(), 0.5, "radius before the bumps" },
        { "bumps", ValueType::Number, Range::Between(0.0, 0.5), 0.2,
          "typical height of a bump, as a share of the radius" },
        { "frequency", ValueType::Number, Range::Positive(), 3.0, "bumps across the diameter" },
        { "seed", ValueType::Integer, Range::Between(0, 1000000), 1, "which blob" },
        { "resolution", ValueType::Integer, Segments, 128,
          "segments around the vertical axis (half as many from pole to pole)" },
      },
      MakeBlob },
    { "gyroid", "a gyroid sheet cut by a ball centred on the origin: a dense isosurface",
      {
        { "radius", ValueType::Number, Range::Positive(), 0.5, "radius of the ball" },
        { "cells", ValueType::Number, Range::Between(0.5, 64.0), 3.0,
          "periods of the gyroid across the ball's diameter" },
        { "thickness", ValueType::Number, Range::Between(0.01, 0.3), 0.1,
          "the sheet's thickness, as a share of a period" },
        { "resolution", ValueType::Integer, Range::Between(8, 640), 64,
          "samples across the ball along each axis (4 bytes each while it is built); "
          "about 10 x cells x resolution^2 triangles" },
      },
      MakeGyroid },
  };
  return sources;
}

//------------------------------------------------------------------------------
const Source& FindSource(const std::string& name, const std::string& path)
{
  const auto& all = Sources();
  const auto found =
    std::find_if(all.begin(), all.end(), [&](const Source& source) { return source.Name == name; });
  if (found == all.end())
  {
    throw InputError(path,
      "unknown source '" + name + "' " +
        KnownNames(all, [](const Source& source) { return source.Name; }));
  }
  return *found;
}

//------------------------------------------------------------------------------
Json CompleteParameters(const Source& source, const Json& parameters, const std::string& path)
{
  CheckParameters(source.Parameters, parameters, path);
  Json complete = parameters;
  for (const SourceParameter& parameter : source.Parameters)
  {
    if (!complete.contains(parameter.Key))
    {
      complete[parameter.Key] = parameter.Default;
    }
  }
  return complete;
}
}
