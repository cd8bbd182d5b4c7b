// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// meshbench: times the mesh-topology filters on a generated mesh of about a
// million triangles (no download): triangles per second for the topology aware
// mesh and the edge adjacency, edges per second for light silhouettes (brute
// force, and the normal-cone tree after its build), and the TAM's bytes
// against the input mesh's. A program run on purpose, not a test.
//
//   meshbench [--mesh knot|sphere] [--triangles N] [--runs R] [--lights K]
//             [--smp BACKEND] [--threads T]

#include "vtkEdgeAdjacencyFilter.h"
#include "vtkLightSilhouetteFilter.h"
#include "vtkTopologyAwareMeshFilter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSphereSource.h"
#include "vtkTypeInt32Array.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// A (2, 3) torus knot (a trefoil) as a closed tube: U rings of V points, two
// triangles per quad, point normals. The Frenet frame of a torus knot is
// periodic (its curvature never vanishes), so the tube closes without a twist.
vtkSmartPointer<vtkPolyData> TorusKnot(vtkIdType triangles)
{
  const double ringRadius = 1.0, knotRadius = 0.4, tubeRadius = 0.12;
  // Quads about as long as they are wide: the knot is ~17 long, the tube
  // ~0.75 round, so about 23 rings for every point around.
  const int v = std::max(8, static_cast<int>(std::lround(std::sqrt(triangles / 2.0 / 23.0))));
  const int u = std::max(16, static_cast<int>(triangles / (2 * v)));
  auto curve = [&](double t)
  {
    const double r = ringRadius + knotRadius * std::cos(3.0 * t);
    return glm::dvec3(r * std::cos(2.0 * t), knotRadius * std::sin(3.0 * t), r * std::sin(2.0 * t));
  };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(u) * v);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(u) * v);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < u; ++i)
  {
    const double t = 2.0 * pi * i / u;
    const double h = 1e-4;
    const glm::dvec3 c = curve(t);
    const glm::dvec3 d1 = (curve(t + h) - curve(t - h)) / (2.0 * h);
    const glm::dvec3 d2 = (curve(t + h) - 2.0 * c + curve(t - h)) / (h * h);
    const glm::dvec3 tangent = glm::normalize(d1);
    const glm::dvec3 normal = glm::normalize(d2 - glm::dot(d2, tangent) * tangent);
    const glm::dvec3 binormal = glm::cross(tangent, normal);
    for (int j = 0; j < v; ++j)
    {
      const double a = 2.0 * pi * j / v;
      const glm::dvec3 n = std::cos(a) * normal + std::sin(a) * binormal;
      const glm::dvec3 p = c + tubeRadius * n;
      const vtkIdType id = static_cast<vtkIdType>(i) * v + j;
      points->SetPoint(id, p.x, p.y, p.z);
      normals->SetTuple3(id, n.x, n.y, n.z);
    }
  }
  vtkNew<vtkTypeInt32Array> offsets;
  vtkNew<vtkTypeInt32Array> connectivity;
  const vtkIdType numTriangles = 2 * static_cast<vtkIdType>(u) * v;
  offsets->SetNumberOfValues(numTriangles + 1);
  connectivity->SetNumberOfValues(3 * numTriangles);
  vtkIdType k = 0;
  for (int i = 0; i < u; ++i)
  {
    for (int j = 0; j < v; ++j)
    {
      const int a = i * v + j;
      const int b = ((i + 1) % u) * v + j;
      const int c = ((i + 1) % u) * v + (j + 1) % v;
      const int d = i * v + (j + 1) % v;
      // Outward: the tube's normal is n, the curve runs along +i, the ring
      // turns from normal to binormal along +j.
      const int quad[6] = { a, d, c, a, c, b };
      for (int q = 0; q < 6; ++q)
      {
        if (q % 3 == 0)
        {
          offsets->SetValue(k / 3, static_cast<std::int32_t>(k));
        }
        connectivity->SetValue(k++, quad[q]);
      }
    }
  }
  offsets->SetValue(numTriangles, static_cast<std::int32_t>(k));
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetNormals(normals);
  return mesh;
}

vtkSmartPointer<vtkPolyData> Sphere(vtkIdType triangles)
{
  // vtkSphereSource makes 2 T (P - 2) triangles; P = T / 2 + 1 keeps them
  // about square at the equator.
  const int t = static_cast<int>(std::lround(std::sqrt(static_cast<double>(triangles))));
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(t);
  source->SetPhiResolution(t / 2 + 1);
  source->Update();
  return source->GetOutput();
}

// Fresh memory's first touch on this machine: the cost the filters' outputs
// pay before any of their own work.
double PageFaultMicroseconds()
{
  const std::size_t bytes = std::size_t(64) << 20;
  const auto start = Clock::now();
  char* block = static_cast<char*>(std::malloc(bytes));
  for (std::size_t i = 0; i < bytes; i += 4096)
  {
    block[i] = 1;
  }
  const double seconds = Seconds(start);
  volatile char keep = block[bytes / 2];
  (void)keep;
  std::free(block);
  return 1e6 * seconds / (bytes / 4096);
}

// Median seconds of `runs` updates of `filter`, each after Modified().
double TimeUpdates(vtkAlgorithm* filter, int runs)
{
  std::vector<double> times;
  for (int r = 0; r < runs; ++r)
  {
    filter->Modified();
    const auto start = Clock::now();
    filter->Update();
    times.push_back(Seconds(start));
  }
  return Median(times);
}

void Usage()
{
  std::fprintf(stderr,
    "usage: meshbench [--mesh knot|sphere] [--triangles N] [--runs R] [--lights K]\n"
    "                 [--smp Sequential|STDThread|TBB|OpenMP] [--threads T]\n");
}
}

int main(int argc, char* argv[])
{
  std::string meshName = "knot";
  vtkIdType triangles = 1000000;
  int runs = 7;
  int lights = 50;
  std::string backend;
  int threads = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (i + 1 >= argc)
    {
      Usage();
      return 2;
    }
    const char* value = argv[++i];
    if (arg == "--mesh")
    {
      meshName = value;
    }
    else if (arg == "--triangles")
    {
      triangles = std::atoll(value);
    }
    else if (arg == "--runs")
    {
      runs = std::atoi(value);
    }
    else if (arg == "--lights")
    {
      lights = std::atoi(value);
    }
    else if (arg == "--smp")
    {
      backend = value;
    }
    else if (arg == "--threads")
    {
      threads = std::atoi(value);
    }
    else
    {
      Usage();
      return 2;
    }
  }
  if ((meshName != "knot" && meshName != "sphere") || triangles < 100 || runs < 1 || lights < 1)
  {
    Usage();
    return 2;
  }

  // Threads: whatever VTK was built with by default (Debian's is TBB), but
  // never the sequential backend when STDThread is there.
  if (!backend.empty())
  {
    if (!vtkSMPTools::SetBackend(backend.c_str()))
    {
      std::fprintf(stderr, "meshbench: SMP backend %s is not available\n", backend.c_str());
      return 2;
    }
  }
  else if (std::strcmp(vtkSMPTools::GetBackend(), "Sequential") == 0)
  {
    vtkSMPTools::SetBackend("STDThread");
  }
  if (threads > 0)
  {
    vtkSMPTools::Initialize(threads);
  }

  const auto generate = Clock::now();
  vtkSmartPointer<vtkPolyData> mesh = meshName == "knot" ? TorusKnot(triangles) : Sphere(triangles);
  const double generateSeconds = Seconds(generate);
  const vtkIdType numTriangles = mesh->GetNumberOfPolys();
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::printf("mesh: %s, %lld triangles, %lld points (generated in %.2f s)\n", meshName.c_str(),
    static_cast<long long>(numTriangles), static_cast<long long>(mesh->GetNumberOfPoints()),
    generateSeconds);
  std::printf("threads: vtkSMPTools backend %s, %d threads\n", vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads());
  std::printf("memory: first touch of fresh memory %.2f us per 4 KiB page (GLIBC_TUNABLES=%s)\n",
    PageFaultMicroseconds(), tunables ? tunables : "");
  std::printf("timings: median of %d updates (each after Modified())\n\n", runs);

  // Edge adjacency.
  vtkNew<vtkEdgeAdjacencyFilter> adjacency;
  adjacency->SetInputData(mesh);
  const double adjacencySeconds = TimeUpdates(adjacency, runs);
  std::printf("edge adjacency        %8.1f ms  %6.2f M triangles/s  (%lld edges: %lld border, "
              "%lld manifold, %lld non-manifold)\n",
    1e3 * adjacencySeconds, numTriangles / adjacencySeconds / 1e6,
    static_cast<long long>(adjacency->GetOutput()->GetNumberOfLines()),
    static_cast<long long>(adjacency->GetNumberOfBorderEdges()),
    static_cast<long long>(adjacency->GetNumberOfManifoldEdges()),
    static_cast<long long>(adjacency->GetNumberOfNonManifoldEdges()));
  adjacency->RemoveAllInputs();
  adjacency->GetOutput()->Initialize();

  // Topology aware mesh, each layout.
  struct Layout
  {
    const char* Name;
    bool Half;
    bool PerFace;
  };
  const Layout layouts[] = { { "TAM (default: float, per vertex)", false, false },
    { "TAM half precision", true, false }, { "TAM per-face attributes", false, true },
    { "TAM half, per-face", true, true } };
  for (const Layout& layout : layouts)
  {
    vtkNew<vtkTopologyAwareMeshFilter> tam;
    tam->SetInputData(mesh);
    tam->SetHalfPrecision(layout.Half);
    tam->SetPerFaceAttributes(layout.PerFace);
    const double seconds = TimeUpdates(tam, runs);
    std::printf("%-34s %8.1f ms  %6.2f M triangles/s  TAM %7.1f MB = %5.2f x input %6.1f MB\n",
      layout.Name, 1e3 * seconds, numTriangles / seconds / 1e6,
      tam->GetTopologyAwareMeshBytes() / 1048576.0, tam->GetMemoryRatio(),
      tam->GetInputMeshBytes() / 1048576.0);
  }
  {
    vtkNew<vtkTopologyAwareMeshFilter> tam;
    tam->SetInputData(mesh);
    tam->DropNonSilhouetteFacesOn();
    tam->Update();
    std::printf("TAM dropping faces that can never be silhouettes: %lld of %lld dropped\n",
      static_cast<long long>(tam->GetNumberOfDroppedFaces()), static_cast<long long>(numTriangles));
  }

  // Silhouettes: the same lights for both searches, positional ones around
  // the mesh and directional ones, alternately.
  double bounds[6];
  mesh->GetBounds(bounds);
  const glm::dvec3 center(
    0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.5 * (bounds[4] + bounds[5]));
  const double radius = 0.5 *
    glm::length(glm::dvec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]));
  std::mt19937 random(12345);
  std::normal_distribution<double> gauss;
  std::vector<glm::dvec3> positions;
  for (int i = 0; i < lights; ++i)
  {
    const glm::dvec3 direction =
      glm::normalize(glm::dvec3(gauss(random), gauss(random), gauss(random)));
    positions.push_back(i % 2 == 0 ? center + 3.0 * radius * direction : direction);
  }

  vtkNew<vtkLightSilhouetteFilter> brute;
  brute->SetInputData(mesh);
  brute->SetMethodToBruteForce();
  vtkNew<vtkLightSilhouetteFilter> tree;
  tree->SetInputData(mesh);
  brute->Update();
  const double bruteBuild = brute->GetBuildTime();
  tree->Update();
  const double treeBuild = tree->GetBuildTime();
  std::vector<double> bruteTimes, treeTimes, bruteSearch, treeSearch;
  vtkIdType mismatches = 0, silhouetteEdges = 0, tested = 0;
  for (int i = 0; i < lights; ++i)
  {
    const glm::dvec3& p = positions[i];
    for (vtkLightSilhouetteFilter* filter : { brute.GetPointer(), tree.GetPointer() })
    {
      filter->SetLightPosition(p.x, p.y, p.z);
      filter->SetPositional(i % 2 == 0);
      const auto start = Clock::now();
      filter->Update();
      const double seconds = Seconds(start);
      (filter == brute.GetPointer() ? bruteTimes : treeTimes).push_back(seconds);
      (filter == brute.GetPointer() ? bruteSearch : treeSearch).push_back(filter->GetSearchTime());
    }
    // The same set of edges (the tree lists them in its own order).
    auto edgeIds = [](vtkLightSilhouetteFilter* filter)
    {
      auto* array =
        vtkIdTypeArray::SafeDownCast(filter->GetOutput()->GetCellData()->GetArray("EdgeIds"));
      std::vector<vtkIdType> ids(
        array->GetPointer(0), array->GetPointer(0) + array->GetNumberOfValues());
      std::sort(ids.begin(), ids.end());
      return ids;
    };
    const bool same = edgeIds(brute) == edgeIds(tree);
    mismatches += same ? 0 : 1;
    silhouetteEdges += brute->GetNumberOfSilhouetteEdges();
    tested += tree->GetNumberOfTestedEdges();
  }
  // Each method alone over a list of lights in a row, as a smoothie pass
  // would call it frame after frame: the other's memory traffic no longer
  // evicts its data between lights. Lights are (x, y, z, positional).
  auto inARow = [](vtkLightSilhouetteFilter* filter, const std::vector<glm::dvec4>& sequence)
  {
    std::vector<double> times;
    for (const glm::dvec4& l : sequence)
    {
      filter->SetLightPosition(l.x, l.y, l.z);
      filter->SetPositional(l.w != 0.0);
      const auto start = Clock::now();
      filter->Update();
      times.push_back(Seconds(start));
    }
    return Median(times);
  };
  std::vector<glm::dvec4> scattered;
  for (int i = 0; i < lights; ++i)
  {
    scattered.emplace_back(positions[i], i % 2 == 0 ? 1.0 : 0.0);
  }
  const double bruteRow = inARow(brute, scattered);
  const double treeRow = inARow(tree, scattered);
  // A light dragged around the mesh, a degree a frame on a tilted circle: a
  // smoothie pass during interaction. Consecutive lights see nearly the same
  // silhouette, so the tree may find its nodes still in the caches.
  std::vector<glm::dvec4> dragged;
  for (int frame = 0; frame < 180; ++frame)
  {
    const double a = 3.14159265358979323846 * frame / 180.0;
    const glm::dvec3 offset =
      glm::normalize(glm::dvec3(std::cos(a), 0.5 * std::sin(a), std::sin(a)));
    dragged.emplace_back(center + 3.0 * radius * offset, 1.0);
  }
  const double bruteOrbit = inARow(brute, dragged);
  const double treeOrbit = inARow(tree, dragged);

  const vtkIdType numEdges = brute->GetNumberOfEdges();
  const double bruteSeconds = Median(bruteTimes);
  const double treeSeconds = Median(treeTimes);
  const double bruteSearchSeconds = Median(bruteSearch);
  const double treeSearchSeconds = Median(treeSearch);
  std::printf("\nsilhouettes over %lld edges, %d lights (half positional, half directional), "
              "%lld silhouette edges a light on average\n",
    static_cast<long long>(numEdges), lights, static_cast<long long>(silhouetteEdges / lights));
  std::printf(
    "  edge map build (both)                %8.1f ms (once per mesh)\n", 1e3 * bruteBuild);
  std::printf("  edge map + normal-cone tree build    %8.1f ms (once per mesh)\n", 1e3 * treeBuild);
  std::printf("  a light, whole update (search + output; median), methods alternating:\n");
  std::printf("    brute force      %8.3f ms  %8.1f M edges/s\n", 1e3 * bruteSeconds,
    numEdges / bruteSeconds / 1e6);
  std::printf("    normal-cone tree %8.3f ms  %8.1f M edges/s  %5.1fx brute force\n",
    1e3 * treeSeconds, numEdges / treeSeconds / 1e6, bruteSeconds / treeSeconds);
  std::printf("  a light, whole update, each method alone over all lights in a row:\n");
  std::printf(
    "    brute force      %8.3f ms  %8.1f M edges/s\n", 1e3 * bruteRow, numEdges / bruteRow / 1e6);
  std::printf("    normal-cone tree %8.3f ms  %8.1f M edges/s  %5.1fx brute force\n", 1e3 * treeRow,
    numEdges / treeRow / 1e6, bruteRow / treeRow);
  std::printf("  a light dragged a degree a frame, 180 frames, each method alone:\n");
  std::printf("    brute force      %8.3f ms  %8.1f M edges/s\n", 1e3 * bruteOrbit,
    numEdges / bruteOrbit / 1e6);
  std::printf("    normal-cone tree %8.3f ms  %8.1f M edges/s  %5.1fx brute force\n",
    1e3 * treeOrbit, numEdges / treeOrbit / 1e6, bruteOrbit / treeOrbit);
  std::printf("  a light, search only (GetSearchTime(); median), methods alternating:\n");
  std::printf("    brute force      %8.3f ms  %8.1f M edges/s\n", 1e3 * bruteSearchSeconds,
    numEdges / bruteSearchSeconds / 1e6);
  std::printf("    normal-cone tree %8.3f ms  %8.1f M edges/s  %5.1fx brute force (tests %lld "
              "edges a light)\n",
    1e3 * treeSearchSeconds, numEdges / treeSearchSeconds / 1e6,
    bruteSearchSeconds / treeSearchSeconds, static_cast<long long>(tested / lights));
  std::printf("  identical edge sets: %s (%lld of %d lights differ)\n", mismatches ? "NO" : "yes",
    static_cast<long long>(mismatches), lights);
  return mismatches ? 1 : 0;
}
