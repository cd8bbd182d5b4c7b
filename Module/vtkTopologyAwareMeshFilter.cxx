// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTopologyAwareMeshFilter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSoftShadowsTriangleMesh.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedShortArray.h"

#include <cstdint> // for std::int32_t, std::uint16_t

vtkStandardNewMacro(vtkTopologyAwareMeshFilter);

namespace
{
using vtksoftshadows::FaceNormal;
using vtksoftshadows::FloatToHalf;

inline void Put(float* out, double value)
{
  *out = static_cast<float>(value);
}
inline void Put(std::uint16_t* out, double value)
{
  *out = FloatToHalf(static_cast<float>(value));
}

// The normals a face stores for its three edges (paper, section 2.1): the
// neighbour's normal, negated when the neighbour runs the edge the same way
// (so the sign test stays geometric), or the face's own normal negated for a
// border or non-manifold edge (always a silhouette).
template <typename P>
void AdjacentNormals(const P* x, const std::int32_t* triangles, const std::int32_t* neighbours,
  vtkIdType face, const double normal[3], double adjacent[3][3])
{
  for (int k = 0; k < 3; ++k)
  {
    const std::int32_t code = neighbours[3 * face + k];
    if (code < 0)
    {
      for (int c = 0; c < 3; ++c)
      {
        adjacent[k][c] = -normal[c];
      }
      continue;
    }
    FaceNormal(x, triangles + 3 * static_cast<vtkIdType>(code >> 1), adjacent[k]);
    if (code & 1)
    {
      for (int c = 0; c < 3; ++c)
      {
        adjacent[k][c] = -adjacent[k][c];
      }
    }
  }
}

// Writes kept face f (output face i) in either layout, T being float or
// unsigned short (half bits).
template <typename T>
struct Writer
{
  const vtksoftshadows::TriangleMesh& Mesh;
  const std::int32_t* Neighbours;
  const std::int32_t* OutputIndex; // nullptr: every face is kept, face f is output f
  bool PerFace;
  T* Position;           // per-vertex layout only
  float* Points;         // per-vertex layout, when separate from Position
  T* FacePositions;      // 9 a vertex, or a face
  T* Normals;            // 9 a vertex, or a face
  vtkIdType* CellIds;    // a face
  std::int32_t* Offsets; // a face, + 1
  std::int32_t* Connectivity;

  template <typename P>
  void Run(const P* x, vtkIdType begin, vtkIdType end) const
  {
    const std::int32_t* triangles = this->Mesh.Triangles.data();
    for (vtkIdType f = begin; f < end; ++f)
    {
      const vtkIdType i = this->OutputIndex ? this->OutputIndex[f] : f;
      if (i < 0)
      {
        continue;
      }
      const std::int32_t* t = triangles + 3 * f;
      double n[3];
      FaceNormal(x, t, n);
      double adjacent[3][3];
      AdjacentNormals(x, triangles, this->Neighbours, f, n, adjacent);
      double corners[9];
      for (int j = 0; j < 3; ++j)
      {
        for (int c = 0; c < 3; ++c)
        {
          corners[3 * j + c] = static_cast<double>(x[3 * static_cast<vtkIdType>(t[j]) + c]);
        }
      }
      this->CellIds[i] = this->Mesh.GetCellId(f);
      this->Offsets[i] = static_cast<std::int32_t>(3 * i);
      if (this->PerFace)
      {
        for (int v = 0; v < 9; ++v)
        {
          Put(this->FacePositions + 9 * i + v, corners[v]);
          Put(this->Normals + 9 * i + v, adjacent[v / 3][v % 3]);
        }
        for (int j = 0; j < 3; ++j)
        {
          this->Connectivity[3 * i + j] = t[j];
        }
        continue;
      }
      // Per vertex: the same face data three times, each with its own position.
      T face[9];
      T normals[9];
      for (int v = 0; v < 9; ++v)
      {
        Put(face + v, corners[v]);
        Put(normals + v, adjacent[v / 3][v % 3]);
      }
      for (int j = 0; j < 3; ++j)
      {
        const vtkIdType vertex = 3 * i + j;
        this->Connectivity[vertex] = static_cast<std::int32_t>(vertex);
        for (int c = 0; c < 3; ++c)
        {
          this->Position[3 * vertex + c] = face[3 * j + c];
          if (this->Points)
          {
            this->Points[3 * vertex + c] = static_cast<float>(corners[3 * j + c]);
          }
        }
        for (int v = 0; v < 9; ++v)
        {
          this->FacePositions[9 * vertex + v] = face[v];
          this->Normals[9 * vertex + v] = normals[v];
        }
      }
    }
  }

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    this->Mesh.VisitPoints([&](const auto* x) { this->Run(x, begin, end); });
  }
};

template <typename ArrayT>
vtkSmartPointer<ArrayT> NewArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  vtksoftshadows::AllocateTuples(array.GetPointer(), tuples);
  return array;
}

template <typename ArrayT, typename T>
vtkIdType Build(const vtksoftshadows::TriangleMesh& mesh, const std::int32_t* neighbours,
  const std::int32_t* outputIndex, vtkIdType numOutput, bool perFace, vtkPolyData* input,
  vtkPolyData* output)
{
  const vtkIdType numVertices = perFace ? 0 : 3 * numOutput;
  const vtkIdType numItems = perFace ? numOutput : numVertices;
  auto facePositions = NewArray<ArrayT>("FacePositions", 9, numItems);
  auto normals = NewArray<ArrayT>("AdjacentNormals", 9, numItems);
  auto cellIds = NewArray<vtkIdTypeArray>("InputCellIds", 1, numOutput);
  auto offsets = NewArray<vtkTypeInt32Array>(nullptr, 1, numOutput + 1);
  auto connectivity = NewArray<vtkTypeInt32Array>(nullptr, 1, 3 * numOutput);

  vtkSmartPointer<ArrayT> position;
  vtkSmartPointer<vtkFloatArray> points;
  if (!perFace)
  {
    position = NewArray<ArrayT>("Position", 3, numVertices);
    points = vtkFloatArray::SafeDownCast(position);
    if (!points)
    {
      points = NewArray<vtkFloatArray>("Points", 3, numVertices);
    }
  }

  Writer<T> writer{ mesh, neighbours, outputIndex, perFace,
    position ? reinterpret_cast<T*>(position->GetVoidPointer(0)) : nullptr,
    (points && points.GetPointer() != static_cast<vtkDataArray*>(position.GetPointer()))
      ? points->GetPointer(0)
      : nullptr,
    reinterpret_cast<T*>(facePositions->GetVoidPointer(0)),
    reinterpret_cast<T*>(normals->GetVoidPointer(0)), cellIds->GetPointer(0),
    offsets->GetPointer(0), connectivity->GetPointer(0) };
  vtkSMPTools::For(0, mesh.GetNumberOfFaces(), writer);
  offsets->SetValue(numOutput, static_cast<std::int32_t>(3 * numOutput));

  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPolys(polys);
  output->GetCellData()->AddArray(cellIds);
  vtkIdType bytes = (facePositions->GetNumberOfValues() + normals->GetNumberOfValues()) *
    facePositions->GetDataTypeSize();
  if (perFace)
  {
    output->SetPoints(input->GetPoints());
    output->GetCellData()->AddArray(facePositions);
    output->GetCellData()->AddArray(normals);
  }
  else
  {
    vtkNew<vtkPoints> outPoints;
    outPoints->SetData(points);
    output->SetPoints(outPoints);
    output->GetPointData()->AddArray(position);
    output->GetPointData()->AddArray(facePositions);
    output->GetPointData()->AddArray(normals);
    bytes += position->GetNumberOfValues() * position->GetDataTypeSize();
  }
  return bytes;
}
}

//------------------------------------------------------------------------------
double vtkTopologyAwareMeshFilter::GetMemoryRatio() const
{
  return this->InputMeshBytes > 0
    ? static_cast<double>(this->TopologyAwareMeshBytes) / static_cast<double>(this->InputMeshBytes)
    : 0.0;
}

//------------------------------------------------------------------------------
int vtkTopologyAwareMeshFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->TopologyAwareMeshBytes = this->InputMeshBytes = this->NumberOfDroppedFaces = 0;

  vtksoftshadows::TriangleMesh mesh;
  if (!vtksoftshadows::ExtractTriangles(input, this, mesh))
  {
    return 0;
  }
  const vtkIdType numFaces = mesh.GetNumberOfFaces();
  if (3 * numFaces > VTK_INT_MAX)
  {
    vtkErrorMacro("The input has " << numFaces << " faces; a TAM holds at most " << VTK_INT_MAX / 3
                                   << " (32-bit vertex indices).");
    return 0;
  }
  vtksoftshadows::RawVector<std::int32_t> neighbours;
  vtksoftshadows::FindFaceNeighbours(mesh, neighbours);

  // Rigid meshes: a face whose three neighbours are coplanar with it never
  // passes the silhouette test for any light (paper, end of section 3).
  std::vector<std::int32_t> outputIndex;
  vtkIdType numOutput = numFaces;
  if (this->DropNonSilhouetteFaces)
  {
    outputIndex.resize(numFaces);
    const double tolerance2 = this->CoplanarTolerance * this->CoplanarTolerance;
    mesh.VisitPoints(
      [&](const auto* x)
      {
        vtkSMPTools::For(0, numFaces,
          [&](vtkIdType begin, vtkIdType end)
          {
            for (vtkIdType f = begin; f < end; ++f)
            {
              bool keep = false;
              for (int k = 0; k < 3; ++k)
              {
                keep = keep || neighbours[3 * f + k] < 0;
              }
              if (!keep)
              {
                double n[3], adjacent[3][3];
                FaceNormal(x, mesh.Triangles.data() + 3 * f, n);
                AdjacentNormals(x, mesh.Triangles.data(), neighbours.data(), f, n, adjacent);
                for (int k = 0; k < 3 && !keep; ++k)
                {
                  const double d[3] = { adjacent[k][0] - n[0], adjacent[k][1] - n[1],
                    adjacent[k][2] - n[2] };
                  keep = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > tolerance2;
                }
              }
              outputIndex[f] = keep ? 1 : -1;
            }
          });
      });
    numOutput = 0;
    for (vtkIdType f = 0; f < numFaces; ++f)
    {
      if (outputIndex[f] > 0)
      {
        outputIndex[f] = static_cast<std::int32_t>(numOutput++);
      }
    }
    this->NumberOfDroppedFaces = numFaces - numOutput;
  }

  const std::int32_t* index = outputIndex.empty() ? nullptr : outputIndex.data();
  this->TopologyAwareMeshBytes = this->HalfPrecision
    ? Build<vtkUnsignedShortArray, std::uint16_t>(
        mesh, neighbours.data(), index, numOutput, this->PerFaceAttributes, input, output)
    : Build<vtkFloatArray, float>(
        mesh, neighbours.data(), index, numOutput, this->PerFaceAttributes, input, output);

  // The input as a renderer holds it: float positions, its point data, and
  // 32-bit triangle indices.
  vtkIdType pointBytes = 3 * sizeof(float);
  vtkPointData* pointData = input->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    if (vtkDataArray* array = pointData->GetArray(a))
    {
      pointBytes += array->GetNumberOfComponents() * array->GetDataTypeSize();
    }
  }
  this->InputMeshBytes = input->GetNumberOfPoints() * pointBytes +
    numFaces * 3 * static_cast<vtkIdType>(sizeof(std::int32_t));
  return 1;
}

//------------------------------------------------------------------------------
void vtkTopologyAwareMeshFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HalfPrecision: " << (this->HalfPrecision ? "On" : "Off") << "\n";
  os << indent << "PerFaceAttributes: " << (this->PerFaceAttributes ? "On" : "Off") << "\n";
  os << indent << "DropNonSilhouetteFaces: " << (this->DropNonSilhouetteFaces ? "On" : "Off")
     << "\n";
  os << indent << "CoplanarTolerance: " << this->CoplanarTolerance << "\n";
  os << indent << "TopologyAwareMeshBytes: " << this->TopologyAwareMeshBytes << "\n";
  os << indent << "InputMeshBytes: " << this->InputMeshBytes << "\n";
  os << indent << "MemoryRatio: " << this->GetMemoryRatio() << "\n";
  os << indent << "NumberOfDroppedFaces: " << this->NumberOfDroppedFaces << "\n";
}
