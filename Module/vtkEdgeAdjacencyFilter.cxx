// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkEdgeAdjacencyFilter.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSoftShadowsEdgeTable.h"
#include "vtkSoftShadowsTriangleMesh.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"

#include <array> // for std::array

vtkStandardNewMacro(vtkEdgeAdjacencyFilter);

//------------------------------------------------------------------------------
int vtkEdgeAdjacencyFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfBorderEdges = this->NumberOfManifoldEdges = this->NumberOfNonManifoldEdges = 0;
  this->NumberOfInconsistentEdges = this->NumberOfRefusedFaces = 0;

  vtksoftshadows::TriangleMesh mesh;
  if (!vtksoftshadows::ExtractTriangles(input, this, mesh))
  {
    return 0;
  }
  vtksoftshadows::EdgeTable table;
  vtksoftshadows::BuildEdgeTable(mesh, table);
  this->NumberOfRefusedFaces = table.RefusedFaces;
  const vtkIdType numEdges = table.GetNumberOfEdges();
  if (2 * numEdges > VTK_INT_MAX)
  {
    vtkErrorMacro("The input has " << numEdges << " edges; at most " << VTK_INT_MAX / 2
                                   << " are supported (32-bit line indices).");
    return 0;
  }

  // One line per edge: the table's point pairs are the connectivity.
  vtkNew<vtkTypeInt32Array> offsets;
  vtksoftshadows::AllocateTuples(offsets.GetPointer(), numEdges + 1);
  vtkNew<vtkUnsignedCharArray> edgeType;
  edgeType->SetName("EdgeType");
  vtksoftshadows::AllocateTuples(edgeType.GetPointer(), numEdges);
  vtkNew<vtkUnsignedCharArray> consistent;
  consistent->SetName("ConsistentOrientation");
  vtksoftshadows::AllocateTuples(consistent.GetPointer(), numEdges);
  vtkNew<vtkIdTypeArray> faceIds;
  faceIds->SetName("FaceIds");
  faceIds->SetNumberOfComponents(2);
  vtksoftshadows::AllocateTuples(faceIds.GetPointer(), numEdges);
  vtkNew<vtkFloatArray> faceNormals;
  faceNormals->SetName("FaceNormals");
  faceNormals->SetNumberOfComponents(6);
  vtksoftshadows::AllocateTuples(faceNormals.GetPointer(), numEdges);

  // Counts of border, manifold, non-manifold and inconsistent edges.
  vtkSMPThreadLocal<std::array<vtkIdType, 4>> counts(std::array<vtkIdType, 4>{ 0, 0, 0, 0 });
  mesh.VisitPoints(
    [&](const auto* x)
    {
      vtkSMPTools::For(0, numEdges,
        [&](vtkIdType begin, vtkIdType end)
        {
          std::array<vtkIdType, 4>& count = counts.Local();
          std::int32_t* off = offsets->GetPointer(0);
          unsigned char* type = edgeType->GetPointer(0);
          unsigned char* same = consistent->GetPointer(0);
          vtkIdType* ids = faceIds->GetPointer(0);
          float* normals = faceNormals->GetPointer(0);
          const std::int32_t* faces = table.Faces.data();
          const std::int32_t* triangles = mesh.Triangles.data();
          for (vtkIdType e = begin; e < end; ++e)
          {
            off[e] = static_cast<std::int32_t>(2 * e);
            type[e] = table.Types[e];
            ++count[type[e]];
            const vtkIdType f0 = faces[2 * e] >> 1;
            double n0[3];
            vtksoftshadows::FaceNormal(x, triangles + 3 * f0, n0);
            ids[2 * e] = mesh.GetCellId(f0);
            for (int c = 0; c < 3; ++c)
            {
              normals[6 * e + c] = static_cast<float>(n0[c]);
            }
            if (type[e] == BORDER_EDGE)
            {
              same[e] = 1;
              ids[2 * e + 1] = -1;
              for (int c = 0; c < 3; ++c)
              {
                normals[6 * e + 3 + c] = static_cast<float>(-n0[c]);
              }
              continue;
            }
            const vtkIdType f1 = faces[2 * e + 1] >> 1;
            double n1[3];
            vtksoftshadows::FaceNormal(x, triangles + 3 * f1, n1);
            ids[2 * e + 1] = mesh.GetCellId(f1);
            for (int c = 0; c < 3; ++c)
            {
              normals[6 * e + 3 + c] = static_cast<float>(n1[c]);
            }
            same[e] = table.IsConsistentManifold(e) ? 1 : 0;
            count[3] += (type[e] == MANIFOLD_EDGE && !same[e]) ? 1 : 0;
          }
        });
    });
  offsets->SetValue(numEdges, static_cast<std::int32_t>(2 * numEdges));
  for (const std::array<vtkIdType, 4>& count : counts)
  {
    this->NumberOfBorderEdges += count[BORDER_EDGE];
    this->NumberOfManifoldEdges += count[MANIFOLD_EDGE];
    this->NumberOfNonManifoldEdges += count[NON_MANIFOLD_EDGE];
    this->NumberOfInconsistentEdges += count[3];
  }

  // All faces of the non-manifold edges, as input cell ids.
  vtkNew<vtkIdTypeArray> moreEdges;
  moreEdges->SetName("NonManifoldEdgeIds");
  vtkNew<vtkIdTypeArray> moreOffsets;
  moreOffsets->SetName("NonManifoldFaceOffsets");
  vtkNew<vtkIdTypeArray> moreFaces;
  moreFaces->SetName("NonManifoldFaceIds");
  moreOffsets->InsertNextValue(0);
  for (std::size_t i = 0; i < table.MoreEdges.size(); ++i)
  {
    const vtkIdType e = table.MoreEdges[i];
    moreEdges->InsertNextValue(e);
    moreFaces->InsertNextValue(mesh.GetCellId(table.Faces[2 * e] >> 1));
    moreFaces->InsertNextValue(mesh.GetCellId(table.Faces[2 * e + 1] >> 1));
    for (std::int32_t j = table.MoreOffsets[i]; j < table.MoreOffsets[i + 1]; ++j)
    {
      moreFaces->InsertNextValue(mesh.GetCellId(table.MoreFaces[j] >> 1));
    }
    moreOffsets->InsertNextValue(moreFaces->GetNumberOfValues());
  }

  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, table.Points);
  output->SetPoints(input->GetPoints());
  output->GetPointData()->PassData(input->GetPointData());
  output->SetLines(lines);
  vtkCellData* cellData = output->GetCellData();
  cellData->AddArray(edgeType);
  cellData->AddArray(consistent);
  cellData->AddArray(faceIds);
  cellData->AddArray(faceNormals);
  output->GetFieldData()->AddArray(moreEdges);
  output->GetFieldData()->AddArray(moreOffsets);
  output->GetFieldData()->AddArray(moreFaces);
  return 1;
}

//------------------------------------------------------------------------------
void vtkEdgeAdjacencyFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfBorderEdges: " << this->NumberOfBorderEdges << "\n";
  os << indent << "NumberOfManifoldEdges: " << this->NumberOfManifoldEdges << "\n";
  os << indent << "NumberOfNonManifoldEdges: " << this->NumberOfNonManifoldEdges << "\n";
  os << indent << "NumberOfInconsistentEdges: " << this->NumberOfInconsistentEdges << "\n";
  os << indent << "NumberOfRefusedFaces: " << this->NumberOfRefusedFaces << "\n";
}
