// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAliasFreeShadowPass.h"

#include "vtkAliasFreeBentNormals.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkEdgeAdjacencyFilter.h"
#include "vtkFloatArray.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowCompute.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowGeometry.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowMatrices.h"
#include "vtkShadowSampling.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"
#include "vtkTriangleFilter.h"

#include "vtkAliasFreeCastersFS.h"
#include "vtkAliasFreeCastersGS.h"
#include "vtkAliasFreeCastersVS.h"
#include "vtkAliasFreeListsCS.h"
#include "vtkAliasFreeLookup.h"
#include "vtkAliasFreeLookupBuildCS.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <random>
#include <set>
#include <tuple>
#include <vector>

namespace
{
// Caster triangles (or edges) a draw call: each covers its influence region,
// up to 20 triangles of it, which llvmpipe bins before it rasterizes them;
// in batches, it holds two batches' worth instead of a million triangles'.
constexpr int CasterBatch = 16384;

// Lookup table cells (vtkAliasFreeLookup.glsl): normals, times distances.
constexpr int LookupAngles = 64 * 64;
constexpr int LookupDistances = 64;

// Storage buffer bindings, as the shaders declare them.
enum Binding : unsigned int
{
  Counts = 0, ///< in the resolve, the centre's hard bits
  Centre = 0,
  Offsets = 1,
  Blocks = 2, ///< the prefix sum's; then the marks of penumbra texels
  Marks = 2,
  Pixels = 3,
  Samples = 4,
  Hidden = 5,
  Lookup = 6,
  Depths = 6, ///< while the lists are built (no lookup table then)
  Stats = 7,
  CasterDepths = 7 ///< while the casters draw (no statistics then)
};

// What a caster's triangle and edge take, CPU and GPU: the triangles (cells
// and three vertices each); each edge's entry in the adjacency filter's
// output, while the triangles are built; and for the soft pass restricted to
// silhouettes, its four vertices with its faces' normals. Measured on the
// gyroid: 290 MB (hard) and 780 MB (soft) more than `hard` at 1M triangles,
// 1.65 GB (hard) at 10M.
constexpr double BytesPerTriangle = 68.0;
constexpr double BytesPerEdgeBuilding = 100.0;
constexpr double BytesPerEdgeKept = 350.0;

// Triangles of `data`'s polygons and strips, as vtkTriangleFilter makes them.
double CountTriangles(vtkPolyData* data)
{
  double triangles = 0.0;
  for (vtkCellArray* cells : { data->GetPolys(), data->GetStrips() })
  {
    if (cells)
    {
      triangles += static_cast<double>(cells->GetNumberOfConnectivityIds()) -
        2.0 * static_cast<double>(cells->GetNumberOfCells());
    }
  }
  return std::max(triangles, 0.0);
}

// Cells of the pyramid of greatest sample depths over a size^2 map: the
// texels, then 2x2 texels, and so on to one cell.
size_t DepthPyramidCells(int size)
{
  size_t cells = 0;
  for (; size > 1; size = (size + 1) / 2)
  {
    cells += static_cast<size_t>(size) * size;
  }
  return cells + 1;
}

// Stats: clip-space bounds (order-preserving integers), depth, longest list,
// number of samples.
int Ordered(float f)
{
  int i;
  std::memcpy(&i, &f, sizeof i);
  return i >= 0 ? i : i ^ 0x7fffffff;
}
float FromOrdered(int i)
{
  i = i >= 0 ? i : i ^ 0x7fffffff;
  float f;
  std::memcpy(&f, &i, sizeof f);
  return f;
}

// What the pass keeps of each caster's polydata: its triangles, and whether
// they close a volume (every edge used once in each direction) and which
// way their normals point (the sign of the enclosed volume); its edges for
// the soft pass's restriction to silhouettes only.
struct CasterTriangles
{
  std::shared_ptr<vtkShadowGeometry> Geometry;
  std::shared_ptr<vtkShadowGeometry> Edges; ///< each edge (a, b, a, b) with its faces' normals
  bool Closed = false;
  float Orientation = 1.0f;
};

// Each edge of `edges` (vtkEdgeAdjacencyFilter's output) as a line with
// adjacency (a, b, a, b) whose points carry its two faces' normals:
// aliasfreeFace0 (w = 1 for edges that are always silhouettes: borders,
// non-manifold or inconsistently oriented ones) and aliasfreeFace1; none
// without `geometry`. Sets `closed` when there are none of those: the faces
// close a volume.
vtkSmartPointer<vtkPolyData> EdgesWithFaces(vtkPolyData* edges, bool geometry, bool& closed)
{
  vtkDataArray* types = edges->GetCellData()->GetArray("EdgeType");
  vtkDataArray* consistent = edges->GetCellData()->GetArray("ConsistentOrientation");
  vtkDataArray* normals = edges->GetCellData()->GetArray("FaceNormals");
  const vtkIdType count = edges->GetNumberOfLines();
  const vtkIdType vertices = geometry ? 4 * count : 0;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vertices);
  vtkNew<vtkFloatArray> face0, face1;
  face0->SetName("aliasfreeFace0");
  face0->SetNumberOfComponents(4);
  face0->SetNumberOfTuples(vertices);
  face1->SetName("aliasfreeFace1");
  face1->SetNumberOfComponents(3);
  face1->SetNumberOfTuples(vertices);
  vtkNew<vtkCellArray> lines;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  vtkIdType e = 0;
  closed = count > 0;
  vtkCellArray* cells = edges->GetLines();
  for (cells->InitTraversal(); cells->GetNextCell(n, ids); ++e)
  {
    const bool always = types->GetComponent(e, 0) != 1.0 || consistent->GetComponent(e, 0) == 0.0;
    closed = closed && !always;
    if (!geometry)
    {
      continue;
    }
    double f[6];
    normals->GetTuple(e, f);
    const float first[4] = { static_cast<float>(f[0]), static_cast<float>(f[1]),
      static_cast<float>(f[2]), always ? 1.0f : 0.0f };
    const float second[3] = { static_cast<float>(f[3]), static_cast<float>(f[4]),
      static_cast<float>(f[5]) };
    vtkIdType line[4];
    for (int k = 0; k < 4; ++k)
    {
      line[k] = 4 * e + k;
      points->SetPoint(line[k], edges->GetPoint(ids[k % 2]));
      face0->SetTypedTuple(line[k], first);
      face1->SetTypedTuple(line[k], second);
    }
    lines->InsertNextCell(4, line);
  }
  if (!geometry)
  {
    return nullptr;
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(points);
  result->SetLines(lines);
  result->GetPointData()->AddArray(face0);
  result->GetPointData()->AddArray(face1);
  return result;
}

void BuildTriangles(vtkPolyData* data, bool withEdges, CasterTriangles& value)
{
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(vtkShadowCasterRegistry::MergedFaces(data));
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  vtkPolyData* mesh = triangles->GetOutput();
  vtkNew<vtkEdgeAdjacencyFilter> adjacency;
  adjacency->SetInputData(mesh);
  adjacency->Update();
  bool closed = false;
  auto edges = EdgesWithFaces(adjacency->GetOutput(), withEdges, closed);
  if (withEdges)
  {
    value.Edges = vtkShadowGeometry::NewShared();
    value.Edges->SetPrimitive(vtkShadowGeometry::Primitive::LinesAdjacency);
    value.Edges->SetBatchSize(CasterBatch);
    value.Edges->SetInput(edges);
  }

  // Divergence theorem: the signed volume of the tetrahedra to the origin
  // says which way a closed mesh's normals point.
  double volume = 0.0;
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = mesh->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
    }
    volume += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
                p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
                p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) /
      6.0;
  }
  value.Closed = closed && volume != 0.0;
  value.Orientation = volume < 0.0 ? -1.0f : 1.0f;
  value.Geometry = vtkShadowGeometry::NewShared();
  value.Geometry->SetBatchSize(CasterBatch);
  value.Geometry->SetInput(mesh);
}

// One light's lookup table and what it was built for.
struct LookupTable
{
  std::tuple<int, int, unsigned int> Key{ -1, 0, 0u }; ///< shape, samples, seed
  vtkShadowCompute::Buffer Masks;
};

// `groups` work groups in rows of at most 65535, the guaranteed limit of a
// dispatch's dimension (the shader numbers them row by row).
void DispatchRows(vtkShadowCompute::Program& program, unsigned int groups)
{
  const unsigned int row = std::min(groups, 65535u);
  program.Dispatch(row, (groups + row - 1) / row);
}

std::string WithDefines(const std::string& source, const std::string& defines)
{
  return "#version 430\n" + defines + source;
}
}

struct vtkAliasFreeShadowPass::Internals
{
  vtkShadowCasterCache<CasterTriangles, bool> Casters; ///< built with edges or not
  vtkAliasFreeBentNormals Bent; // receivers' bent normals (section 6), when on
  vtkShadowCompute::Program Bounds, Count, DepthLevel, DepthMarked, ScanBlocks, ScanTop, ScanAdd,
    Scatter, Resolve, BuildLookup;
  vtkShadowCompute::Buffer CountsBuffer, OffsetsBuffer, BlocksBuffer, PixelsBuffer, SamplesBuffer,
    HiddenBuffer, StatsBuffer, LightSamples, MarksBuffer, CentreBuffer, DepthsBuffer;
  std::vector<std::unique_ptr<LookupTable>> Lookups; // per light slot
  // Temporal jitter: per light slot, what the last frame saw and how many
  // frames its accumulated visibility holds.
  std::vector<std::vector<double>> Still;
  std::vector<int> History;
  std::string Vertex = WithDefines(vtkAliasFreeCastersVS, "");
  std::string HardGeometry = WithDefines(vtkAliasFreeCastersGS, "");
  std::string HardFragment = WithDefines(vtkAliasFreeCastersFS, "");
  std::string SoftGeometry = WithDefines(vtkAliasFreeCastersGS, "#define ALIASFREE_SOFT\n");
  std::string EdgesVertex = WithDefines(vtkAliasFreeCastersVS, "#define ALIASFREE_EDGES\n");
  std::string EdgesGeometry = WithDefines(vtkAliasFreeCastersGS, "#define ALIASFREE_EDGES\n");
  std::string EdgesFragment = WithDefines(vtkAliasFreeCastersFS, "#define ALIASFREE_EDGES\n");
  std::string SoftFragment = WithDefines(
    std::string(vtkAliasFreeLookup) + "\n" + vtkAliasFreeCastersFS, "#define ALIASFREE_SOFT\n");
  bool Failed = false; ///< a shader did not build: reported once
  bool MemoryReported = false;
  bool EnclosingReported = false; ///< a light reached the surfaces it lights
  bool BeyondFaces = false;       ///< this frame's lights have maps of what casts beyond faces

  bool BuildPrograms(vtkAliasFreeShadowPass* pass)
  {
    if (this->BuildLookup.IsBuilt())
    {
      return true;
    }
    // The list stages, one define each; the resolve with the lookup table's
    // code (a sample's own tangent plane); the table's construction.
    const std::string lookup = std::string(vtkAliasFreeLookup) + "\n";
    const std::tuple<vtkShadowCompute::Program*, std::string, std::string> programs[] = {
      { &this->Bounds, "ALIASFREE_BOUNDS", vtkAliasFreeListsCS },
      { &this->Count, "ALIASFREE_COUNT", vtkAliasFreeListsCS },
      { &this->DepthLevel, "ALIASFREE_DEPTH_LEVEL", vtkAliasFreeListsCS },
      { &this->DepthMarked, "ALIASFREE_DEPTH_MARKED", vtkAliasFreeListsCS },
      { &this->ScanBlocks, "ALIASFREE_SCAN_BLOCKS", vtkAliasFreeListsCS },
      { &this->ScanTop, "ALIASFREE_SCAN_TOP", vtkAliasFreeListsCS },
      { &this->ScanAdd, "ALIASFREE_SCAN_ADD", vtkAliasFreeListsCS },
      { &this->Scatter, "ALIASFREE_SCATTER", vtkAliasFreeListsCS },
      { &this->Resolve, "ALIASFREE_RESOLVE", lookup + vtkAliasFreeListsCS },
      { &this->BuildLookup, "ALIASFREE_LOOKUP_BUILD", lookup + vtkAliasFreeLookupBuildCS }
    };
    std::string log;
    for (const auto& program : programs)
    {
      if (!std::get<0>(program)->Build(
            WithDefines(std::get<2>(program), "#define " + std::get<1>(program) + "\n"), &log))
      {
        vtkErrorWithObjectMacro(pass,
          "aliasfree: the " << std::get<1>(program) << " compute shader did not build: " << log);
        return false;
      }
    }
    return true;
  }

  static void Grow(vtkShadowCompute::Buffer& buffer, size_t bytes)
  {
    if (buffer.GetSize() < bytes)
    {
      buffer.Allocate(bytes);
    }
  }
};

vtkStandardNewMacro(vtkAliasFreeShadowPass);

//------------------------------------------------------------------------------
vtkAliasFreeShadowPass::vtkAliasFreeShadowPass()
  : Internal(new Internals)
{
}

vtkAliasFreeShadowPass::~vtkAliasFreeShadowPass() = default;

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::SetNumberOfLightSamples(int count)
{
  const int clamped = std::max(32, std::min(1024, (count + 31) / 32 * 32));
  if (clamped != this->NumberOfLightSamples)
  {
    this->NumberOfLightSamples = clamped;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::SetLightScale(double x, double y, double z)
{
  const double scale[3] = { std::max(x, 1.0e-3), std::max(y, 1.0e-3), std::max(z, 1.0e-3) };
  if (!std::equal(scale, scale + 3, this->LightScale))
  {
    std::copy(scale, scale + 3, this->LightScale);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::Traits vtkAliasFreeShadowPass::GetTraits() const
{
  Traits traits;
  traits.PointLights = true;
  traits.CasterGeometry = true; // the casters' triangles
  traits.Compute = true;
  traits.ScreenSpace = true; // each pixel's visibility
  // The map of what casts beyond faces (lines, points): kept for every
  // light, so that the lights shadowed do not depend on the scene's actors.
  traits.ReceiverTexturesPerLight = 1;
  // Bent normals' two texture buffers, read by the receivers' vertex shaders.
  traits.ReceiverTexturesPerFrame = this->BentNormals ? 2 : 0;
  traits.UncombinedLightSpaceData =
    "per-pixel light-space lists (each process tests only its own triangles)";
  return traits;
}

//------------------------------------------------------------------------------
bool vtkAliasFreeShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  // The light's own depth map serves only what has no view sample:
  // translucent surfaces.
  if (!this->RenderLightDepthMaps(s, false))
  {
    return false;
  }
  // What the triangle tests cannot take (lines, points, imposters, faces
  // drawn as wireframe) casts as `hard` casts it, through a depth map of
  // its own: every view sample's visibility is the lesser of the two.
  Internals& in = *this->Internal;
  // Drawn, and combined, by every process when one has such props.
  in.BeyondFaces = this->OnAnyProcess(!this->Casters->GetDepthMapProps().empty());
  if (!in.BeyondFaces)
  {
    return true;
  }
  for (auto& light : this->Maps->GetLights())
  {
    const auto spec = light.Point ? vtkShadowTextureSpec::DistanceCube(this->PackedCubeMaps)
                                  : vtkShadowTextureSpec::DepthMap(false);
    vtkTextureObject* map = this->Maps->GetTexture(light, 0, spec);
    const bool drawn = light.Point ? this->RenderDistanceCube(s, light.Faces, map, true)
                                   : this->RenderDepthMap(s, light.Map, map, true);
    if (!drawn)
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkAliasFreeShadowPass::RenderScreenSpace(const vtkRenderState* s)
{
  this->NumberOfViewSamples = 0;
  this->LongestList = 0;
  if (this->Internal->Failed)
  {
    return false;
  }
  if (!this->Internal->BuildPrograms(this))
  {
    this->Internal->Failed = true;
    return false;
  }
  const int width = this->Screen->GetWidth(), height = this->Screen->GetHeight();
  const auto& lights = this->Maps->GetLights();
  const bool soft = this->Variant == Soft;
  const size_t pixels = static_cast<size_t>(width) * height;
  const size_t texels = static_cast<size_t>(this->MapSize) * this->MapSize;
  const size_t words = soft ? static_cast<size_t>(this->NumberOfLightSamples / 32) : 0;

  // Memory, before anything is allocated: the camera pass's two targets,
  // per pixel its entry and (at most) its sample, hidden bit and mask, per
  // texel its count, offset and mark (and the draws' targets: the map's
  // size and half of it), the depth pyramid, the lookup tables; and the
  // casters' triangles and edges (once per polydata, built or to build).
  const size_t depthCells = DepthPyramidCells(this->MapSize);
  double bytes = pixels * (2 * 16 + 8 + 16 + 0.125 + 4.0 * words) + texels * (4 + 4 + 4 + 1.25) +
    (texels / 1024 + 1) * 4.0 + depthCells * 4.0;
  double triangles = 0.0;
  std::set<vtkPolyData*> counted;
  for (const vtkShadowCaster& caster : this->Casters->GetCasters())
  {
    if (caster.Faces && counted.insert(caster.Data).second)
    {
      triangles += CountTriangles(caster.Data);
    }
  }
  bytes += triangles *
    (BytesPerTriangle +
      1.5 * (BytesPerEdgeBuilding + (this->KeepsEdges() ? BytesPerEdgeKept : 0.0)));
  for (const auto& light : lights)
  {
    if (soft && light.Radius > 0.0)
    {
      bytes += (this->Jitter ? pixels * 16.0 : 0.0) + LookupAngles * LookupDistances * 4.0 * words +
        this->NumberOfLightSamples * 16.0;
    }
  }
  this->MemoryBytes = bytes;
  if (bytes > this->MemoryLimit * 1024.0 * 1024.0)
  {
    if (!this->Internal->MemoryReported)
    {
      vtkErrorMacro("aliasfree: this frame needs "
        << std::ceil(bytes / (1024.0 * 1024.0)) << " MiB for its lists, masks and tables (" << width
        << "x" << height << " view samples, a " << this->MapSize << "^2 map"
        << (soft ? ", " + std::to_string(this->NumberOfLightSamples) + " light samples" : "")
        << ") and its casters' " << std::llround(triangles)
        << " triangles and their edges, over MemoryLimit (" << this->MemoryLimit
        << " MiB): drawing without shadows. Use fewer caster triangles (decimate the mesh), a "
           "smaller window, map or fewer light samples, or raise MemoryLimit.");
      this->Internal->MemoryReported = true;
    }
    return false;
  }
  this->Internal->MemoryReported = false;

  vtkTextureObject* positions = this->Screen->GetTexture("aliasfree.positions", 4);
  vtkTextureObject* normals = this->Screen->GetTexture("aliasfree.normals", 4);
  // Each pixel's surface: its position, and its face's normal where it has one.
  CameraPassCode code;
  code.Implementation =
    "  gl_FragData[0] = vec4(vtkShadowPositionWC.xyz / vtkShadowPositionWC.w, 1.0);\n"
    "  gl_FragData[1] = vec4(vtkShadowNormalWC, vtkShadowFaceDefined ? 1.0 : 0.0);\n";
  if (!this->RenderCameraDepth(s, { positions, normals }, code))
  {
    return false;
  }

  Internals& in = *this->Internal;
  Internals::Grow(in.CountsBuffer, texels * 4);
  Internals::Grow(in.OffsetsBuffer, texels * 4);
  Internals::Grow(in.BlocksBuffer, (texels / 1024 + 1) * 4);
  Internals::Grow(in.DepthsBuffer, depthCells * 4);
  Internals::Grow(in.PixelsBuffer, pixels * 8);
  Internals::Grow(in.SamplesBuffer, pixels * 16);
  in.Lookups.resize(lights.size());
  in.Still.resize(lights.size());
  in.History.resize(lights.size(), 0);

  positions->Activate();
  normals->Activate();
  bool drawn = true;
  for (size_t slot = 0; slot < lights.size() && drawn; ++slot)
  {
    drawn = this->RenderLight(s, static_cast<int>(slot));
  }
  positions->Deactivate();
  normals->Deactivate();
  in.Casters.Prune(*this->Casters);
  in.EnclosingReported = in.EnclosingReported && !drawn; // reported again when it recurs
  return drawn;
}

//------------------------------------------------------------------------------
bool vtkAliasFreeShadowPass::RenderLight(const vtkRenderState* s, int slot)
{
  const auto& light = this->Maps->GetLights()[slot];
  // Temporal jitter (section 4.2): while the view, the light, the casters
  // and the settings stay as they were, each frame turns the light samples
  // and adds its visibility to the ones before.
  Internals& in = *this->Internal;
  std::vector<double> still;
  if (this->Jitter && this->Variant == Soft && light.Radius > 0.0)
  {
    vtkRenderer* renderer = s->GetRenderer();
    vtkCamera* camera = renderer->GetActiveCamera();
    const double* matrix =
      camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1.0, 1.0)
        ->GetData();
    still.assign(matrix, matrix + 16);
    still.insert(still.end(),
      { static_cast<double>(this->Screen->GetWidth()),
        static_cast<double>(this->Screen->GetHeight()), light.Position.x, light.Position.y,
        light.Position.z, light.Direction.x, light.Direction.y, light.Direction.z,
        light.Map.Direction.x, light.Map.Direction.y, light.Map.Direction.z, light.Radius,
        light.ConeAngle, static_cast<double>(this->MapSize),
        static_cast<double>(this->NumberOfLightSamples), static_cast<double>(this->LightShape),
        this->LightScale[0], this->LightScale[1], this->LightScale[2],
        static_cast<double>(this->Seed), this->RestrictToSilhouettes ? 1.0 : 0.0 });
    for (const vtkShadowCaster& caster : this->Casters->GetCasters())
    {
      still.push_back(static_cast<double>(reinterpret_cast<uintptr_t>(caster.Data)));
      still.push_back(static_cast<double>(caster.Data->GetMTime()));
      const double* m = &caster.ModelToWorld[0][0];
      still.insert(still.end(), m, m + 16);
    }
  }
  const bool same = !still.empty() && still == in.Still[slot];
  in.History[slot] = same ? std::min(in.History[slot] + 1, this->MaximumFramesAccumulated - 1) : 0;
  in.Still[slot] = std::move(still);
  // A point light: each of its six cube faces in turn, with its own lists;
  // each face's resolve writes the pixels whose samples it listed.
  if (!light.Point)
  {
    return this->RenderFrustum(s, slot, light.Map, true);
  }
  for (int face = 0; face < 6; ++face)
  {
    if (!this->RenderFrustum(s, slot, light.Faces[face], face == 0))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
// What the stages of one frustum's pass share.
struct vtkAliasFreeShadowPass::FrustumPass
{
  const vtkRenderState* State = nullptr;
  vtkOpenGLRenderWindow* Context = nullptr;
  int Slot = 0;
  bool First = true; ///< a point light's first face: its resolve writes every pixel
  const vtkShadowMapManager::Light* Light = nullptr;
  vtkShadowFrustum View;   ///< the light's frustum
  vtkShadowFrustum Fitted; ///< cropped to the view samples (stage 1)
  glm::dmat4 WorldToClip{ 1.0 };
  bool Soft = false;
  int Words = 0;           ///< 32-bit words of a light-sample mask
  unsigned int Texels = 0; ///< of the map
  unsigned int GroupsX = 0, GroupsY = 0;
  float LightUniform[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  glm::vec3 Eye{ 0.0f }, Axis{ 0.0f };
  float Reach = 0.0f;       ///< soft: the light's bounding radius, or tan of its angular radius
  float Slack = 0.0f;       ///< how far a face may turn from the centre and still see the light
  float Far = 0.0f;         ///< the farthest view sample
  unsigned int Samples = 0; ///< view samples listed (stage 2)
  glm::dvec3 E1{ 0.0 }, E2{ 0.0 }; ///< across the light's axis
  glm::mat3 ToLight{ 1.0f };       ///< world normals into the light samples' frame (soft)
  bool Restrict = false;           ///< soft, restricted to silhouette edges' regions
  int Width = 0, Height = 0;       ///< of the screen-space buffers
  int MapSize = 0;
  int PositionsUnit = -1, NormalsUnit = -1; ///< the camera pass's targets

  // Use `program` with the uniforms every stage's compute programs share.
  void Use(vtkShadowCompute::Program& program, const glm::dmat4& worldToClip) const
  {
    program.Use(this->Context);
    program.SetUniform2i("aliasfreeScreen", this->Width, this->Height);
    program.SetUniformi("aliasfreeMapSize", this->MapSize);
    program.SetUniformi("aliasfreeTexels", static_cast<int>(this->Texels));
    program.SetUniformi("aliasfreePositions", this->PositionsUnit);
    program.SetUniformi("aliasfreeNormals", this->NormalsUnit);
    const glm::mat4 m(worldToClip);
    program.SetUniformMatrix4f("aliasfreeWorldToClip", glm::value_ptr(m));
    program.SetUniform4f("aliasfreeLight", this->LightUniform);
    program.SetUniform3f("aliasfreeEye", glm::value_ptr(this->Eye));
    program.SetUniform3f("aliasfreeAxis", glm::value_ptr(this->Axis));
    program.SetUniformf("aliasfreeFacingSlack", this->Slack);
  }
};

//------------------------------------------------------------------------------
bool vtkAliasFreeShadowPass::RenderFrustum(
  const vtkRenderState* s, int slot, const vtkShadowFrustum& view, bool first)
{
  FrustumPass pass;
  this->BeginFrustum(s, slot, view, first, pass);
  if (!this->FitFrustumToViewSamples(pass))
  {
    return false;
  }
  this->BuildLists(pass);
  this->PrepareLightSamples(pass);
  if (!this->TestCasters(pass))
  {
    return false;
  }
  this->Resolve(pass);
  return true;
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::BeginFrustum(
  const vtkRenderState* s, int slot, const vtkShadowFrustum& view, bool first, FrustumPass& pass)
{
  const auto& light = this->Maps->GetLights()[slot];
  pass.State = s;
  pass.Context = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  pass.Slot = slot;
  pass.First = first;
  pass.Light = &light;
  pass.View = view;
  pass.Fitted = view;
  pass.Texels = static_cast<unsigned int>(this->MapSize) * this->MapSize;
  pass.Soft = this->Variant == Soft && light.Radius > 0.0;
  pass.Words = pass.Soft ? this->NumberOfLightSamples / 32 : 0;
  pass.Width = this->Screen->GetWidth();
  pass.Height = this->Screen->GetHeight();
  pass.GroupsX = (pass.Width + 7) / 8;
  pass.GroupsY = (pass.Height + 7) / 8;
  pass.MapSize = this->MapSize;
  pass.PositionsUnit = this->Screen->GetTexture("aliasfree.positions", 4)->GetTextureUnit();
  pass.NormalsUnit = this->Screen->GetTexture("aliasfree.normals", 4)->GetTextureUnit();
  const glm::dvec3 towards = light.Directional ? -view.Direction : light.Position;
  pass.LightUniform[0] = static_cast<float>(towards.x);
  pass.LightUniform[1] = static_cast<float>(towards.y);
  pass.LightUniform[2] = static_cast<float>(towards.z);
  pass.LightUniform[3] = light.Directional ? 0.0f : 1.0f;
  pass.Eye = glm::vec3(view.Eye);
  pass.Axis = glm::vec3(view.Direction);
  // Soft: the light's reach, its bounding sphere's radius (spot and point
  // lights) or the tangent of its angular radius (directional), and how far
  // a face may turn from its centre and still see some of it.
  const double* scale = this->LightScale;
  const double spread = light.Directional ? light.GetHalfSize() : 0.0;
  pass.Reach = !pass.Soft
    ? 0.0f
    : static_cast<float>(light.Directional ? spread
                                           : light.Radius *
            (this->LightShape == Sphere    ? std::max({ scale[0], scale[1], scale[2] })
                : this->LightShape == Disc ? std::max(scale[0], scale[1])
                                           : std::sqrt(scale[0] * scale[0] + scale[1] * scale[1])));
  pass.Slack = light.Directional
    ? static_cast<float>(std::sin(std::atan(static_cast<double>(pass.Reach))))
    : pass.Reach;
  pass.Restrict = pass.Soft && this->RestrictToSilhouettes;
  Internals& in = *this->Internal;
  in.CountsBuffer.BindStorage(Counts);
  in.OffsetsBuffer.BindStorage(Offsets);
  in.BlocksBuffer.BindStorage(Blocks);
  in.PixelsBuffer.BindStorage(Pixels);
  in.SamplesBuffer.BindStorage(Samples);
}

//------------------------------------------------------------------------------
bool vtkAliasFreeShadowPass::FitFrustumToViewSamples(FrustumPass& pass)
{
  // 1. The view samples' bounds in the light's map (section 4.3).
  Internals& in = *this->Internal;
  const vtkShadowFrustum& view = pass.View;
  const int mapSize = this->MapSize;
  const int initial[8] = { Ordered(2.0f), Ordered(-2.0f), Ordered(2.0f), Ordered(-2.0f),
    Ordered(-VTK_FLOAT_MAX), 0, 0, Ordered(VTK_FLOAT_MAX) };
  in.StatsBuffer.Allocate(sizeof initial, initial);
  in.StatsBuffer.BindStorage(Stats);
  const glm::dmat4 lightToClip = view.Projection * view.View;
  pass.Use(in.Bounds, lightToClip);
  in.Bounds.Dispatch(pass.GroupsX, pass.GroupsY);
  vtkShadowCompute::Barrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  int stats[8];
  in.StatsBuffer.Read(stats, sizeof stats);
  // A light whose sphere reaches a surface it lights has no outside to see
  // it from, and every triangle's influence region would cover the map:
  // minutes a frame, for no meaningful shadow. Refused instead.
  const float nearest = FromOrdered(stats[7]);
  if (pass.Soft && !pass.Light->Directional && pass.Reach >= nearest)
  {
    if (!in.EnclosingReported)
    {
      vtkErrorMacro("aliasfree: light " << pass.Slot << "'s radius (" << pass.Reach
                                        << ") reaches a surface it lights (" << nearest
                                        << " from its centre): drawing without shadows. Make the "
                                           "light smaller than its distance to the scene.");
      in.EnclosingReported = true;
    }
    return false;
  }
  vtkShadowFrustum& fitted = pass.Fitted;
  pass.Far = std::max(FromOrdered(stats[4]), static_cast<float>(view.Near));
  if (this->FitToViewSamples && stats[0] <= stats[1])
  {
    // Crop the clip space to the bounds, two texels wider on each side.
    double x0 = FromOrdered(stats[0]), x1 = FromOrdered(stats[1]);
    double y0 = FromOrdered(stats[2]), y1 = FromOrdered(stats[3]);
    const double mx = 2.0 * std::max(x1 - x0, 1.0e-4) / mapSize;
    const double my = 2.0 * std::max(y1 - y0, 1.0e-4) / mapSize;
    x0 = std::max(x0 - mx, -1.0);
    x1 = std::min(x1 + mx, 1.0);
    y0 = std::max(y0 - my, -1.0);
    y1 = std::min(y1 + my, 1.0);
    glm::dmat4 crop(1.0);
    crop[0][0] = 2.0 / (x1 - x0);
    crop[1][1] = 2.0 / (y1 - y0);
    crop[3][0] = -(x0 + x1) / (x1 - x0);
    crop[3][1] = -(y0 + y1) / (y1 - y0);
    fitted.Projection = crop * view.Projection;
    fitted.WorldToMap = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) *
      glm::scale(glm::dmat4(1.0), glm::dvec3(0.5)) * fitted.Projection * fitted.View;
  }
  pass.WorldToClip = fitted.Projection * fitted.View;
  return true;
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::BuildLists(FrustumPass& pass)
{
  // 2. Lists: counts, offsets (prefix sum), samples packed at them.
  Internals& in = *this->Internal;
  const glm::dmat4& worldToClip = pass.WorldToClip;
  const int initial[8] = { Ordered(2.0f), Ordered(-2.0f), Ordered(2.0f), Ordered(-2.0f),
    Ordered(-VTK_FLOAT_MAX), 0, 0, 0 };
  in.StatsBuffer.Allocate(sizeof initial, initial);
  in.StatsBuffer.BindStorage(Stats);
  in.CountsBuffer.Clear(0);
  in.DepthsBuffer.Clear(0x80000000u); // below every depth: no sample
  in.DepthsBuffer.BindStorage(Depths);
  pass.Use(in.Count, worldToClip);
  in.Count.Dispatch(pass.GroupsX, pass.GroupsY);
  vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  if (pass.Soft)
  {
    this->BuildDepthLevels(pass);
  }
  int stats[8];
  in.StatsBuffer.Read(stats, sizeof stats);
  pass.Samples = static_cast<unsigned int>(stats[6]);
  this->NumberOfViewSamples += pass.Samples;
  this->LongestList = std::max(this->LongestList, stats[5]);

  const unsigned int blocks = (pass.Texels + 1023) / 1024;
  pass.Use(in.ScanBlocks, worldToClip);
  DispatchRows(in.ScanBlocks, blocks);
  vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT);
  pass.Use(in.ScanTop, worldToClip);
  in.ScanTop.SetUniformi("aliasfreeTexels", static_cast<int>(blocks));
  in.ScanTop.Dispatch(1);
  vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT);
  pass.Use(in.ScanAdd, worldToClip);
  in.ScanAdd.Dispatch((this->MapSize + 7) / 8, (this->MapSize + 7) / 8);
  vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT);
  pass.Use(in.Scatter, worldToClip);
  in.Scatter.Dispatch(pass.GroupsX, pass.GroupsY);
  vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::BuildDepthLevels(FrustumPass& pass)
{
  // The pyramid of greatest depths over the texels' own, for culling
  // influence regions (vtkAliasFreeCastersGS.glsl).
  Internals& in = *this->Internal;
  in.DepthsBuffer.BindStorage(Depths);
  int from[3] = { 0, this->MapSize, this->MapSize };
  while (from[1] > 1)
  {
    const int size = (from[1] + 1) / 2;
    const int to[3] = { from[0] + from[1] * from[1], size, size };
    in.DepthLevel.Use(pass.Context);
    in.DepthLevel.SetUniform3i("aliasfreeLevelFrom", from);
    in.DepthLevel.SetUniform3i("aliasfreeLevelTo", to);
    in.DepthLevel.Dispatch((size + 7) / 8, (size + 7) / 8);
    vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT);
    std::copy(to, to + 3, from);
  }
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::PrepareLightSamples(FrustumPass& pass)
{
  // 3. Hidden bits (hard) or masks of light samples (soft), cleared.
  Internals& in = *this->Internal;
  const auto& light = *pass.Light;
  const vtkShadowFrustum& view = pass.View;
  const bool soft = pass.Soft;
  const int words = pass.Words;
  const unsigned int samples = pass.Samples;
  const int slot = pass.Slot;
  const double* scale = this->LightScale;
  const double spread = light.Directional ? light.GetHalfSize() : 0.0;
  Internals::Grow(in.HiddenBuffer,
    std::max<size_t>(soft ? static_cast<size_t>(samples) * words * 4 : (samples / 32 + 1) * 4, 4));
  in.HiddenBuffer.Clear(0);
  in.HiddenBuffer.BindStorage(Hidden);

  // The light's samples and lookup table (soft), built when they change.
  glm::dvec3 e1, e2;
  vtkShadowMatrices::Basis(light.Directional ? -view.Direction : light.Direction, e1, e2);
  const glm::dvec3 e3 = light.Directional ? -view.Direction : light.Direction;
  if (soft)
  {
    auto& table = in.Lookups[slot];
    if (!table)
    {
      table.reset(new LookupTable);
    }
    const auto key = std::make_tuple(
      light.Directional ? Disc : this->LightShape, this->NumberOfLightSamples, this->Seed);
    if (table->Key != key)
    {
      // In the light's frame (x, y across its axis, z along it): the unit
      // ball (sphere), disc or square; directional lights: the unit disc.
      const int n = this->NumberOfLightSamples;
      std::vector<glm::dvec3> points;
      if (light.Directional || this->LightShape == Disc)
      {
        // Exactly n strata: the most nearly square grid whose sides divide n.
        int columns = static_cast<int>(std::sqrt(static_cast<double>(n)));
        while (n % columns != 0)
        {
          --columns;
        }
        for (const auto& d : vtkShadowSampling::StratifiedDisc(columns, n / columns, this->Seed))
        {
          points.emplace_back(d, 0.0);
        }
      }
      else if (this->LightShape == Sphere)
      {
        points = vtkShadowSampling::HaltonBall(n, this->Seed);
      }
      else
      {
        std::mt19937 generator(this->Seed);
        for (int i = 0; i < n; ++i)
        {
          // Stratified along one axis, Halton's radical inverse along the other.
          points.emplace_back(2.0 * (i + vtkShadowSampling::Uniform(generator)) / n - 1.0,
            2.0 * vtkShadowSampling::RadicalInverse(static_cast<unsigned int>(i + 1), 2) - 1.0,
            0.0);
        }
      }
      std::vector<float> packed(4 * static_cast<size_t>(n), 0.0f);
      for (int i = 0; i < n; ++i)
      {
        packed[4 * i] = static_cast<float>(points[i].x);
        packed[4 * i + 1] = static_cast<float>(points[i].y);
        packed[4 * i + 2] = static_cast<float>(points[i].z);
      }
      in.LightSamples.Allocate(packed.size() * sizeof(float), packed.data());
      const int cells = LookupAngles * LookupDistances;
      table->Masks.Allocate(static_cast<size_t>(cells) * words * 4);
      in.LightSamples.BindStorage(Samples);
      table->Masks.BindStorage(Lookup);
      in.BuildLookup.Use(pass.Context);
      in.BuildLookup.SetUniformi("aliasfreeCells", cells);
      in.BuildLookup.SetUniformi("aliasfreeWords", words);
      DispatchRows(in.BuildLookup, (cells * words + 255) / 256);
      vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT);
      in.SamplesBuffer.BindStorage(Samples);
      table->Key = key;
    }
    table->Masks.BindStorage(Lookup);
    // World normals into the frame, scaled by the light's size and shape
    // (an ellipsoid's planes are the ball's planes of the scaled normal).
    const glm::dmat3 frame(e1, e2, e3);
    const glm::dvec3 size = light.Directional
      ? glm::dvec3(spread, spread, 0.0)
      : light.Radius * glm::dvec3(scale[0], scale[1], scale[2]);
    const glm::dmat3 shape(
      glm::dvec3(size.x, 0.0, 0.0), glm::dvec3(0.0, size.y, 0.0), glm::dvec3(0.0, 0.0, size.z));
    // Jittered: the samples turned by J (any rotation of the ball; about
    // the axis for discs and the cone; the square's eight symmetries), so
    // normals by J^T. Frame 0 of an accumulation is not turned.
    glm::dmat3 turn(1.0);
    const int history = in.History[slot];
    if (history > 0)
    {
      std::mt19937 generator(this->Seed * 7919u + static_cast<unsigned int>(history));
      std::uniform_real_distribution<double> uniform(0.0, 1.0);
      const double twoPi = 2.0 * glm::pi<double>();
      auto aboutZ = [](double angle)
      {
        return glm::dmat3(glm::dvec3(std::cos(angle), std::sin(angle), 0.0),
          glm::dvec3(-std::sin(angle), std::cos(angle), 0.0), glm::dvec3(0.0, 0.0, 1.0));
      };
      if (!light.Directional && this->LightShape == Sphere)
      {
        // A uniform random rotation: a random axis (uniform on the sphere)
        // and angle from a uniform quaternion (Shoemake).
        const double u1 = uniform(generator), u2 = uniform(generator), u3 = uniform(generator);
        const glm::dquat q(std::sqrt(u1) * std::cos(twoPi * u3),
          std::sqrt(1.0 - u1) * std::sin(twoPi * u2), std::sqrt(1.0 - u1) * std::cos(twoPi * u2),
          std::sqrt(u1) * std::sin(twoPi * u3));
        turn = glm::mat3_cast(q);
      }
      else if (!light.Directional && this->LightShape == Rectangle)
      {
        const int symmetry = static_cast<int>(uniform(generator) * 8.0) % 8;
        turn = aboutZ(0.5 * glm::pi<double>() * (symmetry % 4));
        if (symmetry >= 4)
        {
          turn = turn *
            glm::dmat3(
              glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, -1.0, 0.0), glm::dvec3(0.0, 0.0, 1.0));
        }
      }
      else
      {
        turn = aboutZ(twoPi * uniform(generator));
      }
    }
    pass.ToLight = glm::mat3(glm::transpose(turn) * shape * glm::transpose(frame));
  }
  pass.E1 = e1;
  pass.E2 = e2;
}

//------------------------------------------------------------------------------
bool vtkAliasFreeShadowPass::TestCasters(FrustumPass& pass)
{
  // 4. Every caster triangle over the texels it touches (its influence
  // region, soft), testing their samples. Soft, restricted to the
  // silhouettes: first the texels of silhouette edges' influence regions
  // are marked and the centre's hard shadow drawn; triangles then test
  // samples of marked texels only (section 4.3).
  if (pass.Samples == 0)
  {
    return true;
  }
  Internals& in = *this->Internal;
  const auto& light = *pass.Light;
  const vtkShadowFrustum& view = pass.View;
  const bool soft = pass.Soft;
  const bool restrict = pass.Restrict;
  // Edges are kept for every light of a soft pass restricted to silhouettes
  // (one with no radius too), so that mixed lights do not rebuild them.
  const bool withEdges = this->KeepsEdges();
  const int words = pass.Words;
  const int mapSize = this->MapSize;
  const float reach = pass.Reach, far = pass.Far;
  const glm::vec3 eye = pass.Eye, axis = pass.Axis;
  const glm::mat3 toLight = pass.ToLight;
  const float* lightUniform = pass.LightUniform; // read while drawing
  const glm::mat4 clip(pass.WorldToClip);
  const glm::vec3 side0(light.Directional ? pass.E1 : glm::dvec3(0.0)),
    side1(light.Directional ? pass.E2 : glm::dvec3(0.0));
  const float epsilon =
    static_cast<float>(light.Directional ? 1.0e-5 * (view.Far - view.Near) : 1.0e-5);
  enum class Kind
  {
    Edges,
    Hard,
    Soft
  };
  // The casters draw into a scratch map-sized target: they write lists, not colours.
  vtkShadowTextureSpec target;
  target.Type = vtkShadowTextureSpec::Format::Byte;
  vtkTextureObject* scratch = this->Maps->GetScratch(0, target);
  // The soft pass at half the resolution: a fragment tests 2x2 texels.
  vtkShadowTextureSpec coarse = target;
  coarse.Size = (mapSize + 1) / 2;
  vtkTextureObject* coarseScratch = soft ? this->Maps->GetScratch(1, coarse) : nullptr;
  auto draw = [&](Kind kind)
  {
    vtkShadowDrawSetup setup;
    setup.View = &pass.Fitted;
    setup.Colours = { kind == Kind::Soft ? coarseScratch : scratch };
    const float rasterSize = static_cast<float>(kind == Kind::Soft ? coarse.Size : mapSize);
    const float rasterScale = kind == Kind::Soft ? 0.5f * mapSize / coarse.Size : 1.0f;
    setup.DepthTest = false;
    setup.Draw = vtkShadowDrawSetup::Props::None;
    for (const vtkShadowCaster& caster : this->Casters->GetCasters())
    {
      if (!caster.Faces)
      {
        continue;
      }
      CasterTriangles& triangles = in.Casters.Get(
        caster,
        [withEdges](vtkPolyData* data, CasterTriangles& value)
        { BuildTriangles(data, withEdges, value); },
        withEdges);
      vtkShadowGeometry* geometry =
        kind == Kind::Edges ? triangles.Edges.get() : triangles.Geometry.get();
      if (kind == Kind::Edges)
      {
        geometry->SetShaders(in.EdgesVertex, in.EdgesFragment, in.EdgesGeometry);
      }
      else
      {
        geometry->SetShaders(in.Vertex, kind == Kind::Soft ? in.SoftFragment : in.HardFragment,
          kind == Kind::Soft ? in.SoftGeometry : in.HardGeometry);
      }
      const int closed = triangles.Closed ? 1 : 0;
      // A mirroring placement turns the enclosed volume inside out.
      const float orientation = glm::determinant(glm::dmat3(caster.ModelToWorld)) < 0.0
        ? -triangles.Orientation
        : triangles.Orientation;
      const glm::mat3 normalToWorld(glm::transpose(glm::inverse(glm::dmat3(caster.ModelToWorld))));
      setup.Geometry.emplace_back(geometry, caster.ModelToWorld,
        [=](vtkShaderProgram* program)
        {
          program->SetUniformMatrix4x4(
            "aliasfreeWorldToClip", const_cast<float*>(glm::value_ptr(clip)));
          program->SetUniform4f("aliasfreeLight", lightUniform);
          program->SetUniformf("aliasfreeMapSize", static_cast<float>(mapSize));
          program->SetUniformf("aliasfreeRasterSize", rasterSize);
          program->SetUniformf("aliasfreeRasterScale", rasterScale);
          program->SetUniformi("aliasfreeMapTexels", mapSize);
          program->SetUniformi("aliasfreeClosed", closed);
          program->SetUniformf("aliasfreeOrientation", orientation);
          program->SetUniformf("aliasfreeEpsilon", epsilon);
          if (kind != Kind::Hard)
          {
            program->SetUniformf("aliasfreeReach", reach);
            program->SetUniform3f("aliasfreeEye", glm::value_ptr(eye));
            program->SetUniform3f("aliasfreeAxis", glm::value_ptr(axis));
            program->SetUniform3f("aliasfreeSide0", glm::value_ptr(side0));
            program->SetUniform3f("aliasfreeSide1", glm::value_ptr(side1));
            program->SetUniformf("aliasfreeFar", far);
          }
          if (kind == Kind::Edges)
          {
            program->SetUniformMatrix3x3(
              "aliasfreeNormalToWorld", const_cast<float*>(glm::value_ptr(normalToWorld)));
          }
          if (kind == Kind::Soft)
          {
            program->SetUniformMatrix3x3(
              "aliasfreeToLight", const_cast<float*>(glm::value_ptr(toLight)));
            program->SetUniformi("aliasfreeWords", words);
          }
        });
    }
    if (!setup.Geometry.empty() && !this->Draw(pass.State, setup))
    {
      vtkErrorMacro("aliasfree: drawing the casters into the map failed (its shaders, or its "
                    "target): drawing without shadows.");
      in.Failed = true;
      return false;
    }
    vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT);
    return true;
  };
  Internals::Grow(in.MarksBuffer, static_cast<size_t>(pass.Texels) * 4);
  in.MarksBuffer.BindStorage(Marks);
  in.DepthsBuffer.BindStorage(CasterDepths);
  if (restrict)
  {
    in.MarksBuffer.Clear(0);
    Internals::Grow(in.CentreBuffer, (pass.Samples / 32 + 1) * 4);
    in.CentreBuffer.Clear(0);
    in.CentreBuffer.BindStorage(Hidden);
    if (!draw(Kind::Edges) || !draw(Kind::Hard))
    {
      return false;
    }
    // The soft pass tests the marked texels only: the others leave its
    // pyramid, so that regions over none of them are culled whole.
    in.DepthsBuffer.BindStorage(Depths);
    pass.Use(in.DepthMarked, pass.WorldToClip);
    in.DepthMarked.Dispatch((mapSize + 7) / 8, (mapSize + 7) / 8);
    vtkShadowCompute::Barrier(GL_SHADER_STORAGE_BARRIER_BIT);
    this->BuildDepthLevels(pass);
    in.DepthsBuffer.BindStorage(CasterDepths);
    in.Lookups[pass.Slot]->Masks.BindStorage(Lookup); // the pyramid's stages took its binding
    in.HiddenBuffer.BindStorage(Hidden);
  }
  if (!draw(soft ? Kind::Soft : Kind::Hard))
  {
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::Resolve(FrustumPass& pass)
{
  // 5. Each pixel's visibility, for the receivers.
  Internals& in = *this->Internal;
  const int slot = pass.Slot;
  const bool soft = pass.Soft;
  vtkTextureObject* visibility = this->Screen->GetVisibility(slot);
  const double* camera = pass.State->GetRenderer()->GetActiveCamera()->GetPosition();
  const float cameraPosition[3] = { static_cast<float>(camera[0]), static_cast<float>(camera[1]),
    static_cast<float>(camera[2]) };
  pass.Use(in.Resolve, pass.WorldToClip);
  in.Resolve.SetUniformi("aliasfreeWords", pass.Words);
  in.Resolve.SetUniformi("aliasfreeRestrict", pass.Restrict ? 1 : 0);
  in.Resolve.SetUniformi("aliasfreeListedOnly", pass.First ? 0 : 1);
  in.Resolve.SetUniformMatrix3f("aliasfreeToLight", glm::value_ptr(pass.ToLight));
  if (soft)
  {
    in.Lookups[slot]->Masks.BindStorage(Lookup);
  }
  if (pass.Restrict)
  {
    in.MarksBuffer.BindStorage(Marks);
    in.CentreBuffer.BindStorage(Centre);
  }
  in.Resolve.SetUniform3f("aliasfreeCameraPosition", cameraPosition);
  vtkShadowCompute::BindImage(0, visibility, GL_WRITE_ONLY, GL_RGBA32F);
  const bool jittered = this->Jitter && soft;
  in.Resolve.SetUniformi("aliasfreeHistory", jittered ? in.History[slot] : -1);
  if (jittered)
  {
    vtkTextureObject* history =
      this->Screen->GetTexture("aliasfree.history" + std::to_string(slot), 4);
    vtkShadowCompute::BindImage(1, history, GL_READ_WRITE, GL_RGBA32F);
  }
  in.Resolve.Dispatch(pass.GroupsX, pass.GroupsY);
  vtkShadowCompute::Barrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::ReceiverShading vtkAliasFreeShadowPass::GetReceiverShading(
  const vtkShadowShaderSources& sources)
{
  ReceiverShading shading;
  const int lights = static_cast<int>(this->Maps->GetLights().size());
  if (!this->BentNormals || lights == 0 || !vtkAliasFreeBentNormals::Applies(sources))
  {
    return shading;
  }
  shading.VertexDeclarations = vtkAliasFreeBentNormals::VertexDeclarations(lights);
  shading.VertexImplementation = vtkAliasFreeBentNormals::VertexImplementation();
  shading.FragmentDeclarations = vtkAliasFreeBentNormals::FragmentDeclarations(lights);
  for (int slot = 0; slot < lights; ++slot)
  {
    shading.PhongScales.push_back(vtkAliasFreeBentNormals::PhongScale(slot));
  }
  return shading;
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::SetReceiverShadingUniforms(vtkShaderProgram* program, vtkProp* prop)
{
  if (!this->BentNormals)
  {
    return;
  }
  // Bent towards each light's centre: its position, or the direction towards it.
  std::vector<glm::vec4> lights;
  for (const auto& light : this->Maps->GetLights())
  {
    lights.push_back(light.Directional ? glm::vec4(glm::vec3(-light.Direction), 0.0f)
                                       : glm::vec4(glm::vec3(light.Position), 1.0f));
  }
  this->Internal->Bent.SetUniforms(program, prop, lights,
    vtkOpenGLRenderWindow::SafeDownCast(this->Maps->GetRenderer()->GetRenderWindow()));
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::ReceiversDrawn()
{
  this->Internal->Bent.EndFrame(*this->Casters);
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  Internals& in = *this->Internal;
  in.Casters.Clear();
  in.Bent.ReleaseGraphicsResources(w);
  for (auto* program : { &in.Bounds, &in.Count, &in.DepthLevel, &in.DepthMarked, &in.ScanBlocks,
         &in.ScanTop, &in.ScanAdd, &in.Scatter, &in.Resolve, &in.BuildLookup })
  {
    program->Release();
  }
  for (auto* buffer : { &in.CountsBuffer, &in.OffsetsBuffer, &in.BlocksBuffer, &in.PixelsBuffer,
         &in.SamplesBuffer, &in.HiddenBuffer, &in.StatsBuffer, &in.LightSamples, &in.MarksBuffer,
         &in.CentreBuffer, &in.DepthsBuffer })
  {
    buffer->Release();
  }
  in.Lookups.clear();
  in.Failed = false;
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::ReceiverCode vtkAliasFreeShadowPass::GetReceiverCode()
{
  // The exact visibility of the faces, and with props that draw more than
  // faces the lesser of it and their map's hard shadow (GetDepthMapProps()).
  ReceiverCode code;
  if (!this->Internal->BeyondFaces)
  {
    return code;
  }
  const auto& lights = this->Maps->GetLights();
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    code.Textures.push_back({ "aliasfreeBeyondFaces" + std::to_string(slot),
      lights[slot].Point ? "samplerCube" : "sampler2DShadow", lights[slot].Textures[0] });
  }
  code.Visibility = [this](int slot)
  {
    const std::string beyond =
      this->GetHardLookupExpression(slot, "aliasfreeBeyondFaces" + std::to_string(slot));
    return "min(" + this->GetDefaultVisibility(slot) + ", " + beyond + ")";
  };
  return code;
}

//------------------------------------------------------------------------------
void vtkAliasFreeShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Variant: " << (this->Variant == Hard ? "Hard" : "Soft") << "\n";
  os << indent << "NumberOfLightSamples: " << this->NumberOfLightSamples << "\n";
  static const char* shapes[] = { "Sphere", "Disc", "Rectangle" };
  os << indent << "LightShape: " << shapes[this->LightShape] << "\n";
  os << indent << "LightScale: " << this->LightScale[0] << " " << this->LightScale[1] << " "
     << this->LightScale[2] << "\n";
  os << indent << "FitToViewSamples: " << this->FitToViewSamples << "\n";
  os << indent << "RestrictToSilhouettes: " << this->RestrictToSilhouettes << "\n";
  os << indent << "Jitter: " << this->Jitter << "\n";
  os << indent << "MaximumFramesAccumulated: " << this->MaximumFramesAccumulated << "\n";
  os << indent << "BentNormals: " << this->BentNormals << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "MemoryLimit: " << this->MemoryLimit << "\n";
  os << indent << "MemoryBytes: " << this->MemoryBytes << "\n";
  os << indent << "NumberOfViewSamples: " << this->NumberOfViewSamples << "\n";
  os << indent << "LongestList: " << this->LongestList << "\n";
}
