// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightSilhouetteFilter.h"

#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSoftShadowsEdgeTable.h"
#include "vtkSoftShadowsNormalConeTree.h"
#include "vtkSoftShadowsTriangleMesh.h"
#include "vtkTypeInt32Array.h"

#include <algorithm> // for std::lower_bound, std::min
#include <chrono>    // for std::chrono::steady_clock
#include <cmath>     // for std::isfinite

vtkStandardNewMacro(vtkLightSilhouetteFilter);

using vtksoftshadows::FacesLight;

//------------------------------------------------------------------------------
// What the searches reuse while the input is unmodified: the faces' planes,
// the edge-to-faces map and, once built, the hierarchy.
struct vtkLightSilhouetteFilter::vtkInternals
{
  vtkPolyData* Input = nullptr; // identity only, with its modification time
  vtkMTimeType InputTime = 0;
  bool Valid = false;
  bool TreeBuilt = false;

  vtksoftshadows::TriangleMesh Mesh;
  vtksoftshadows::EdgeTable Table;
  std::vector<double> Normals; // unit normal a face
  std::vector<double> Offsets; // n . p0 a face
  // Edges the tree does not hold (border, non-manifold, inconsistently
  // oriented, or with a face of zero area): tested one by one every time.
  std::vector<std::int32_t> Irregular;
  vtksoftshadows::NormalConeTree Tree;
  std::vector<unsigned char> Front; // brute force: each face toward the light?

  // Lists every search fills, kept from one to the next: touching fresh
  // memory can cost more than the search itself.
  vtksoftshadows::NormalConeTree::QueryBuffers TreeBuffers;
  std::vector<std::vector<std::int32_t>> Blocks; // brute force: silhouette edges a block
  std::vector<std::int32_t> Silhouette;          // 3 an edge: id, points

  bool FaceFront(std::int32_t face, const double light[4]) const
  {
    return FacesLight(
      this->Normals.data() + 3 * static_cast<vtkIdType>(face), this->Offsets[face], light);
  }

  // All faces on one side of the plane through the edge and the light: the
  // face's side is whether it faces the light, flipped when it runs the edge
  // against the edge's first face. For two faces running the edge in opposite
  // directions this is "one toward the light, one away"; a border edge, with
  // one face, always is one.
  template <typename FrontFn>
  bool IsSilhouette(vtkIdType edge, FrontFn&& front) const
  {
    const std::int32_t* faces = this->Table.Faces.data() + 2 * edge;
    if (faces[1] < 0)
    {
      return true;
    }
    const bool side = front(faces[0] >> 1);
    if ((front(faces[1] >> 1) != ((faces[1] & 1) != 0)) != side)
    {
      return false;
    }
    if (this->Table.Types[edge] != 2)
    {
      return true;
    }
    const auto& more = this->Table.MoreEdges;
    const std::size_t i = std::lower_bound(more.begin(), more.end(), edge) - more.begin();
    for (std::int32_t j = this->Table.MoreOffsets[i]; j < this->Table.MoreOffsets[i + 1]; ++j)
    {
      const std::int32_t code = this->Table.MoreFaces[j];
      if ((front(code >> 1) != ((code & 1) != 0)) != side)
      {
        return false;
      }
    }
    return true;
  }
};

namespace
{
// Tests edges edge(0) .. edge(count - 1) one by one, in parallel over fixed
// blocks joined in order: the output order does not depend on the threads.
template <typename EdgeFn, typename FrontFn, typename AppendFn, typename Internals>
void TestInBlocks(vtkIdType count, EdgeFn&& edge, FrontFn&& front, AppendFn&& append,
  const Internals& internals, std::vector<std::vector<std::int32_t>>& found,
  std::vector<std::int32_t>& silhouette)
{
  const vtkIdType blockSize = 1 << 14;
  const vtkIdType numBlocks = (count + blockSize - 1) / blockSize;
  found.resize(std::max(found.size(), static_cast<std::size_t>(numBlocks)));
  vtkSMPTools::For(0, numBlocks, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType block = begin; block < end; ++block)
      {
        found[block].clear();
        const vtkIdType last = std::min(count, (block + 1) * blockSize);
        for (vtkIdType i = block * blockSize; i < last; ++i)
        {
          const vtkIdType e = edge(i);
          if (internals.IsSilhouette(e, front))
          {
            append(found[block], e, front(internals.Table.Faces[2 * e] >> 1));
          }
        }
      }
    });
  for (vtkIdType block = 0; block < numBlocks; ++block)
  {
    silhouette.insert(silhouette.end(), found[block].begin(), found[block].end());
  }
}
}

//------------------------------------------------------------------------------
vtkLightSilhouetteFilter::vtkLightSilhouetteFilter()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkLightSilhouetteFilter::~vtkLightSilhouetteFilter() = default;

//------------------------------------------------------------------------------
void vtkLightSilhouetteFilter::SetLight(vtkLight* light)
{
  if (this->Light != light)
  {
    this->Light = light;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLight* vtkLightSilhouetteFilter::GetLight()
{
  return this->Light;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightSilhouetteFilter::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Light)
  {
    time = std::max(time, this->Light->GetMTime());
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkLightSilhouetteFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  vtkInternals& internals = *this->Internals;
  this->NumberOfEdges = this->NumberOfSilhouetteEdges = this->NumberOfTestedEdges = 0;
  this->BuildTime = this->SearchTime = 0.0;

  // The light as (x, y, z, w): a point (w = 1) or a direction toward it (w = 0).
  double light[4];
  if (this->Light)
  {
    double position[3], focalPoint[3];
    this->Light->GetTransformedPosition(position);
    this->Light->GetTransformedFocalPoint(focalPoint);
    const bool positional = this->Light->GetPositional() != 0;
    for (int c = 0; c < 3; ++c)
    {
      light[c] = positional ? position[c] : position[c] - focalPoint[c];
    }
    light[3] = positional ? 1.0 : 0.0;
  }
  else
  {
    for (int c = 0; c < 3; ++c)
    {
      light[c] = this->LightPosition[c];
    }
    light[3] = this->Positional ? 1.0 : 0.0;
  }
  if (!std::isfinite(light[0]) || !std::isfinite(light[1]) || !std::isfinite(light[2]))
  {
    vtkErrorMacro(
      "The light (" << light[0] << ", " << light[1] << ", " << light[2] << ") is not finite.");
    return 0;
  }
  if (light[3] == 0.0 && light[0] == 0.0 && light[1] == 0.0 && light[2] == 0.0)
  {
    vtkErrorMacro("A directional light needs a direction: its position and focal point are the "
                  "same point.");
    return 0;
  }

  // The edge-to-faces map and the faces' planes, rebuilt only for a new or
  // modified input.
  const auto start = std::chrono::steady_clock::now();
  bool built = false;
  if (!internals.Valid || internals.Input != input || internals.InputTime != input->GetMTime())
  {
    internals = vtkInternals();
    if (!vtksoftshadows::ExtractTriangles(input, this, internals.Mesh))
    {
      return 0;
    }
    vtksoftshadows::BuildEdgeTable(internals.Mesh, internals.Table);
    const vtkIdType numFaces = internals.Mesh.GetNumberOfFaces();
    internals.Normals.resize(3 * numFaces);
    internals.Offsets.resize(numFaces);
    const auto& mesh = internals.Mesh;
    mesh.VisitPoints(
      [&](const auto* x)
      {
        vtkSMPTools::For(0, numFaces,
          [&](vtkIdType begin, vtkIdType end)
          {
            for (vtkIdType f = begin; f < end; ++f)
            {
              double* n = internals.Normals.data() + 3 * f;
              vtksoftshadows::FaceNormal(x, mesh.Triangles.data() + 3 * f, n);
              const vtkIdType p = mesh.Triangles[3 * f];
              internals.Offsets[f] = n[0] * x[3 * p] + n[1] * x[3 * p + 1] + n[2] * x[3 * p + 2];
            }
          });
      });
    internals.Input = input;
    internals.InputTime = input->GetMTime();
    internals.Valid = true;
    built = true;
  }
  const vtkIdType numEdges = internals.Table.GetNumberOfEdges();
  if (numEdges >= (vtkIdType(1) << 30))
  {
    vtkErrorMacro(
      "The input has " << numEdges << " edges; at most " << ((1 << 30) - 1) << " are supported.");
    internals = vtkInternals();
    return 0;
  }
  this->NumberOfEdges = numEdges;

  // The hierarchy holds the edges with two consistently oriented faces of
  // non-zero area; for those alone "all faces on one side" needs no more than
  // the faces' cones. The rest are tested one by one.
  if (this->Method == NORMAL_CONE_TREE && !internals.TreeBuilt)
  {
    const auto& table = internals.Table;
    const double* normals = internals.Normals.data();
    auto nonZero = [normals](std::int32_t face)
    {
      const double* n = normals + 3 * static_cast<vtkIdType>(face);
      return n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
    };
    vtksoftshadows::RawVector<vtksoftshadows::NormalConeTree::Edge> edges;
    vtksoftshadows::RawVector<double> midpoints;
    edges.reserve(numEdges);
    midpoints.reserve(3 * numEdges);
    const std::int32_t* points = table.Points->GetPointer(0);
    internals.Mesh.VisitPoints(
      [&](const auto* x)
      {
        for (vtkIdType e = 0; e < numEdges; ++e)
        {
          const std::int32_t f0 = table.Faces[2 * e] >> 1;
          const std::int32_t f1 = table.Faces[2 * e + 1] >> 1;
          if (!table.IsConsistentManifold(e) || !nonZero(f0) || !nonZero(f1))
          {
            internals.Irregular.push_back(static_cast<std::int32_t>(e));
            continue;
          }
          const std::int32_t a = points[2 * e];
          const std::int32_t b = points[2 * e + 1];
          edges.push_back({ static_cast<std::int32_t>(e), { f0, f1 }, { a, b } });
          for (int c = 0; c < 3; ++c)
          {
            midpoints.push_back(
              0.5 * (double(x[3 * vtkIdType(a) + c]) + double(x[3 * vtkIdType(b) + c])));
          }
        }
      });
    // A ball holding the mesh, for the tree's local frame.
    const vtkBoundingBox box(input->GetPoints()->GetBounds());
    double origin[3];
    box.GetCenter(origin);
    internals.Tree.Build(
      edges, midpoints, normals, internals.Offsets.data(), origin, 0.5 * box.GetDiagonalLength());
    internals.TreeBuilt = true;
    built = true;
  }
  if (built)
  {
    this->BuildTime =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // The search. Each silhouette edge comes as its id and its two points,
  // ordered so that the faces lie on its left seen from the light: the way
  // its first face runs it when that face is toward the light.
  const std::int32_t* edgePoints = internals.Table.Points->GetPointer(0);
  auto append = [&](std::vector<std::int32_t>& out, vtkIdType e, bool toward)
  {
    out.push_back(static_cast<std::int32_t>(e));
    out.push_back(edgePoints[2 * e + (toward ? 0 : 1)]);
    out.push_back(edgePoints[2 * e + (toward ? 1 : 0)]);
  };
  const auto searchStart = std::chrono::steady_clock::now();
  std::vector<std::int32_t>& silhouette = internals.Silhouette;
  silhouette.clear();
  if (this->Method == BRUTE_FORCE)
  {
    const vtkIdType numFaces = internals.Mesh.GetNumberOfFaces();
    internals.Front.resize(numFaces);
    vtkSMPTools::For(0, numFaces,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType f = begin; f < end; ++f)
        {
          internals.Front[f] = internals.FaceFront(static_cast<std::int32_t>(f), light) ? 1 : 0;
        }
      });
    auto front = [&](std::int32_t face) { return internals.Front[face] != 0; };
    TestInBlocks(
      numEdges, [](vtkIdType e) { return e; }, front, append, internals, internals.Blocks,
      silhouette);
    this->NumberOfTestedEdges = numEdges;
  }
  else
  {
    this->NumberOfTestedEdges = internals.Tree.Query(light, internals.TreeBuffers, silhouette);
    auto front = [&](std::int32_t face) { return internals.FaceFront(face, light); };
    const auto& irregular = internals.Irregular;
    TestInBlocks(
      static_cast<vtkIdType>(irregular.size()),
      [&irregular](vtkIdType i) { return static_cast<vtkIdType>(irregular[i]); }, front, append,
      internals, internals.Blocks, silhouette);
    this->NumberOfTestedEdges += static_cast<vtkIdType>(irregular.size());
  }
  this->SearchTime =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - searchStart).count();
  const vtkIdType numSilhouette = static_cast<vtkIdType>(silhouette.size() / 3);
  this->NumberOfSilhouetteEdges = numSilhouette;

  // Output: the lines on the input's own points (not copied: the silhouette
  // changes with every light, the mesh does not), so lines that meet share
  // their point.
  vtkNew<vtkTypeInt32Array> offsets;
  offsets->SetNumberOfValues(numSilhouette + 1);
  vtkNew<vtkTypeInt32Array> connectivity;
  connectivity->SetNumberOfValues(2 * numSilhouette);
  vtkNew<vtkIdTypeArray> edgeIds;
  edgeIds->SetName("EdgeIds");
  edgeIds->SetNumberOfValues(numSilhouette);
  std::int32_t* off = offsets->GetPointer(0);
  std::int32_t* conn = connectivity->GetPointer(0);
  vtkIdType* ids = edgeIds->GetPointer(0);
  for (vtkIdType i = 0; i < numSilhouette; ++i)
  {
    off[i] = static_cast<std::int32_t>(2 * i);
    ids[i] = silhouette[3 * i];
    conn[2 * i] = silhouette[3 * i + 1];
    conn[2 * i + 1] = silhouette[3 * i + 2];
  }
  off[numSilhouette] = static_cast<std::int32_t>(2 * numSilhouette);

  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);
  output->SetPoints(input->GetPoints());
  output->SetLines(lines);
  output->GetCellData()->AddArray(edgeIds);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightSilhouetteFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightPosition: (" << this->LightPosition[0] << ", " << this->LightPosition[1]
     << ", " << this->LightPosition[2] << ")\n";
  os << indent << "Positional: " << (this->Positional ? "On" : "Off") << "\n";
  os << indent << "Light: " << this->Light.GetPointer() << "\n";
  os << indent << "Method: " << (this->Method == BRUTE_FORCE ? "BRUTE_FORCE" : "NORMAL_CONE_TREE")
     << "\n";
  os << indent << "NumberOfEdges: " << this->NumberOfEdges << "\n";
  os << indent << "NumberOfSilhouetteEdges: " << this->NumberOfSilhouetteEdges << "\n";
  os << indent << "NumberOfTestedEdges: " << this->NumberOfTestedEdges << "\n";
  os << indent << "BuildTime: " << this->BuildTime << "\n";
  os << indent << "SearchTime: " << this->SearchTime << "\n";
}
