// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "MeshFiles.h"

#include "MessageCapture.h"
#include "ObjFiles.h"
#include "PlyFiles.h"
#include "VtpFiles.h"

#include "vtkSoftShadowsMeshCheck.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtksys/SystemTools.hxx>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <new>
#include <sstream>
#include <stdexcept>

namespace softshadows
{
namespace
{
template <typename Reader>
vtkSmartPointer<Reader> MakeReader(const std::filesystem::path& file)
{
  auto reader = vtkSmartPointer<Reader>::New();
  reader->SetFileName(file.string().c_str());
  return reader;
}

std::string ReadBytes(const std::filesystem::path& file)
{
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof())
  {
    throw std::runtime_error("it cannot be opened");
  }
  return bytes;
}

// A PLY file is read once, checked, and handed to the reader from memory,
// so that what was checked is what is read.
vtkSmartPointer<vtkAlgorithm> MakePlyReader(const std::filesystem::path& file)
{
  const std::string bytes = ReadBytes(file);
  const std::string problem = FindPlyProblem(bytes);
  if (!problem.empty())
  {
    throw std::runtime_error(problem);
  }
  auto reader = vtkSmartPointer<vtkPLYReader>::New();
  reader->ReadFromInputStringOn();
  reader->SetInputString(bytes);
  return reader;
}

// VTK 9.1's OBJ reader reads only from a file: the file checked is read
// again by it, or a copy of it with absolute indices (AbsoluteObjIndices),
// which `copy` keeps while the reader reads.
vtkSmartPointer<vtkAlgorithm> MakeObjReader(
  const std::filesystem::path& file, std::unique_ptr<TemporaryFile>& copy)
{
  const std::string bytes = ReadBytes(file);
  const std::string problem = FindObjProblem(bytes);
  if (!problem.empty())
  {
    throw std::runtime_error(problem);
  }
  const std::string absolute = AbsoluteObjIndices(bytes);
  if (absolute == bytes)
  {
    return MakeReader<vtkOBJReader>(file);
  }
  copy = std::make_unique<TemporaryFile>(absolute, ".obj");
  return MakeReader<vtkOBJReader>(copy->Path());
}

// The first vertex coordinate of an STL file that is not a finite number,
// in words, or empty: vtkSTLReader merges the points it read through a point
// locator whose buckets come from their bounds, and with an infinite or NaN
// coordinate it indexes past them, corrupting memory (found by fuzzing).
std::string FindStlNonFinite(const std::string& bytes, bool binary)
{
  auto problem = [](std::int64_t triangle, float value)
  {
    return "triangle " + std::to_string(triangle) + " has a vertex coordinate " +
      std::to_string(value) + ": NaN and infinite coordinates are not supported";
  };
  if (binary)
  {
    // 80 bytes of header, a count, then 50 bytes a triangle: its normal,
    // its three vertices (float32, little-endian) and two bytes.
    for (std::size_t at = 84, triangle = 0; at + 50 <= bytes.size(); at += 50, ++triangle)
    {
      for (int k = 3; k < 12; ++k)
      {
        unsigned char b[4];
        std::memcpy(b, bytes.data() + at + 4 * k, 4);
        const std::uint32_t bits = static_cast<std::uint32_t>(b[0]) |
          static_cast<std::uint32_t>(b[1]) << 8 | static_cast<std::uint32_t>(b[2]) << 16 |
          static_cast<std::uint32_t>(b[3]) << 24;
        float value;
        std::memcpy(&value, &bits, 4);
        if (!std::isfinite(value))
        {
          return problem(static_cast<std::int64_t>(triangle), value);
        }
      }
    }
    return std::string();
  }
  // Text: the three numbers after each "vertex".
  std::istringstream words(bytes);
  std::string word;
  std::int64_t vertices = 0;
  while (words >> word)
  {
    if (word != "vertex")
    {
      continue;
    }
    for (int k = 0; k < 3 && words >> word; ++k)
    {
      const float value = std::strtof(word.c_str(), nullptr);
      if (!std::isfinite(value))
      {
        return problem(vertices / 3, value);
      }
    }
    ++vertices;
  }
  return std::string();
}

// VTK 9.1's vtkSTLReader reads a file it does not take for text as binary
// STL and allocates for the triangle count of its header when that exceeds
// what the file holds (as an int; counts below are "bogus" and ignored):
// a truncated file or stray bytes would have it allocate gigabytes.
vtkSmartPointer<vtkAlgorithm> MakeStlReader(const std::filesystem::path& file)
{
  const bool binary =
    vtksys::SystemTools::DetectFileType(file.string().c_str()) != vtksys::SystemTools::FileTypeText;
  if (binary)
  {
    std::ifstream in(file, std::ios::binary);
    unsigned char count[4] = {};
    in.seekg(80);
    if (in.read(reinterpret_cast<char*>(count), 4))
    {
      const auto claimed = static_cast<int32_t>(static_cast<uint32_t>(count[0]) |
        static_cast<uint32_t>(count[1]) << 8 | static_cast<uint32_t>(count[2]) << 16 |
        static_cast<uint32_t>(count[3]) << 24);
      const auto held = static_cast<int64_t>((std::filesystem::file_size(file) - 84) / 50);
      if (claimed > held)
      {
        throw std::runtime_error("its binary STL header gives " + std::to_string(claimed) +
          " triangles, but the file holds " + std::to_string(held));
      }
    }
  }
  const std::string problem = FindStlNonFinite(ReadBytes(file), binary);
  if (!problem.empty())
  {
    throw std::runtime_error(problem);
  }
  return MakeReader<vtkSTLReader>(file);
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> ReadMeshFile(const std::filesystem::path& file, MeshFormat format)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  std::unique_ptr<TemporaryFile> copy;
  switch (format)
  {
    case MeshFormat::VTP:
      reader = MakeVtpReader(file);
      break;
    case MeshFormat::OBJ:
      reader = MakeObjReader(file, copy);
      break;
    case MeshFormat::PLY:
      reader = MakePlyReader(file);
      break;
    case MeshFormat::STL:
      reader = MakeStlReader(file);
      break;
  }

  std::string problem;
  {
    MessageCapture messages;
    try
    {
      reader->Update();
    }
    catch (const std::bad_alloc&)
    {
      // What the checks above cannot see (a VTP file's compression headers).
      throw std::runtime_error("reading it takes more memory than this machine has");
    }
    problem = messages.FirstMessage();
  }
  auto* mesh = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (mesh && mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() > 0)
  {
    // Only the geometry and point normals are drawn (scenes give colours).
    // The rest goes: VTK's OBJ reader leaves MaterialIds shorter than the
    // cells of a file that mixes lines and faces.
    vtkSmartPointer<vtkDataArray> normals = mesh->GetPointData()->GetNormals();
    mesh->GetPointData()->Initialize();
    mesh->GetCellData()->Initialize();
    mesh->GetPointData()->SetNormals(normals);

    // Checked before anything walks its cells: the normals computed for
    // it build cell links, which need VTK's cell sizes too.
    problem = vtkSoftShadowsMeshCheck::FindProblem(mesh, true);
    if (problem.empty())
    {
      return mesh;
    }
  }
  throw std::runtime_error(problem.empty() ? "no polygons in it" : problem);
}
}
