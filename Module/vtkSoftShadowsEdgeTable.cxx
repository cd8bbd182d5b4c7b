// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSoftShadowsEdgeTable.h"

#include "vtkSMPTools.h"

#include <OpenMesh/Core/Mesh/PolyConnectivity.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm> // for std::sort
#include <cstdint>   // for std::uint64_t
#include <memory>    // for std::unique_ptr
#include <mutex>     // for std::mutex
#include <utility>   // for std::swap

namespace vtksoftshadows
{
namespace
{
using OpenMesh::VertexHandle;

// OpenMesh prints every face it refuses on its error stream. Here refusals are
// expected (fins, inconsistent orientation) and handled, so the stream is quiet
// while faces go in, and as it was afterwards. The stream is global: one
// switch for all chunks built in parallel.
class QuietOpenMeshErrors
{
public:
  QuietOpenMeshErrors()
    : WasEnabled(omerr().is_enabled())
  {
    omerr().disable();
  }
  ~QuietOpenMeshErrors()
  {
    if (this->WasEnabled)
    {
      omerr().enable();
    }
  }
  QuietOpenMeshErrors(const QuietOpenMeshErrors&) = delete;
  void operator=(const QuietOpenMeshErrors&) = delete;

private:
  bool WasEnabled;
};

std::mutex QuietMutex; // one QuietOpenMeshErrors at a time across filters

// Adding faces to a half-edge structure is sequential, and the slowest part
// of the table. Large meshes are cut into chunks of consecutive faces, each
// with its own OpenMesh structure built in parallel; edges that chunks share
// are merged afterwards. The number of chunks depends only on the number of
// faces (never on the number of threads), so the edge order is reproducible.
constexpr vtkIdType FacesPerChunk = vtkIdType(1) << 17;
constexpr int MaximumChunks = 16;

struct Chunk
{
  vtkIdType FirstFace = 0;
  vtkIdType EndFace = 0;
  OpenMesh::PolyConnectivity Mesh;
  std::vector<std::int32_t> FaceOf; // OpenMesh face -> face, when faces were refused
  std::vector<std::int32_t> Refused;
  // Per OpenMesh edge, when some are merged: 0 kept as is, 1 merged into
  // another chunk's edge, 2 holds a merged edge's faces.
  std::vector<std::uint8_t> State;
  std::vector<std::int32_t> TableIndex;                      // when some are merged away
  std::vector<std::pair<std::int32_t, std::int32_t>> Owners; // OpenMesh edge -> group, sorted
  vtkIdType TableBase = 0;

  std::int32_t Face(OpenMesh::FaceHandle f) const
  {
    return this->FaceOf.empty() ? static_cast<std::int32_t>(this->FirstFace + f.idx())
                                : this->FaceOf[f.idx()];
  }
  vtkIdType TableEdge(vtkIdType e) const
  {
    return this->TableBase + (this->TableIndex.empty() ? e : this->TableIndex[e]);
  }
};

// A face edge, or a chunk's edge, that may have to be merged with others of
// the same two points.
struct Record
{
  std::uint64_t Key;  // (smaller point id << 32) | larger
  std::int32_t Chunk; // the chunk, for an OpenMesh edge; -1 for a refused face's edge
  std::int32_t Index; // OpenMesh edge, or refused face
  std::int32_t From;  // refused face: the point it leaves the edge from

  bool operator<(const Record& other) const
  {
    if (this->Key != other.Key)
    {
      return this->Key < other.Key;
    }
    if (this->Chunk != other.Chunk)
    {
      return this->Chunk < other.Chunk;
    }
    return this->Index < other.Index;
  }
  bool operator==(const Record& other) const
  {
    return this->Key == other.Key && this->Chunk == other.Chunk && this->Index == other.Index;
  }
};

std::uint64_t EdgeKey(std::int32_t u, std::int32_t v)
{
  const std::uint64_t a = static_cast<std::uint32_t>(std::min(u, v));
  const std::uint64_t b = static_cast<std::uint32_t>(std::max(u, v));
  return (a << 32) | b;
}

// A merged edge: all its faces (face << 1 runs it from Key's smaller point...
// resolved when written), in increasing face order.
struct Group
{
  std::uint64_t Key;
  std::vector<std::pair<std::int32_t, std::int32_t>> Faces; // (face, the point it leaves from)
  vtkIdType TableEdge = -1;
};

void BuildChunk(const TriangleMesh& mesh, Chunk& chunk)
{
  const std::int32_t* t = mesh.Triangles.data();
  const vtkIdType numFaces = chunk.EndFace - chunk.FirstFace;
  // Room for a chunk's border edges too: a closed mesh has 3/2 edges a face,
  // a chunk cut out of it a few more (reserved, not touched: costs nothing).
  chunk.Mesh.reserve(mesh.NumberOfPoints, 2 * numFaces + 3, numFaces);
  for (vtkIdType p = 0; p < mesh.NumberOfPoints; ++p)
  {
    chunk.Mesh.new_vertex();
  }
  for (vtkIdType f = chunk.FirstFace; f < chunk.EndFace; ++f)
  {
    const auto face = chunk.Mesh.add_face(
      VertexHandle(t[3 * f]), VertexHandle(t[3 * f + 1]), VertexHandle(t[3 * f + 2]));
    if (!face.is_valid())
    {
      if (chunk.Refused.empty())
      {
        chunk.FaceOf.reserve(numFaces);
        for (vtkIdType g = chunk.FirstFace; g < f; ++g)
        {
          chunk.FaceOf.push_back(static_cast<std::int32_t>(g));
        }
      }
      chunk.Refused.push_back(static_cast<std::int32_t>(f));
    }
    else if (!chunk.Refused.empty())
    {
      chunk.FaceOf.push_back(static_cast<std::int32_t>(f));
    }
  }
}
}

//------------------------------------------------------------------------------
void BuildEdgeTable(const TriangleMesh& mesh, EdgeTable& table)
{
  table = EdgeTable();
  const vtkIdType numFaces = mesh.GetNumberOfFaces();
  const std::int32_t* t = mesh.Triangles.data();

  // 1. One half-edge structure per chunk of faces, in parallel.
  int numChunks = 1;
  while (numChunks < MaximumChunks && numFaces >= 2 * numChunks * FacesPerChunk)
  {
    numChunks *= 2;
  }
  std::vector<std::unique_ptr<Chunk>> chunks(numChunks);
  for (int c = 0; c < numChunks; ++c)
  {
    chunks[c].reset(new Chunk);
    chunks[c]->FirstFace = numFaces * c / numChunks;
    chunks[c]->EndFace = numFaces * (c + 1) / numChunks;
  }
  {
    std::lock_guard<std::mutex> lock(QuietMutex);
    QuietOpenMeshErrors quiet;
    vtkSMPTools::For(0, numChunks, 1,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType c = begin; c < end; ++c)
        {
          BuildChunk(mesh, *chunks[c]);
        }
      });
  }

  // 2. Points more than one chunk uses: only edges between two of them can be
  // in several chunks.
  std::vector<std::uint8_t> shared;
  if (numChunks > 1)
  {
    std::vector<std::int8_t> owner(mesh.NumberOfPoints, -1);
    shared.assign(mesh.NumberOfPoints, 0);
    for (int c = 0; c < numChunks; ++c)
    {
      for (vtkIdType i = 3 * chunks[c]->FirstFace; i < 3 * chunks[c]->EndFace; ++i)
      {
        std::int8_t& o = owner[t[i]];
        if (o < 0)
        {
          o = static_cast<std::int8_t>(c);
        }
        else if (o != c)
        {
          shared[t[i]] = 1;
        }
      }
    }
  }

  // 3. Records of everything that may need merging: chunk edges between
  // shared points, and every edge of every refused face (with the edge its
  // own chunk has between the same points, if any).
  std::vector<std::vector<Record>> perChunk(numChunks);
  vtkSMPTools::For(0, numChunks, 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType c = begin; c < end; ++c)
      {
        const Chunk& chunk = *chunks[c];
        const OpenMesh::PolyConnectivity& om = chunk.Mesh;
        std::vector<Record>& records = perChunk[c];
        if (!shared.empty())
        {
          for (vtkIdType e = 0; e < static_cast<vtkIdType>(om.n_edges()); ++e)
          {
            const auto h = om.halfedge_handle(OpenMesh::EdgeHandle(static_cast<int>(e)), 0);
            const int u = om.from_vertex_handle(h).idx();
            const int v = om.to_vertex_handle(h).idx();
            if (shared[u] && shared[v])
            {
              records.push_back(
                { EdgeKey(u, v), static_cast<std::int32_t>(c), static_cast<std::int32_t>(e), -1 });
            }
          }
        }
        for (std::int32_t f : chunk.Refused)
        {
          for (int k = 0; k < 3; ++k)
          {
            const std::int32_t u = t[3 * f + k];
            const std::int32_t v = t[3 * f + (k + 1) % 3];
            records.push_back({ EdgeKey(u, v), -1, f, u });
            const auto h = om.find_halfedge(VertexHandle(u), VertexHandle(v));
            if (h.is_valid())
            {
              records.push_back(
                { EdgeKey(u, v), static_cast<std::int32_t>(c), om.edge_handle(h).idx(), -1 });
            }
          }
        }
      }
    });
  std::vector<Record> records;
  for (auto& list : perChunk)
  {
    records.insert(records.end(), list.begin(), list.end());
    std::vector<Record>().swap(list);
  }
  std::sort(records.begin(), records.end());
  records.erase(std::unique(records.begin(), records.end()), records.end());

  // 4. Groups of records with the same two points: merged edges, unless a
  // group is a single chunk edge (shared points, but one chunk has the edge).
  for (auto& chunk : chunks)
  {
    chunk->State.assign(chunk->Mesh.n_edges(), 0);
  }
  std::vector<Group> groups;
  std::vector<vtkIdType> ownGroups; // groups no chunk has an edge for
  for (std::size_t i = 0; i < records.size();)
  {
    std::size_t j = i;
    while (j < records.size() && records[j].Key == records[i].Key)
    {
      ++j;
    }
    if (j - i == 1 && records[i].Chunk >= 0)
    {
      i = j;
      continue;
    }
    Group group;
    group.Key = records[i].Key;
    bool owned = false;
    // Refused faces' records (chunk -1) sort first, chunk edges after, by chunk.
    for (std::size_t r = i; r < j; ++r)
    {
      const Record& record = records[r];
      if (record.Chunk < 0)
      {
        group.Faces.emplace_back(record.Index, record.From);
        continue;
      }
      Chunk& chunk = *chunks[record.Chunk];
      const OpenMesh::PolyConnectivity& om = chunk.Mesh;
      const OpenMesh::EdgeHandle edge(record.Index);
      for (int side = 0; side < 2; ++side)
      {
        const auto h = om.halfedge_handle(edge, side);
        const auto f = om.face_handle(h);
        if (f.is_valid())
        {
          group.Faces.emplace_back(chunk.Face(f), om.from_vertex_handle(h).idx());
        }
      }
      if (!owned)
      {
        chunk.State[record.Index] = 2;
        chunk.Owners.emplace_back(record.Index, static_cast<std::int32_t>(groups.size()));
        owned = true;
      }
      else
      {
        chunk.State[record.Index] = 1;
      }
    }
    std::sort(group.Faces.begin(), group.Faces.end());
    if (!owned)
    {
      ownGroups.push_back(static_cast<vtkIdType>(groups.size()));
    }
    groups.push_back(std::move(group));
    i = j;
  }
  std::vector<Record>().swap(records);

  // 5. Table edge numbers: each chunk's edges in OpenMesh order, less those
  // merged into another chunk's; then edges that only refused faces have.
  vtkIdType numEdges = 0;
  for (auto& chunkPointer : chunks)
  {
    Chunk& chunk = *chunkPointer;
    std::sort(chunk.Owners.begin(), chunk.Owners.end());
    chunk.TableBase = numEdges;
    const vtkIdType n = static_cast<vtkIdType>(chunk.Mesh.n_edges());
    vtkIdType kept = n;
    if (std::find(chunk.State.begin(), chunk.State.end(), std::uint8_t(1)) != chunk.State.end())
    {
      chunk.TableIndex.resize(n);
      kept = 0;
      for (vtkIdType e = 0; e < n; ++e)
      {
        chunk.TableIndex[e] = static_cast<std::int32_t>(kept);
        kept += chunk.State[e] == 1 ? 0 : 1;
      }
    }
    numEdges += kept;
  }
  for (vtkIdType g : ownGroups)
  {
    groups[g].TableEdge = numEdges++;
  }

  // 6. The table itself.
  table.Points = vtkSmartPointer<vtkTypeInt32Array>::New();
  AllocateTuples(table.Points.GetPointer(), 2 * numEdges);
  table.Faces.resize(2 * numEdges);
  table.Types.resize(numEdges);
  std::int32_t* points = table.Points->GetPointer(0);
  std::int32_t* faces = table.Faces.data();
  std::uint8_t* types = table.Types.data();
  std::vector<std::pair<vtkIdType, Group*>> merged;
  for (auto& chunkPointer : chunks)
  {
    const Chunk& chunk = *chunkPointer;
    const OpenMesh::PolyConnectivity& om = chunk.Mesh;
    vtkSMPTools::For(0, static_cast<vtkIdType>(om.n_edges()),
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType e = begin; e < end; ++e)
        {
          if (chunk.State[e] != 0)
          {
            continue;
          }
          // Half-edge 0 belongs to the face that made the edge, the lower face.
          const vtkIdType out = chunk.TableEdge(e);
          const OpenMesh::EdgeHandle edge(static_cast<int>(e));
          auto h0 = om.halfedge_handle(edge, 0);
          auto h1 = om.halfedge_handle(edge, 1);
          if (!om.face_handle(h0).is_valid())
          {
            std::swap(h0, h1);
          }
          const auto f1 = om.face_handle(h1);
          points[2 * out] = om.from_vertex_handle(h0).idx();
          points[2 * out + 1] = om.to_vertex_handle(h0).idx();
          faces[2 * out] = 2 * chunk.Face(om.face_handle(h0));
          faces[2 * out + 1] = f1.is_valid() ? 2 * chunk.Face(f1) + 1 : -1;
          types[out] = f1.is_valid() ? 1 : 0;
        }
      });
    for (const auto& owner : chunk.Owners)
    {
      merged.emplace_back(chunk.TableEdge(owner.first), &groups[owner.second]);
    }
  }
  for (vtkIdType g : ownGroups)
  {
    merged.emplace_back(groups[g].TableEdge, &groups[g]);
  }
  std::sort(merged.begin(), merged.end());
  table.MoreOffsets.push_back(0);
  for (const auto& entry : merged)
  {
    const vtkIdType out = entry.first;
    const Group& group = *entry.second;
    const std::int32_t from = group.Faces[0].second;
    const std::int32_t a = static_cast<std::int32_t>(group.Key >> 32);
    const std::int32_t b = static_cast<std::int32_t>(group.Key & 0xffffffffu);
    points[2 * out] = from;
    points[2 * out + 1] = from == a ? b : a;
    const std::size_t n = group.Faces.size();
    types[out] = n == 1 ? 0 : (n == 2 ? 1 : 2);
    faces[2 * out + 1] = -1;
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::int32_t code = 2 * group.Faces[i].first + (group.Faces[i].second == from ? 0 : 1);
      if (i < 2)
      {
        faces[2 * out + i] = code;
      }
      else
      {
        table.MoreFaces.push_back(code);
      }
    }
    if (n > 2)
    {
      table.MoreEdges.push_back(static_cast<std::int32_t>(out));
      table.MoreOffsets.push_back(static_cast<std::int32_t>(table.MoreFaces.size()));
    }
  }
  for (const auto& chunk : chunks)
  {
    table.RefusedFaces += static_cast<vtkIdType>(chunk->Refused.size());
  }
}
}
