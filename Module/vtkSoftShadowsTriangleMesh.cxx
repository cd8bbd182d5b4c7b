// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSoftShadowsTriangleMesh.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolygon.h"
#include "vtkSMPTools.h"
#include "vtkSoftShadowsMeshCheck.h"
#include "vtkSoftShadowsVTKVersion.h"

#include <algorithm> // for std::max, std::swap
#include <atomic>    // for std::atomic
#include <cstring>   // for std::memcpy
#include <string>    // for std::string

namespace vtksoftshadows
{
namespace
{
// Appends faces to the mesh, dropping those that repeat a point id.
class FaceWriter
{
public:
  FaceWriter(TriangleMesh& mesh, vtkPoints* points)
    : Mesh(mesh)
    , Points(points)
  {
  }

  void AddTriangle(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType cellId)
  {
    if (a == b || b == c || a == c)
    {
      ++this->Degenerate;
      return;
    }
    this->Mesh.Triangles.push_back(static_cast<std::int32_t>(a));
    this->Mesh.Triangles.push_back(static_cast<std::int32_t>(b));
    this->Mesh.Triangles.push_back(static_cast<std::int32_t>(c));
    this->Mesh.CellIds.push_back(cellId);
  }

  // Polygons of four or more points: VTK's ear cutting (which handles concave
  // polygons), each triangle turned to the polygon's own winding; a fan when
  // ear cutting gives up on a degenerate polygon.
  template <typename Range>
  void AddPolygon(const Range& ids, vtkIdType cellId)
  {
    const vtkIdType n = static_cast<vtkIdType>(ids.size());
    if (n < 3)
    {
      ++this->Degenerate;
      return;
    }
    if (n == 3)
    {
      this->AddTriangle(ids[0], ids[1], ids[2], cellId);
      return;
    }
    this->Polygon->PointIds->SetNumberOfIds(n);
    this->Polygon->Points->SetNumberOfPoints(n);
    double newell[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType i = 0; i < n; ++i)
    {
      double p[3], q[3];
      this->Points->GetPoint(ids[i], p);
      this->Points->GetPoint(ids[(i + 1) % n], q);
      this->Polygon->PointIds->SetId(i, ids[i]);
      this->Polygon->Points->SetPoint(i, p);
      newell[0] += (p[1] - q[1]) * (p[2] + q[2]);
      newell[1] += (p[2] - q[2]) * (p[0] + q[0]);
      newell[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    // Ear cutting, as vtkPolygon::Triangulate(vtkIdList*) does in the VTK
    // releases that have it (9.6 has not; this call is in every release).
    if (this->Polygon->EarCutTriangulation(this->Tris) &&
      this->Tris->GetNumberOfIds() == 3 * (n - 2))
    {
      for (vtkIdType t = 0; t < n - 2; ++t)
      {
        // Ear cutting gives indices into the polygon's own point list.
        vtkIdType a = ids[this->Tris->GetId(3 * t)];
        vtkIdType b = ids[this->Tris->GetId(3 * t + 1)];
        vtkIdType c = ids[this->Tris->GetId(3 * t + 2)];
        double pa[3], pb[3], pc[3];
        this->Points->GetPoint(a, pa);
        this->Points->GetPoint(b, pb);
        this->Points->GetPoint(c, pc);
        const double u[3] = { pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2] };
        const double v[3] = { pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2] };
        const double cross[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
          u[0] * v[1] - u[1] * v[0] };
        if (cross[0] * newell[0] + cross[1] * newell[1] + cross[2] * newell[2] < 0.0)
        {
          std::swap(b, c);
        }
        this->AddTriangle(a, b, c, cellId);
      }
      return;
    }
    for (vtkIdType i = 1; i + 1 < n; ++i)
    {
      this->AddTriangle(ids[0], ids[i], ids[i + 1], cellId);
    }
  }

  // VTK's strip convention: every other triangle is turned round so that all
  // of them share the first one's winding.
  template <typename Range>
  void AddStrip(const Range& ids, vtkIdType cellId)
  {
    const vtkIdType n = static_cast<vtkIdType>(ids.size());
    if (n < 3)
    {
      ++this->Degenerate;
      return;
    }
    for (vtkIdType i = 0; i + 2 < n; ++i)
    {
      if (i % 2 == 0)
      {
        this->AddTriangle(ids[i], ids[i + 1], ids[i + 2], cellId);
      }
      else
      {
        this->AddTriangle(ids[i + 1], ids[i], ids[i + 2], cellId);
      }
    }
  }

  vtkIdType Degenerate = 0;

private:
  TriangleMesh& Mesh;
  vtkPoints* Points;
  vtkNew<vtkPolygon> Polygon;
  vtkNew<vtkIdList> Tris;
};

struct AppendCells
{
  template <typename State>
  void operator()(State& state, FaceWriter& writer, vtkIdType firstCellId, bool strips)
  {
    const vtkIdType numCells = state.GetNumberOfCells();
    for (vtkIdType c = 0; c < numCells; ++c)
    {
      const auto ids = state.GetCellRange(c);
      if (strips)
      {
        writer.AddStrip(ids, firstCellId + c);
      }
      else if (ids.size() == 3)
      {
        writer.AddTriangle(ids[0], ids[1], ids[2], firstCellId + c);
      }
      else
      {
        writer.AddPolygon(ids, firstCellId + c);
      }
    }
  }
};

// The common case, polygons that are all triangles: copied in parallel, and
// faces are cells one to one unless a triangle repeats a point id.
struct CopyTriangles
{
  template <typename State>
  bool operator()(State& state, TriangleMesh& mesh)
  {
    const vtkIdType numCells = state.GetNumberOfCells();
    if (state.GetConnectivity()->GetNumberOfValues() != 3 * numCells)
    {
      return false;
    }
    const auto* ids = state.GetConnectivity()->GetPointer(0);
    mesh.Triangles.resize(3 * numCells);
    std::int32_t* out = mesh.Triangles.data();
    std::atomic<bool> degenerate(false);
    vtkSMPTools::For(0, numCells,
      [&](vtkIdType begin, vtkIdType end)
      {
        bool found = false;
        for (vtkIdType c = begin; c < end; ++c)
        {
          const std::int32_t a = static_cast<std::int32_t>(ids[3 * c]);
          const std::int32_t b = static_cast<std::int32_t>(ids[3 * c + 1]);
          const std::int32_t d = static_cast<std::int32_t>(ids[3 * c + 2]);
          out[3 * c] = a;
          out[3 * c + 1] = b;
          out[3 * c + 2] = d;
          found = found || a == b || b == d || a == d;
        }
        if (found)
        {
          degenerate = true;
        }
      });
    if (degenerate)
    {
      mesh.Triangles.clear();
      return false;
    }
    return true;
  }
};
}

//------------------------------------------------------------------------------
bool ExtractTriangles(vtkPolyData* input, vtkAlgorithm* filter, TriangleMesh& mesh)
{
  mesh = TriangleMesh();
  const vtkIdType numPoints = input ? input->GetNumberOfPoints() : 0;
  const vtkIdType numVerts = input ? input->GetNumberOfVerts() : 0;
  const vtkIdType numLines = input ? input->GetNumberOfLines() : 0;
  const vtkIdType numPolys = input ? input->GetNumberOfPolys() : 0;
  const vtkIdType numStrips = input ? input->GetNumberOfStrips() : 0;
  if (numPoints == 0)
  {
    vtkErrorWithObjectMacro(filter, "The input has no points: nothing to do.");
    return false;
  }
  if (numPolys + numStrips == 0)
  {
    vtkErrorWithObjectMacro(filter,
      "The input has no polygons or triangle strips ("
        << numVerts << " vertex and " << numLines
        << " line cells, which have no faces): nothing to do.");
    return false;
  }
  if (numPoints > VTK_INT_MAX)
  {
    vtkErrorWithObjectMacro(filter,
      "The input has " << numPoints << " points; at most " << VTK_INT_MAX << " are supported.");
    return false;
  }

  // Ids out of range would be read blindly below; a NaN would make every
  // light test meaningless.
  const std::string problem = vtkSoftShadowsMeshCheck::FindProblem(input);
  if (!problem.empty())
  {
    vtkErrorWithObjectMacro(filter, << problem.c_str());
    return false;
  }

  // Points read in place.
  mesh.NumberOfPoints = numPoints;
  mesh.PointArray = input->GetPoints()->GetData();
  if (auto* f = vtkFloatArray::FastDownCast(mesh.PointArray))
  {
    mesh.FloatPoints = f->GetPointer(0);
  }
  else if (auto* d = vtkDoubleArray::FastDownCast(mesh.PointArray))
  {
    mesh.DoublePoints = d->GetPointer(0);
  }
  else
  {
    mesh.ConvertedPoints.resize(3 * numPoints);
    for (vtkIdType i = 0; i < numPoints; ++i)
    {
      mesh.PointArray->GetTuple(i, mesh.ConvertedPoints.data() + 3 * i);
    }
    mesh.DoublePoints = mesh.ConvertedPoints.data();
  }
  if (numVerts > 0 || numLines > 0)
  {
    vtkWarningWithObjectMacro(filter,
      "Ignored " << numVerts << " vertex and " << numLines
                 << " line cells of the input: only polygons and triangle strips have faces.");
  }

  // Faces: vtkPolyData numbers its cells verts, lines, polys, then strips.
  const auto polys = vtkSoftShadowsVTKVersion::VisitableCells(input->GetPolys());
  const auto strips = vtkSoftShadowsVTKVersion::VisitableCells(input->GetStrips());
  mesh.FirstCellId = numVerts + numLines;
  if (numStrips > 0 || !polys->Visit(CopyTriangles{}, mesh))
  {
    const vtkIdType expected = std::max<vtkIdType>(0,
      polys->GetNumberOfConnectivityIds() - 2 * numPolys + strips->GetNumberOfConnectivityIds() -
        2 * numStrips);
    mesh.Triangles.reserve(3 * expected);
    mesh.CellIds.reserve(expected);
    FaceWriter writer(mesh, input->GetPoints());
    if (numPolys > 0)
    {
      polys->Visit(AppendCells{}, writer, numVerts + numLines, false);
    }
    if (numStrips > 0)
    {
      strips->Visit(AppendCells{}, writer, numVerts + numLines + numPolys, true);
    }
    if (writer.Degenerate > 0)
    {
      vtkWarningWithObjectMacro(filter,
        "Dropped " << writer.Degenerate
                   << " degenerate faces (repeated point ids, or fewer than three points).");
    }
  }
  if (mesh.GetNumberOfFaces() == 0)
  {
    vtkErrorWithObjectMacro(filter, "The input has no face with three distinct points.");
    mesh = TriangleMesh();
    return false;
  }
  if (mesh.GetNumberOfFaces() > MaximumNumberOfFaces)
  {
    vtkErrorWithObjectMacro(filter,
      "The input has " << mesh.GetNumberOfFaces() << " triangles; at most " << MaximumNumberOfFaces
                       << " are supported.");
    mesh = TriangleMesh();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void FindFaceNeighbours(const TriangleMesh& mesh, RawVector<std::int32_t>& neighbours)
{
  const vtkIdType numFaces = mesh.GetNumberOfFaces();
  const vtkIdType numPoints = mesh.NumberOfPoints;
  const std::int32_t* t = mesh.Triangles.data();

  // Faces around each point, as offsets into one array (counting sort).
  RawVector<std::int32_t> offsets(numPoints + 1);
  std::fill(offsets.begin(), offsets.end(), 0);
  for (vtkIdType i = 0; i < 3 * numFaces; ++i)
  {
    ++offsets[t[i] + 1];
  }
  for (vtkIdType p = 0; p < numPoints; ++p)
  {
    offsets[p + 1] += offsets[p];
  }
  RawVector<std::int32_t> faces(3 * numFaces);
  {
    RawVector<std::int32_t> next(offsets.begin(), offsets.end() - 1);
    for (vtkIdType i = 0; i < 3 * numFaces; ++i)
    {
      faces[next[t[i]]++] = static_cast<std::int32_t>(i / 3);
    }
  }

  neighbours.resize(3 * numFaces);
  vtkSMPTools::For(0, numFaces,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType f = begin; f < end; ++f)
      {
        for (int k = 0; k < 3; ++k)
        {
          const std::int32_t u = t[3 * f + k];
          const std::int32_t v = t[3 * f + (k + 1) % 3];
          std::int32_t found = Border;
          for (std::int32_t i = offsets[u]; i < offsets[u + 1]; ++i)
          {
            const std::int32_t g = faces[i];
            if (g == f)
            {
              continue;
            }
            const std::int32_t* tg = t + 3 * static_cast<vtkIdType>(g);
            // Where is u in g? Then g runs u->v if v follows u, v->u if v precedes it.
            const int at = tg[0] == u ? 0 : (tg[1] == u ? 1 : 2);
            const bool forward = tg[(at + 1) % 3] == v;
            const bool backward = tg[(at + 2) % 3] == v;
            if (!forward && !backward)
            {
              continue;
            }
            if (found != Border)
            {
              found = NonManifold;
              break;
            }
            found = 2 * g + (forward ? 1 : 0);
          }
          neighbours[3 * f + k] = found;
        }
      }
    });
}

//------------------------------------------------------------------------------
std::uint16_t FloatToHalf(float value)
{
  std::uint32_t x;
  std::memcpy(&x, &value, sizeof(x));
  const std::uint32_t sign = (x >> 16) & 0x8000u;
  const std::uint32_t magnitude = x & 0x7fffffffu;
  if (magnitude >= 0x7f800000u) // infinity, or NaN (kept a quiet NaN)
  {
    return static_cast<std::uint16_t>(sign | (magnitude > 0x7f800000u ? 0x7e00u : 0x7c00u));
  }
  if (magnitude >= 0x477ff000u) // 65520 and above round to infinity
  {
    return static_cast<std::uint16_t>(sign | 0x7c00u);
  }
  if (magnitude < 0x38800000u) // below 2^-14: a half subnormal, or zero
  {
    if (magnitude < 0x33000000u) // below 2^-25: rounds to zero
    {
      return static_cast<std::uint16_t>(sign);
    }
    const std::uint32_t exponent = magnitude >> 23;
    const std::uint32_t mantissa = (magnitude & 0x7fffffu) | 0x800000u;
    const std::uint32_t shift = 126u - exponent; // 14 .. 24
    const std::uint32_t rounded =
      (mantissa + (1u << (shift - 1)) - 1u + ((mantissa >> shift) & 1u)) >> shift;
    return static_cast<std::uint16_t>(sign | rounded);
  }
  // Normal: rebias the exponent (127 -> 15), round the mantissa to 10 bits,
  // ties to even; a carry into the exponent is the correct result.
  std::uint32_t h = magnitude - 0x38000000u;
  h += 0xfffu + ((h >> 13) & 1u);
  return static_cast<std::uint16_t>(sign | (h >> 13));
}
}
