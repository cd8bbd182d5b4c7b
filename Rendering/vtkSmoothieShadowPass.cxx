#include "vtkSmoothieShadowPass.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkEdgeAdjacencyFilter.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkLightSilhouetteFilter.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowDistanceStage.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowGeometry.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkSmoothieEdgesFS.h"
#include "vtkSmoothieEdgesGS.h"
#include "vtkSmoothieEdgesVS.h"
#include "vtkSmoothieLookupFS.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <unordered_map>
#include <vector>

namespace
{
constexpr float Far = VTK_FLOAT_MAX; // nothing drawn: infinitely far

// One light slot's smoothies of one caster: its silhouette edges as lines
// with adjacency, for the light they were found for.
struct SlotEdges
{
  std::array<double, 4> Light{ { 0.0, 0.0, 0.0, -1.0 } }; ///< in model space; w < 0: none yet
  int Search = -1;
  vtkIdType Edges = 0;
  std::shared_ptr<vtkShadowGeometry> Geometry;
};

// What the pass keeps of each caster's polydata.
struct CasterEdges
{
  vtkSmartPointer<vtkLightSilhouetteFilter> Filter; ///< over the merged faces; keeps its tree
  vtkSmartPointer<vtkDataArray> FaceNormals;        ///< per edge: its two faces' normals
  std::vector<SlotEdges> Slots;
};

void BuildEdges(vtkPolyData* data, CasterEdges& edges)
{
  // Faces meet where they share a point id: merge coincident points first
  // (flat-shaded meshes, seams a rounding apart), or every edge there would
  // be a border, always a silhouette.
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(data);
  clean->SetTolerance(1.0e-6); // of the bounding box's diagonal
  clean->ConvertLinesToPointsOff();
  clean->ConvertPolysToLinesOff();
  clean->ConvertStripsToPolysOff();
  clean->Update();
  // Faces only: lines and points have no silhouette.
  auto faces = vtkSmartPointer<vtkPolyData>::New();
  faces->SetPoints(clean->GetOutput()->GetPoints());
  faces->SetPolys(clean->GetOutput()->GetPolys());
  faces->SetStrips(clean->GetOutput()->GetStrips());
  // The face normals of each edge (the silhouette filter's EdgeIds index them).
  vtkNew<vtkEdgeAdjacencyFilter> adjacency;
  adjacency->SetInputData(faces);
  adjacency->Update();
  edges.FaceNormals = adjacency->GetOutput()->GetCellData()->GetArray("FaceNormals");
  edges.Filter = vtkSmartPointer<vtkLightSilhouetteFilter>::New();
  edges.Filter->SetInputData(faces);
}

// The silhouette edges a -> b as lines with adjacency (a, b, c, c): c ends
// the edge that starts at b, where a corner goes. Attribute smoothieNormalMC:
// the edge's face normals summed (figure 2a), at a and b; the next edge's,
// with w = 1, at c.
vtkSmartPointer<vtkPolyData> ChainEdges(vtkPolyData* silhouette, vtkDataArray* faceNormals)
{
  vtkCellArray* lines = silhouette->GetLines();
  vtkDataArray* edgeIds = silhouette->GetCellData()->GetArray("EdgeIds");
  const vtkIdType count = lines->GetNumberOfCells();
  std::vector<std::array<vtkIdType, 2>> ends(count);
  std::unordered_map<vtkIdType, vtkIdType> starting; // point id -> an edge starting there
  starting.reserve(2 * count);
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    vtkIdType e = 0;
    for (lines->InitTraversal(); lines->GetNextCell(n, ids); ++e)
    {
      ends[e] = { { ids[0], ids[1] } };
      starting.emplace(ids[0], e);
    }
  }
  auto normal = [&](vtkIdType e)
  {
    double n[6];
    faceNormals->GetTuple(static_cast<vtkIdType>(edgeIds->GetComponent(e, 0)), n);
    return std::array<float, 3>{ { static_cast<float>(n[0] + n[3]), static_cast<float>(n[1] + n[4]),
      static_cast<float>(n[2] + n[5]) } };
  };

  vtkPoints* in = silhouette->GetPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(4 * count);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("smoothieNormalMC");
  normals->SetNumberOfComponents(4);
  normals->SetNumberOfTuples(4 * count);
  for (vtkIdType e = 0; e < count; ++e)
  {
    const auto next = starting.find(ends[e][1]);
    const bool corner = next != starting.end() && next->second != e;
    const vtkIdType c = corner ? ends[next->second][1] : ends[e][1];
    const std::array<float, 3> own = normal(e);
    const std::array<float, 3> following = corner ? normal(next->second) : own;
    const vtkIdType first = 4 * e;
    points->SetPoint(first, in->GetPoint(ends[e][0]));
    points->SetPoint(first + 1, in->GetPoint(ends[e][1]));
    points->SetPoint(first + 2, in->GetPoint(c));
    points->SetPoint(first + 3, in->GetPoint(c));
    const float a[4] = { own[0], own[1], own[2], 0.0f };
    const float f[4] = { following[0], following[1], following[2], corner ? 1.0f : 0.0f };
    normals->SetTypedTuple(first, a);
    normals->SetTypedTuple(first + 1, a);
    normals->SetTypedTuple(first + 2, f);
    normals->SetTypedTuple(first + 3, f);
  }
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(count + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(4 * count);
  for (vtkIdType e = 0; e <= count; ++e)
  {
    offsets->SetValue(e, 4 * e);
  }
  for (vtkIdType v = 0; v < 4 * count; ++v)
  {
    connectivity->SetValue(v, v);
  }
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  auto chained = vtkSmartPointer<vtkPolyData>::New();
  chained->SetPoints(points);
  chained->SetLines(cells);
  chained->GetPointData()->AddArray(normals);
  return chained;
}

// A pass shader with `prefix` put after its version line.
std::string WithPrefix(const std::string& source, const std::string& prefix)
{
  const std::string tag = "//VTK::System::Dec";
  std::string text = source;
  text.insert(text.find(tag) + tag.size(), "\n" + prefix);
  return text;
}
}

struct vtkSmoothieShadowPass::Internals
{
  vtkShadowCasterCache<CasterEdges> Casters;
  vtkShadowDistanceStage LinearDepth; ///< pass 1 of 2D maps
  std::string FragmentShader = vtkSmoothieEdgesFS;
  std::string CubeFaceFragmentShader = WithPrefix(vtkSmoothieEdgesFS, "#define SMOOTHIE_CUBE_FACE");
  bool PackedReported = false;
};

vtkStandardNewMacro(vtkSmoothieShadowPass);

vtkSmoothieShadowPass::vtkSmoothieShadowPass()
  : Internal(new Internals)
{
  this->Internal->LinearDepth.SetLinearDepth(true);
}
vtkSmoothieShadowPass::~vtkSmoothieShadowPass() = default;

//------------------------------------------------------------------------------
bool vtkSmoothieShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  if (this->PackedCubeMaps)
  {
    if (!this->Internal->PackedReported)
    {
      vtkWarningMacro("PackedCubeMaps: smoothies read float cube maps; using those.");
      this->Internal->PackedReported = true;
    }
    this->PackedCubeMaps = false;
  }
  auto& lights = this->Maps->GetLights();

  // Each caster's silhouette edges for each light, found again only when
  // the light moved in the caster's model space.
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::pair<const vtkShadowCaster*, CasterEdges*>> casters;
  this->NumberOfSilhouetteEdges = 0;
  for (const vtkShadowCaster& caster : this->Casters->GetCasters())
  {
    if (caster.Data->GetNumberOfPolys() + caster.Data->GetNumberOfStrips() == 0)
    {
      continue;
    }
    CasterEdges& edges = this->Internal->Casters.Get(caster, BuildEdges);
    edges.Slots.resize(lights.size());
    for (size_t slot = 0; slot < lights.size(); ++slot)
    {
      const auto& light = lights[slot];
      const glm::dvec3 l = light.Directional ? caster.DirectionToModel(-light.Map.Direction)
                                             : caster.PointToModel(light.Position);
      const std::array<double, 4> key = { { l.x, l.y, l.z, light.Directional ? 0.0 : 1.0 } };
      SlotEdges& entry = edges.Slots[slot];
      if (!entry.Geometry)
      {
        entry.Geometry = std::shared_ptr<vtkShadowGeometry>(new vtkShadowGeometry,
          [](vtkShadowGeometry* geometry)
          {
            geometry->ReleaseGraphicsResources(nullptr);
            delete geometry;
          });
        entry.Geometry->SetPrimitive(vtkShadowGeometry::Primitive::LinesAdjacency);
      }
      if (entry.Light != key || entry.Search != this->SilhouetteSearch)
      {
        edges.Filter->SetLightPosition(key[0], key[1], key[2]);
        edges.Filter->SetPositional(key[3] > 0.0);
        edges.Filter->SetMethod(this->SilhouetteSearch);
        edges.Filter->Update();
        entry.Geometry->SetInput(ChainEdges(edges.Filter->GetOutput(), edges.FaceNormals));
        entry.Edges = edges.Filter->GetOutput()->GetNumberOfLines();
        entry.Light = key;
        entry.Search = this->SilhouetteSearch;
      }
      entry.Geometry->SetModelToWorld(caster.ModelToWorld);
      this->NumberOfSilhouetteEdges += entry.Edges;
    }
    casters.emplace_back(&caster, &edges);
  }
  this->Internal->Casters.Prune(*this->Casters);
  this->SilhouetteTime =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    auto& light = lights[slot];
    if (light.Textures.size() < 2)
    {
      light.Textures.resize(2);
    }
    // 1. The shadow map: linear depths, the nearest kept by MIN blending; a
    // point light's: the framework's squared distances.
    vtkTextureObject* receivers = nullptr;
    if (light.Point)
    {
      this->Maps->AllocateCubeMap(context, light, this->MapSize, false);
      if (!this->RenderDistanceCube(s, light.Faces, light.CubeMap))
      {
        return false;
      }
      receivers = light.CubeMap;
    }
    else
    {
      auto& depths = light.Textures[0];
      if (!depths || depths->GetWidth() != static_cast<unsigned>(this->MapSize))
      {
        depths = vtkShadowScreenBuffers::NewFloatTexture(context, this->MapSize, this->MapSize, 1);
      }
      vtkShadowDrawSetup setup;
      setup.View = &light.Map;
      setup.Colours = { depths };
      std::fill(setup.ClearColour, setup.ClearColour + 4, Far);
      setup.Blend = vtkShadowDrawSetup::Blending::Min;
      setup.DepthTest = false;
      this->Internal->LinearDepth.SetSlopeBias(this->SlopeScaledBias);
      setup.Stage = &this->Internal->LinearDepth;
      if (!this->Draw(s, setup))
      {
        return false;
      }
      receivers = depths;
    }

    // 2. The smoothie buffer: depth and alpha', MIN blended.
    auto& buffer = light.Textures[1];
    const unsigned int target = light.Point ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    if (!buffer || buffer->GetWidth() != static_cast<unsigned>(this->MapSize) ||
      buffer->GetTarget() != target)
    {
      if (light.Point)
      {
        buffer = vtkSmartPointer<vtkTextureObject>::New();
        buffer->SetContext(context);
        buffer->SetWrapS(vtkTextureObject::ClampToEdge);
        buffer->SetWrapT(vtkTextureObject::ClampToEdge);
        buffer->SetWrapR(vtkTextureObject::ClampToEdge);
        buffer->SetMinificationFilter(vtkTextureObject::Nearest);
        buffer->SetMagnificationFilter(vtkTextureObject::Nearest);
        buffer->CreateCubeFromRaw(this->MapSize, this->MapSize, 2, VTK_FLOAT, nullptr);
      }
      else
      {
        buffer = vtkShadowScreenBuffers::NewFloatTexture(context, this->MapSize, this->MapSize, 2);
      }
    }

    // The thickness in screen units (2 across the map): fixed, or K for
    // the outer penumbra's width, R (1/b - 1/r) over a texel's width per unit
    // of distance behind a spot or point light, tan(angular radius) (r - b)
    // over a texel's width behind a directional one.
    const vtkShadowFrustum& frustum = light.Point ? light.Faces[0] : light.Map;
    const double unit = 2.0 / this->MapSize; // a texel in screen units
    const double perTexel =
      (frustum.Parallel ? frustum.Footprint.x : frustum.Footprint.y) / this->MapSize;
    const double size = light.Directional ? std::tan(glm::radians(light.Radius)) : light.Radius;
    const float thickness[4] = { static_cast<float>(this->Thickness * unit),
      static_cast<float>(this->PenumbraScale * size / perTexel * unit),
      frustum.Parallel ? 1.0f : 0.0f, static_cast<float>(this->MaximumThickness * unit) };
    const float mapSize = static_cast<float>(this->MapSize);
    const int falloff = this->Falloff;

    vtkShadowDrawSetup setup;
    setup.Colours = { buffer };
    setup.ClearColour[0] = Far;
    setup.ClearColour[1] = 1.0f;
    setup.Blend = vtkShadowDrawSetup::Blending::Min;
    setup.DepthTest = false;
    setup.Draw = vtkShadowDrawSetup::Props::None;
    for (const auto& caster : casters)
    {
      SlotEdges& entry = caster.second->Slots[slot];
      entry.Geometry->SetShaders(vtkSmoothieEdgesVS,
        light.Point ? this->Internal->CubeFaceFragmentShader : this->Internal->FragmentShader,
        vtkSmoothieEdgesGS);
      setup.Geometry.push_back(entry.Geometry.get());
    }
    // Each frustum's own uniforms: a point light's six faces in turn.
    auto draw = [&](const vtkShadowFrustum& view)
    {
      const glm::mat4 clipToWorld(glm::inverse(view.Projection * view.View));
      const glm::vec3 eye(view.Eye);
      const glm::vec3 axis(view.Direction);
      const float far = static_cast<float>(view.Far);
      const int unitIndex = receivers->GetTextureUnit();
      for (vtkShadowGeometry* geometry : setup.Geometry)
      {
        geometry->SetUniforms(
          [=](vtkShaderProgram* program)
          {
            program->SetUniformMatrix4x4(
              "smoothieClipToWorld", const_cast<float*>(glm::value_ptr(clipToWorld)));
            program->SetUniform3f("smoothieEye", glm::value_ptr(eye));
            program->SetUniform3f("smoothieAxis", glm::value_ptr(axis));
            program->SetUniform4f("smoothieThickness", thickness);
            program->SetUniformf("smoothieFar", far);
            program->SetUniformf("smoothieMapSize", mapSize);
            program->SetUniformi("smoothieReceivers", unitIndex);
            program->SetUniformi("smoothieFalloff", falloff);
          });
      }
      return this->Draw(s, setup);
    };
    receivers->Activate();
    bool drawn = true;
    if (light.Point)
    {
      setup.Faces = &light.Faces;
      for (setup.CubeFace = 0; setup.CubeFace < 6 && drawn; ++setup.CubeFace)
      {
        drawn = draw(light.Faces[setup.CubeFace]);
      }
    }
    else
    {
      setup.View = &light.Map;
      drawn = draw(light.Map);
    }
    receivers->Deactivate();
    if (!drawn)
    {
      vtkErrorMacro("The smoothie pass failed (its shaders, or its target): drawing without "
                    "shadows.");
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<vtkSoftShadowPass::ReceiverTexture> vtkSmoothieShadowPass::GetReceiverTextures()
{
  std::vector<ReceiverTexture> textures;
  const auto& lights = this->Maps->GetLights();
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    const std::string i = std::to_string(slot);
    if (lights[slot].Point)
    {
      textures.push_back({ "smoothieBuffer" + i, "samplerCube", lights[slot].Textures[1] });
      continue;
    }
    textures.push_back({ "smoothieDepths" + i, "sampler2D", lights[slot].Textures[0] });
    textures.push_back({ "smoothieBuffer" + i, "sampler2D", lights[slot].Textures[1] });
  }
  return textures;
}

//------------------------------------------------------------------------------
std::string vtkSmoothieShadowPass::GetVisibilityDeclarations()
{
  return vtkSmoothieLookupFS;
}

//------------------------------------------------------------------------------
std::string vtkSmoothieShadowPass::GetVisibilityExpression(int slot)
{
  const auto& light = this->Maps->GetLights()[slot];
  const std::string i = std::to_string(slot);
  const std::string m = std::to_string(light.MapIndex);
  if (light.Point)
  {
    return "smoothieCubeVisibility(vtkShadowCube[" + m + "], smoothieBuffer" + i +
      ", vtkShadowCubeCenter[" + m + "], vtkShadowPositionWC, vtkShadowNormalWC)";
  }
  return "smoothieVisibility(smoothieDepths" + i + ", smoothieBuffer" + i +
    ", vtkShadowWorldToMap[" + i + "], vtkShadowReceiver(" + i +
    ", vtkShadowPositionWC, vtkShadowNormalWC), vtkShadowEye[" + i + "], vtkShadowAxis[" + i + "])";
}

//------------------------------------------------------------------------------
void vtkSmoothieShadowPass::SetVisibilityUniforms(vtkShaderProgram* program)
{
  if (program->IsUniformUsed("smoothieMapSize"))
  {
    program->SetUniformf("smoothieMapSize", static_cast<float>(this->MapSize));
  }
}

//------------------------------------------------------------------------------
void vtkSmoothieShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internal->Casters.Clear();
}

//------------------------------------------------------------------------------
void vtkSmoothieShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Thickness: " << this->Thickness << "\n";
  os << indent << "PenumbraScale: " << this->PenumbraScale << "\n";
  os << indent << "Falloff: " << (this->Falloff == Linear ? "Linear" : "SquareRoot") << "\n";
  os << indent << "MaximumThickness: " << this->MaximumThickness << "\n";
  os << indent << "SilhouetteSearch: "
     << (this->SilhouetteSearch == vtkLightSilhouetteFilter::BRUTE_FORCE ? "BruteForce"
                                                                         : "NormalConeTree")
     << "\n";
  os << indent << "NumberOfSilhouetteEdges: " << this->NumberOfSilhouetteEdges << "\n";
  os << indent << "SilhouetteTime: " << this->SilhouetteTime << "\n";
}
