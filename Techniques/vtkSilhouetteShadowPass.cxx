// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSilhouetteShadowPass.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowGeometry.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"
#include "vtkTopologyAwareMeshFilter.h"

#include "vtkSilhouetteBandsGS.h"
#include "vtkSilhouetteCommon.h"
#include "vtkSilhouetteEdgesFS.h"
#include "vtkSilhouetteEdgesVS.h"
#include "vtkSilhouetteLookupFS.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <vector>

namespace
{
constexpr double Diagonal = 1.4142135623730951; // a texel's diagonal, in texels
constexpr float ClearDistance = -1.0e4f;        // no silhouette near: far outside

// How a caster's TAM is laid out on the GPU.
struct MeshLayout
{
  bool Drop = false;    ///< DropNonSilhouetteFaces
  bool PerFace = false; ///< once a face (instances or points), not once a corner
  bool Half = false;    ///< binary16 attributes

  bool operator==(const MeshLayout& other) const
  {
    return this->Drop == other.Drop && this->PerFace == other.PerFace && this->Half == other.Half;
  }
};

// What the pass keeps of each caster's polydata.
struct CasterMesh
{
  vtkSmartPointer<vtkTopologyAwareMeshFilter> Filter;
  std::shared_ptr<vtkShadowGeometry> Geometry;
};

// The TAM of a caster's polydata, and the geometry that draws it (shaders
// and primitive: set per light, for 2D maps or cube faces).
void BuildMesh(vtkPolyData* data, const MeshLayout& layout, CasterMesh& mesh)
{
  vtkSmartPointer<vtkPolyData> faces = vtkShadowCasterRegistry::MergedFaces(data);
  mesh.Filter = vtkSmartPointer<vtkTopologyAwareMeshFilter>::New();
  mesh.Filter->SetInputData(faces);
  mesh.Filter->SetDropNonSilhouetteFaces(layout.Drop);
  mesh.Filter->SetPerFaceAttributes(layout.PerFace);
  mesh.Filter->SetHalfPrecision(layout.Half);
  mesh.Filter->Update();
  // Only what the silhouette pass reads goes to the GPU: the face's corners
  // and its neighbours' normals, a vertex's own corner being gl_VertexID.
  vtkPolyData* tam = mesh.Filter->GetOutput();
  auto buffer = vtkSmartPointer<vtkPolyData>::New();
  buffer->SetPoints(tam->GetPoints());
  buffer->SetPolys(tam->GetPolys());
  vtkFieldData* from =
    layout.PerFace ? static_cast<vtkFieldData*>(tam->GetCellData()) : tam->GetPointData();
  vtkFieldData* to =
    layout.PerFace ? static_cast<vtkFieldData*>(buffer->GetCellData()) : buffer->GetPointData();
  to->AddArray(from->GetArray("FacePositions"));
  to->AddArray(from->GetArray("AdjacentNormals"));
  mesh.Geometry = vtkShadowGeometry::NewShared();
  mesh.Geometry->SetInput(buffer);
  mesh.Geometry->SetHalfFloat(layout.Half);
}

// The fraction of a disc of unit radius on the lit side of a straight edge
// at signed distance u (u > 0: the centre is on the occluder's side): the
// penumbra profile of a spherical light behind a straight silhouette.
double DiscLit(double u)
{
  u = std::min(std::max(u, -1.0), 1.0);
  return (std::acos(u) - u * std::sqrt(1.0 - u * u)) / 3.14159265358979323846;
}
}

// Per light slot: what the receivers need, and the lookup it was built for.
struct vtkSilhouetteShadowPass::Internals
{
  struct Band
  {
    float Range[4] = { 0.0f, 1.0f, 0.0f, 0.0f }; ///< near, far, parallel, K
    float HalfWidth = 1.0f;                      ///< W: distances kept within it
    float MaximumPenumbra = 1.0f;                ///< Wmax
    /// The receivers' multiply-adds (vtkSilhouetteLookupFS.glsl): half-width
    /// per unit of map depth, 0.5 / W, rows per texel of width, first row.
    float LookupScale[4] = { 0.0f, 0.5f, 0.0f, 0.5f };
    /// The lookup table (Section 2.2.2's falloff across the band) and what
    /// it was built for.
    vtkSmartPointer<vtkTextureObject> Lookup;
    std::vector<double> LookupKey;
  };
  std::vector<Band> Bands;
  vtkShadowCasterCache<CasterMesh, MeshLayout> Meshes;
  // Pass 2's shaders, [rectangles around edges][a cube face (no 2D depth
  // map to read)]: the vertex shader's with the common depths.
  std::array<std::array<std::string, 2>, 2> VertexShaders, FragmentShaders;
  Internals()
  {
    for (int bands = 0; bands < 2; ++bands)
    {
      for (int cube = 0; cube < 2; ++cube)
      {
        const std::string defines = std::string(bands ? "#define SILHOUETTE_BANDS\n" : "") +
          (cube ? "#define SILHOUETTE_CUBE_FACE\n" : "");
        this->VertexShaders[bands][cube] =
          vtkShadowGeometry::WithPrefix(vtkSilhouetteEdgesVS, defines + vtkSilhouetteCommon);
        this->FragmentShaders[bands][cube] =
          vtkShadowGeometry::WithPrefix(vtkSilhouetteEdgesFS, defines);
      }
    }
  }
};

vtkStandardNewMacro(vtkSilhouetteShadowPass);

vtkSilhouetteShadowPass::vtkSilhouetteShadowPass()
  : Internal(new Internals)
{
}
vtkSilhouetteShadowPass::~vtkSilhouetteShadowPass() = default;

namespace
{
// The lookup texture of section 2.2 (eq. 4's four segments side by side,
// `texels` each) with `rows` penumbra widths from 0 to `widest` texels:
//   z_E behind the point:           lit | shadow-map shadow
//   z_E in front, shadow map lit:   the profile of distance d
//   z_E in front, shadow map dark:  the profile's inner half (d >= 0), else
//                                   shadow (another occluder's)
// Receivers whose samples spread over the penumbra read the rows of
// narrower widths (SampleNarrowing()).
std::vector<float> BuildLookup(
  int texels, int rows, double halfWidth, double widest, double edgeWidth)
{
  std::vector<float> values(static_cast<size_t>(4 * texels) * rows);
  for (int row = 0; row < rows; ++row)
  {
    const double width = rows > 1 ? widest * row / (rows - 1) : 0.0;
    const double radius = std::max(width, 0.5 * edgeWidth);
    float* line = &values[static_cast<size_t>(4 * texels) * row];
    for (int j = 0; j < texels; ++j)
    {
      const double d = (2.0 * j / (texels - 1) - 1.0) * halfWidth;
      const float profile = static_cast<float>(DiscLit(d / radius));
      line[j] = 1.0f;
      line[texels + j] = 0.0f;
      line[2 * texels + j] = profile;
      line[3 * texels + j] = d >= 0.0 ? profile : 0.0f;
    }
  }
  return values;
}

// How much the profiles of `samples` samples, all but one `spread`
// half-widths off the point, are narrowed so that their mean keeps the
// light disc's second moment: per axis, a ring of radius s adds s^2 / 2 for
// (n - 1) / n of the samples, a disc profile of radius r adds r^2 / 4 (1 -
// 1.5 spread^2 for the paper's four).
double SampleNarrowing(int samples, double spread)
{
  const double around = (samples - 1.0) / samples;
  return std::sqrt(std::max(1.0 - 2.0 * around * spread * spread, 0.0));
}
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::Traits vtkSilhouetteShadowPass::GetTraits() const
{
  Traits traits;
  traits.PointLights = true;
  traits.CasterGeometry = true; // topology aware meshes
  traits.Samplers = true;       // pass 2 reads the depth map raw
  // Receivers gather four texels of a point light's cube of squared
  // distances, and of the depth map's comparisons (textureGather on a
  // shadow sampler).
  traits.FloatCubeMaps = true;
  traits.ReceiverExtensions = { "GL_ARB_texture_gather", "GL_ARB_gpu_shader5" };
  traits.ReceiverTexturesPerLight = 2; // the distance map and its lookup table
  traits.UncombinedLightSpaceData = "silhouette distance maps";
  return traits;
}

//------------------------------------------------------------------------------
bool vtkSilhouetteShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  // Pass 1: depth, as `hard` draws it.
  if (!this->RenderLightDepthMaps(s, false))
  {
    return false;
  }
  auto& lights = this->Maps->GetLights();
  const bool soft = this->Variant == Soft;

  // Each caster's TAM, rebuilt only when its polydata changes. What is not
  // drawn as filled faces (lines, points, wireframe, imposters) has none:
  // its depth-map shadow is all it casts.
  std::vector<std::pair<const vtkShadowCaster*, vtkShadowGeometry*>> meshes;
  this->TopologyAwareMeshVertices = 0;
  for (const vtkShadowCaster& caster : this->Casters->GetCasters())
  {
    if (!caster.Faces)
    {
      continue;
    }
    MeshLayout layout;
    layout.Drop = this->DropNonSilhouetteFaces;
    layout.PerFace = this->PerFaceAttributes || this->SilhouetteGeometry == EdgeRectangles;
    layout.Half = this->HalfPrecision;
    CasterMesh& mesh = this->Internal->Meshes.Get(
      caster, [&layout](vtkPolyData* data, CasterMesh& built) { BuildMesh(data, layout, built); },
      layout);
    mesh.Geometry->SetPrimitive(this->SilhouetteGeometry == EdgeRectangles
        ? vtkShadowGeometry::Primitive::TrianglePoints
        : (layout.PerFace ? vtkShadowGeometry::Primitive::TriangleInstances
                          : vtkShadowGeometry::Primitive::Triangles));
    meshes.emplace_back(&caster, mesh.Geometry.get());
  }
  this->Internal->Meshes.Prune(*this->Casters);

  vtkShadowGPUTimer::Scope timing(this->TechniqueTimer); // pass 2, on every way out
  auto& bands = this->Internal->Bands;
  bands.resize(lights.size());
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    auto& light = lights[slot];
    // Point lights: the six cube faces share their depth range and texel size.
    const vtkShadowFrustum& frustum = light.Point ? light.Faces[0] : light.Map;
    Internals::Band& band = bands[slot];

    // The penumbra's half-width in texels is K (r - e) / (e r) behind a spot
    // light (K = radius over a texel's size per unit of distance) and K (r -
    // e) behind a directional one (K = tan of the angular radius over a
    // texel's size); the widest is for an edge at the near plane over a
    // receiver at the far one.
    const double k = soft ? light.GetHalfSize() / frustum.GetTexelSize(this->MapSize) : 0.0;
    const double widest = frustum.Parallel ? k * (frustum.Far - frustum.Near)
                                           : k * (1.0 / frustum.Near - 1.0 / frustum.Far);
    band.Range[0] = static_cast<float>(frustum.Near);
    band.Range[1] = static_cast<float>(frustum.Far);
    band.Range[2] = frustum.Parallel ? 1.0f : 0.0f;
    band.Range[3] = static_cast<float>(k);
    band.MaximumPenumbra =
      static_cast<float>(std::min(std::max(widest, 0.5 * this->EdgeWidth), this->MaximumPenumbra));
    // Section 2.1.1: w_s = expected width + two texel diagonals, w_sc = w_s / 2.
    const double expected = this->ExpectedWidth > 0.0
      ? this->ExpectedWidth
      : 2.0 * std::max<double>(soft ? band.MaximumPenumbra : 0.0, 1.0);
    band.HalfWidth = static_cast<float>(0.5 * expected + Diagonal);
    // K (r - e) for a parallel map, whose depth is (r - near) / (far -
    // near); K (1 / e - 1 / r) for a perspective one, whose depth is
    // (1 / near - 1 / r) / (1 / near - 1 / far): either is the depths'
    // difference times a constant.
    const int rows = soft ? this->LookupRows : 1;
    band.LookupScale[0] =
      static_cast<float>(frustum.Parallel ? k * (frustum.Far - frustum.Near)
                                          : k * (1.0 / frustum.Near - 1.0 / frustum.Far));
    band.LookupScale[1] = static_cast<float>(0.5 / band.HalfWidth);
    band.LookupScale[2] = static_cast<float>((rows - 1.0) / (rows * double(band.MaximumPenumbra)));
    band.LookupScale[3] = static_cast<float>(0.5 / rows);

    // The slot's silhouette map, and its lookup, built again when its band changed.
    vtkShadowTextureSpec spec;
    spec.Components = 2;
    spec.Cube = light.Point;
    spec.Linear = true;
    vtkTextureObject* distances = this->Maps->GetTexture(light, 0, spec);
    const std::vector<double> key = { static_cast<double>(this->LookupTexels),
      static_cast<double>(rows), band.HalfWidth, band.MaximumPenumbra, this->EdgeWidth };
    if (!band.Lookup || band.LookupKey != key)
    {
      std::vector<float> lookup = BuildLookup(
        this->LookupTexels, rows, band.HalfWidth, band.MaximumPenumbra, this->EdgeWidth);
      band.Lookup = vtkShadowScreenBuffers::NewFloatTexture(
        context, 4 * this->LookupTexels, rows, 1, lookup.data(), true);
      band.LookupKey = key;
    }

    // Pass 2: the silhouettes of every caster's TAM, the light in each
    // caster's model space; a point light's one cube face at a time.
    vtkShadowDrawSetup setup;
    setup.View = &light.Map;
    if (light.Point)
    {
      setup.View = nullptr;
      setup.Faces = &light.Faces;
    }
    setup.Colours = { distances };
    setup.ClearColour[0] = ClearDistance;
    setup.ClearColour[1] = 1.0f;
    setup.Draw = vtkShadowDrawSetup::Props::None;
    const float halfWidth = band.HalfWidth;
    const float mapSize = static_cast<float>(this->MapSize);
    // Each face's w_sc from the light unless the expected width is given.
    const float widestKept = band.MaximumPenumbra;
    const std::array<float, 4> range = { band.Range[0], band.Range[1], band.Range[2],
      this->ExpectedWidth > 0.0 ? 0.0f : band.Range[3] };
    for (const auto& mesh : meshes)
    {
      const vtkShadowCaster& caster = *mesh.first;
      const glm::vec4 toLight(caster.LightToModel(light.GetHomogeneous()));
      const float lightMC[4] = { toLight.x, toLight.y, toLight.z, toLight.w };
      vtkTextureObject* depthMap = light.Point ? nullptr : light.DepthMap.Get();
      const bool bands = this->SilhouetteGeometry == EdgeRectangles;
      mesh.second->SetShaders(this->Internal->VertexShaders[bands][light.Point],
        this->Internal->FragmentShaders[bands][light.Point], bands ? vtkSilhouetteBandsGS : "");
      setup.Geometry.emplace_back(mesh.second, caster.ModelToWorld,
        [lightMC, halfWidth, mapSize, depthMap, widestKept, range](vtkShaderProgram* program)
        {
          program->SetUniform4f("silhouetteDepthRange", range.data());
          program->SetUniformf("silhouetteWidest", widestKept);
          if (depthMap)
          {
            program->SetUniformi("silhouetteDepths", depthMap->GetTextureUnit());
          }
          program->SetUniform4f("silhouetteLightMC", lightMC);
          program->SetUniformf("silhouetteMapSize", mapSize);
          program->SetUniformf("silhouetteHalfWidth", halfWidth);
        });
    }
    bool drawn = true;
    if (light.Point)
    {
      for (setup.CubeFace = 0; setup.CubeFace < 6 && drawn; ++setup.CubeFace)
      {
        drawn = this->Draw(s, setup);
      }
    }
    else
    {
      // Read raw through a sampler object: pass 1's depths.
      vtkShadowScreenBuffers::Sampler raw(
        this->Screen.get(), light.DepthMap, vtkShadowScreenBuffers::Sampler::Reading::RawDepth);
      drawn = this->Draw(s, setup);
    }
    if (!drawn)
    {
      vtkErrorMacro("The silhouette pass failed (its shaders, or its target): drawing without "
                    "shadows.");
      return false;
    }
  }

  // Uploaded as they were first drawn.
  this->TopologyAwareMeshBytes = 0;
  for (const auto& mesh : meshes)
  {
    this->TopologyAwareMeshBytes += mesh.second->GetUploadedBytes();
    this->TopologyAwareMeshVertices += mesh.second->GetNumberOfVertices();
  }

  return true;
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::ReceiverCode vtkSilhouetteShadowPass::GetReceiverCode()
{
  ReceiverCode code;
  // Both sets of samples, count, reach and turn, and the paper's set's
  // profile narrowing (which the point's own sample keeps) are compiled in:
  // the count bounds their loop, and llvmpipe loads a uniform for every
  // fragment that reads it. 9 significant digits round-trip a float.
  std::ostringstream constants;
  constants << std::scientific << std::setprecision(9);
  const auto declare = [&constants](const char* name, int samples, double spread)
  {
    const double turn = 2.0 * vtkMath::Pi() / std::max(samples - 1, 1);
    constants << "const int " << name << "Samples = " << samples << ";\n"
              << "const float " << name << "Spread = " << spread << ";\n"
              << "const vec2 " << name << "Turn = vec2(" << std::cos(turn) << ", " << std::sin(turn)
              << ");\n";
  };
  declare("silhouette", this->PenumbraSamples, this->SampleSpread);
  declare("silhouetteOverlap", this->OverlapSamples, this->OverlapSpread);
  constants << "const float silhouetteNarrowing = "
            << SampleNarrowing(this->PenumbraSamples, this->SampleSpread) << ";\n";
  code.Declarations = constants.str() + vtkSilhouetteCommon + vtkSilhouetteLookupFS;
  // Each light's signed distances and its lookup texture.
  const auto& lights = this->Maps->GetLights();
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    const std::string i = std::to_string(slot);
    code.Textures.push_back({ "silhouetteDistances" + i,
      lights[slot].Point ? "samplerCube" : "sampler2D", lights[slot].Textures[0] });
    code.Textures.push_back(
      { "silhouetteLookup" + i, "sampler2D", this->Internal->Bands[slot].Lookup });
  }
  code.Visibility = [this](int slot) { return this->GetVisibility(slot); };
  code.Uniforms = [this](vtkShaderProgram* program)
  {
    if (!program->IsUniformUsed("silhouetteMapSize") &&
      !program->IsUniformUsed("silhouetteBand[0]"))
    {
      return;
    }
    const auto& bands = this->Internal->Bands;
    for (size_t slot = 0; slot < bands.size(); ++slot)
    {
      const std::string i = "[" + std::to_string(slot) + "]";
      program->SetUniform4f(("silhouetteDepthRange" + i).c_str(), bands[slot].Range);
      const float band[2] = { bands[slot].HalfWidth, bands[slot].MaximumPenumbra };
      program->SetUniform2f(("silhouetteBand" + i).c_str(), band);
      program->SetUniform4f(("silhouetteLookupScale" + i).c_str(), bands[slot].LookupScale);
    }
    program->SetUniformf("silhouetteMapSize", static_cast<float>(this->MapSize));
    const double texels = this->LookupTexels;
    const float segment[2] = { static_cast<float>((texels - 1.0) / (4.0 * texels)),
      static_cast<float>(0.125 / texels) };
    program->SetUniform2f("silhouetteLookupSegment", segment);
  };
  return code;
}

//------------------------------------------------------------------------------
std::string vtkSilhouetteShadowPass::GetVisibility(int slot) const
{
  const auto& light = this->Maps->GetLights()[slot];
  const std::string i = std::to_string(slot);
  const std::string m = std::to_string(light.MapIndex);
  const std::string soft = this->Variant == Soft ? "true" : "false";
  if (light.Point)
  {
    const std::string center = "vtkShadowCubeCenter[" + m + "]";
    if (this->DebugView)
    {
      return "silhouetteCubeDebug(silhouetteDistances" + i + ", " + center +
        ", vtkShadowPositionWC, " + i + ")";
    }
    return "silhouetteCubeVisibility(vtkShadowCube[" + m + "], silhouetteDistances" + i +
      ", silhouetteLookup" + i + ", " + center + ", vtkShadowPositionWC, vtkShadowNormalWC, " + i +
      ", " + soft + ")";
  }
  const std::string receiver = "vtkShadowPositionVC, vtkShadowNormalVC, " + i;
  if (this->DebugView)
  {
    return "silhouetteDebug(silhouetteDistances" + i + ", " + receiver + ")";
  }
  return "silhouetteVisibility(vtkShadowMap[" + m + "], silhouetteDistances" + i +
    ", silhouetteLookup" + i + ", " + receiver + ", " + soft + ")";
}

//------------------------------------------------------------------------------
void vtkSilhouetteShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internal->Meshes.Clear();
  for (auto& band : this->Internal->Bands)
  {
    if (band.Lookup)
    {
      band.Lookup->ReleaseGraphicsResources(w);
    }
    band.Lookup = nullptr;
    band.LookupKey.clear();
  }
}

//------------------------------------------------------------------------------
void vtkSilhouetteShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Variant: " << (this->Variant == Soft ? "Soft" : "Hard") << "\n";
  os << indent << "ExpectedWidth: " << this->ExpectedWidth << "\n";
  os << indent << "EdgeWidth: " << this->EdgeWidth << "\n";
  os << indent << "MaximumPenumbra: " << this->MaximumPenumbra << "\n";
  os << indent << "PenumbraSamples: " << this->PenumbraSamples << "\n";
  os << indent << "SampleSpread: " << this->SampleSpread << "\n";
  os << indent << "OverlapSamples: " << this->OverlapSamples << "\n";
  os << indent << "OverlapSpread: " << this->OverlapSpread << "\n";
  os << indent << "LookupTexels: " << this->LookupTexels << "\n";
  os << indent << "LookupRows: " << this->LookupRows << "\n";
  os << indent << "SilhouetteGeometry: "
     << (this->SilhouetteGeometry == EdgeRectangles ? "EdgeRectangles" : "IncenterScaling") << "\n";
  os << indent << "PerFaceAttributes: " << this->PerFaceAttributes << "\n";
  os << indent << "HalfPrecision: " << this->HalfPrecision << "\n";
  os << indent << "DropNonSilhouetteFaces: " << this->DropNonSilhouetteFaces << "\n";
  os << indent << "DebugView: " << this->DebugView << "\n";
  os << indent << "TopologyAwareMeshBytes: " << this->TopologyAwareMeshBytes << "\n";
}
