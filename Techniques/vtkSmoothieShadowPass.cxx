// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSmoothieShadowPass.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
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
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"

#include "vtkSmoothieEdgesFS.h"
#include "vtkSmoothieEdgesGS.h"
#include "vtkSmoothieEdgesVS.h"
#include "vtkSmoothieLookupFS.h"
#include "vtkSmoothieQuadsVS.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <deque>
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
  std::shared_ptr<vtkShadowGeometry> Geometry; ///< the edges, for the geometry shader
  vtkSmartPointer<vtkPolyData> Chained;        ///< Geometry's input
  // Built on the CPU: per frustum (a point light's six faces), the smoothie
  // triangles and the model-to-clip matrix they were built for.
  std::array<std::shared_ptr<vtkShadowGeometry>, 6> Quads;
  std::array<glm::dmat4, 6> QuadsFor;
  std::array<vtkPolyData*, 6> QuadsFrom{}; ///< the Chained they came from
};

// What the pass keeps of each caster's polydata: its faces' silhouette
// search, and per placement (the actors drawing the polydata, in the
// registry's order: each sees the lights from its own side) per light slot
// its silhouette edges.
struct CasterEdges
{
  vtkSmartPointer<vtkLightSilhouetteFilter> Filter; ///< over the merged faces; keeps its tree
  vtkSmartPointer<vtkDataArray> FaceNormals;        ///< per edge: its two faces' normals
  std::deque<std::vector<SlotEdges>> Placements;    ///< a deque: taken ones stay put
  unsigned long Frame = 0;                          ///< the frame that last took a placement
  size_t Taken = 0;                                 ///< placements taken in that frame

  /// The next placement's slots this frame; those of actors gone are dropped.
  std::vector<SlotEdges>& TakePlacement(unsigned long frame)
  {
    if (this->Frame != frame)
    {
      this->Placements.resize(this->Taken);
      this->Frame = frame;
      this->Taken = 0;
    }
    if (this->Taken == this->Placements.size())
    {
      this->Placements.emplace_back();
    }
    return this->Placements[this->Taken++];
  }
};

void BuildEdges(vtkPolyData* data, CasterEdges& edges)
{
  vtkSmartPointer<vtkPolyData> faces = vtkShadowCasterRegistry::MergedFaces(data);
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

// What the thickness depends on (vtkSmoothieEdgesGS.glsl's uniforms).
struct Sizing
{
  glm::dvec3 Eye{ 0.0 }, Axis{ 0.0, 0.0, -1.0 };
  glm::dvec4 Values{ 0.0 }; ///< fixed, K, parallel, widest
  double Far = 1.0;
};

// vtkSmoothieEdgesGS.glsl's construction on the CPU, for one frustum: the
// same smoothie edges and corners, as triangles whose vertices carry their
// silhouette vertex (model space) and their screen offset
// (vtkSmoothieQuadsVS.glsl).
class QuadBuilder
{
public:
  QuadBuilder(const glm::dmat4& modelToClip, const glm::dmat4& modelToWorld, const Sizing& sizing)
    : ModelToClip(modelToClip)
    , ModelToWorld(modelToWorld)
    , Size(sizing)
  {
  }

  vtkSmartPointer<vtkPolyData> Build(vtkPolyData* chained)
  {
    vtkPoints* points = chained->GetPoints();
    vtkDataArray* normals = chained->GetPointData()->GetArray("smoothieNormalMC");
    const vtkIdType edges = chained->GetNumberOfLines();
    for (vtkIdType e = 0; e < edges; ++e)
    {
      double p[3][3], n[3][4];
      for (int k = 0; k < 3; ++k)
      {
        points->GetPoint(4 * e + k, p[k]);
        normals->GetTuple(4 * e + k, n[k]);
      }
      this->Edge(glm::dvec3(p[0][0], p[0][1], p[0][2]), glm::dvec3(p[1][0], p[1][1], p[1][2]),
        glm::dvec3(p[2][0], p[2][1], p[2][2]), glm::dvec3(n[0][0], n[0][1], n[0][2]),
        glm::dvec3(n[2][0], n[2][1], n[2][2]), n[2][3] > 0.5);
    }
    const vtkIdType count = static_cast<vtkIdType>(this->Widths.size());
    auto array = [count](const char* name, int components, const std::vector<float>& values)
    {
      vtkNew<vtkFloatArray> a;
      a->SetName(name);
      a->SetNumberOfComponents(components);
      a->SetNumberOfTuples(count);
      std::copy(values.begin(), values.end(), a->GetPointer(0));
      return vtkSmartPointer<vtkFloatArray>(a);
    };
    vtkNew<vtkPoints> corners;
    corners->SetData(array("", 3, this->Positions));
    vtkNew<vtkIdTypeArray> offsets;
    offsets->SetNumberOfValues(count / 3 + 1);
    for (vtkIdType t = 0; t <= count / 3; ++t)
    {
      offsets->SetValue(t, 3 * t);
    }
    vtkNew<vtkIdTypeArray> connectivity;
    connectivity->SetNumberOfValues(count);
    for (vtkIdType v = 0; v < count; ++v)
    {
      connectivity->SetValue(v, v);
    }
    vtkNew<vtkCellArray> triangles;
    triangles->SetData(offsets, connectivity);
    auto quads = vtkSmartPointer<vtkPolyData>::New();
    quads->SetPoints(corners);
    quads->SetPolys(triangles);
    quads->GetPointData()->AddArray(array("smoothieOffsetIn", 2, this->Offsets));
    quads->GetPointData()->AddArray(array("smoothieShapeIn", 4, this->Shapes));
    quads->GetPointData()->AddArray(array("smoothieWidthIn", 1, this->Widths));
    return quads;
  }

private:
  glm::dvec4 Clip(const glm::dvec3& p) const { return this->ModelToClip * glm::dvec4(p, 1.0); }
  static glm::dvec2 Screen(const glm::dvec4& c) { return glm::dvec2(c) / c.w; }

  double ThicknessAt(const glm::dvec3& p) const
  {
    if (this->Size.Values.x > 0.0)
    {
      return this->Size.Values.x;
    }
    const glm::dvec3 world(this->ModelToWorld * glm::dvec4(p, 1.0));
    const double b = std::max(glm::dot(world - this->Size.Eye, this->Size.Axis), 1.0e-6);
    const double t = this->Size.Values.z > 0.0
      ? this->Size.Values.y * std::max(this->Size.Far - b, 0.0)
      : this->Size.Values.y / b;
    return std::min(t, this->Size.Values.w);
  }

  glm::dvec2 Extrusion(const glm::dvec3& p, const glm::dvec3& q, const glm::dvec3& n,
    const glm::dvec4& cp, const glm::dvec4& cq) const
  {
    const glm::dvec2 e = Screen(cq) - Screen(cp);
    glm::dvec2 d = glm::normalize(glm::dvec2(e.y, -e.x));
    const glm::dvec4 m = this->Clip(0.5 * (p + q));
    const glm::dvec4 dn = this->ModelToClip * glm::dvec4(n, 0.0);
    const glm::dvec2 ns = glm::dvec2(dn) * m.w - glm::dvec2(m) * dn.w;
    const double agree = glm::dot(d, ns);
    const double length = glm::length(ns);
    if (length > 0.0 && std::abs(agree) > 1.0e-3 * length)
    {
      d *= agree > 0.0 ? 1.0 : -1.0;
    }
    return d;
  }

  void Vertex(const glm::dvec3& p, const glm::dvec2& offset, const glm::dvec4& shape, double width)
  {
    this->Positions.insert(this->Positions.end(),
      { static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z) });
    this->Offsets.insert(
      this->Offsets.end(), { static_cast<float>(offset.x), static_cast<float>(offset.y) });
    this->Shapes.insert(this->Shapes.end(),
      { static_cast<float>(shape.x), static_cast<float>(shape.y), static_cast<float>(shape.z),
        static_cast<float>(shape.w) });
    this->Widths.push_back(static_cast<float>(width));
  }

  // Two triangles: a, b, a + u, and b, a + u, b + v (a strip's order).
  void Quad(const glm::dvec3& a, const glm::dvec2& u0, const glm::dvec2& u1, const glm::dvec3& b,
    const glm::dvec2& v0, const glm::dvec2& v1, const glm::dvec4& shape, double ta, double tb)
  {
    this->Vertex(a, u0, shape, ta);
    this->Vertex(b, v0, shape, tb);
    this->Vertex(a, u1, shape, ta);
    this->Vertex(b, v0, shape, tb);
    this->Vertex(a, u1, shape, ta);
    this->Vertex(b, v1, shape, tb);
  }

  void Corner(
    const glm::dvec3& b, const glm::dvec4& cb, const glm::dvec2& u, const glm::dvec2& v, double t)
  {
    const glm::dvec2 miter = (u + v) / std::max(1.0 + glm::dot(u, v), 1.0e-3);
    const glm::dvec4 shape(Screen(cb), 0.0, 1.0);
    this->Quad(b, glm::dvec2(0.0), t * u, b, t * v, t * miter, shape, t, t);
  }

  void Edge(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& nab,
    const glm::dvec3& nbc, bool corner)
  {
    const glm::dvec4 ca = this->Clip(a), cb = this->Clip(b), cc = this->Clip(c);
    if (ca.w <= 1.0e-6 || cb.w <= 1.0e-6)
    {
      return;
    }
    const glm::dvec2 sa = Screen(ca), sb = Screen(cb);
    if (glm::distance(sa, sb) < 1.0e-7)
    {
      return;
    }
    const double ta = this->ThicknessAt(a), tb = this->ThicknessAt(b);
    const glm::dvec2 d1 = this->Extrusion(a, b, nab, ca, cb);
    const glm::dvec4 line(d1, glm::dot(d1, sa), 0.0);
    this->Quad(a, glm::dvec2(0.0), ta * d1, b, glm::dvec2(0.0), tb * d1, line, ta, tb);
    if (!corner || cc.w <= 1.0e-6)
    {
      return;
    }
    const glm::dvec2 sc = Screen(cc);
    if (glm::distance(sb, sc) < 1.0e-7)
    {
      return;
    }
    const glm::dvec2 d2 = this->Extrusion(b, c, nbc, cb, cc);
    const glm::dvec2 e1 = glm::normalize(sb - sa), e2 = glm::normalize(sc - sb);
    if (glm::dot(e2, d1) >= 0.0 && glm::dot(-e1, d2) >= 0.0)
    {
      return;
    }
    if (glm::dot(d1, d2) >= -0.5)
    {
      this->Corner(b, cb, d1, d2, tb);
      return;
    }
    const glm::dvec2 bisector = d1 + d2;
    const glm::dvec2 m = glm::dot(bisector, bisector) > 1.0e-6 ? glm::normalize(bisector) : e1;
    this->Corner(b, cb, d1, m, tb);
    this->Corner(b, cb, m, d2, tb);
  }

  glm::dmat4 ModelToClip, ModelToWorld;
  Sizing Size;
  std::vector<float> Positions, Offsets, Shapes, Widths;
};

}

struct vtkSmoothieShadowPass::Internals
{
  vtkShadowCasterCache<CasterEdges> Casters;
  vtkShadowDistanceStage LinearDepth; ///< pass 1 of 2D maps
  std::string FragmentShader = vtkSmoothieEdgesFS;
  std::string CubeFaceFragmentShader =
    vtkShadowGeometry::WithPrefix(vtkSmoothieEdgesFS, "#define SMOOTHIE_CUBE_FACE");
  std::string GeometryShader = vtkSmoothieEdgesGS;
  std::string CubeFaceGeometryShader =
    vtkShadowGeometry::WithPrefix(vtkSmoothieEdgesGS, "#define SMOOTHIE_CUBE_FACE");
  unsigned long Frame = 0; ///< frames drawn, for CasterEdges::TakePlacement()
};

vtkStandardNewMacro(vtkSmoothieShadowPass);

vtkSmoothieShadowPass::vtkSmoothieShadowPass()
  : Internal(new Internals)
{
  this->Internal->LinearDepth.SetLinearDepth(true);
}
vtkSmoothieShadowPass::~vtkSmoothieShadowPass() = default;

//------------------------------------------------------------------------------
vtkSoftShadowPass::Traits vtkSmoothieShadowPass::GetTraits() const
{
  Traits traits;
  traits.PointLights = true;
  traits.CasterGeometry = true; // silhouette edges
  // Receivers read four texels of two channels in three fetches
  // (textureGather with a component), and float cube maps.
  traits.FloatCubeMaps = true;
  traits.ReceiverExtensions = { "GL_ARB_texture_gather", "GL_ARB_gpu_shader5" };
  traits.ReceiverTexturesPerLight = 1; // the smoothie buffer
  traits.UncombinedLightSpaceData = "smoothie depth and alpha buffers";
  return traits;
}

//------------------------------------------------------------------------------
bool vtkSmoothieShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  auto& lights = this->Maps->GetLights();

  // Each caster's silhouette edges for each light, found again only when
  // the light moved in the caster's model space. What is not drawn as
  // filled faces (lines, points, wireframe, imposters) casts its depth-map
  // shadow only.
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::pair<const vtkShadowCaster*, std::vector<SlotEdges>*>> casters;
  this->NumberOfSilhouetteEdges = 0;
  const unsigned long frame = ++this->Internal->Frame;
  for (const vtkShadowCaster& caster : this->Casters->GetCasters())
  {
    if (!caster.Faces)
    {
      continue;
    }
    CasterEdges& edges = this->Internal->Casters.Get(caster, BuildEdges);
    std::vector<SlotEdges>& slots = edges.TakePlacement(frame);
    slots.resize(lights.size());
    for (size_t slot = 0; slot < lights.size(); ++slot)
    {
      const auto& light = lights[slot];
      const glm::dvec4 l = caster.LightToModel(light.GetHomogeneous());
      const std::array<double, 4> key = { { l.x, l.y, l.z, l.w } };
      SlotEdges& entry = slots[slot];
      if (!entry.Geometry)
      {
        entry.Geometry = vtkShadowGeometry::NewShared();
        entry.Geometry->SetPrimitive(vtkShadowGeometry::Primitive::LinesAdjacency);
      }
      if (entry.Light != key || entry.Search != this->SilhouetteSearch)
      {
        edges.Filter->SetLightPosition(key[0], key[1], key[2]);
        edges.Filter->SetPositional(key[3] > 0.0);
        edges.Filter->SetMethod(this->SilhouetteSearch);
        edges.Filter->Update();
        entry.Chained = ChainEdges(edges.Filter->GetOutput(), edges.FaceNormals);
        entry.Geometry->SetInput(entry.Chained);
        entry.Edges = edges.Filter->GetOutput()->GetNumberOfLines();
        entry.Light = key;
        entry.Search = this->SilhouetteSearch;
      }
      entry.Geometry->SetModelToWorld(caster.ModelToWorld);
      this->NumberOfSilhouetteEdges += entry.Edges;
    }
    casters.emplace_back(&caster, &slots);
  }
  this->Internal->Casters.Prune(*this->Casters);
  double cpu =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    auto& light = lights[slot];
    // 1. The shadow map: linear depths, the nearest kept by MIN blending; a
    // point light's: the framework's squared distances.
    vtkTextureObject* receivers = nullptr;
    if (light.Point)
    {
      this->Maps->AllocateCubeMap(light, false);
      if (!this->RenderDistanceCube(s, light.Faces, light.CubeMap))
      {
        return false;
      }
      receivers = light.CubeMap;
    }
    else
    {
      receivers = this->Maps->GetTexture(light, 0, vtkShadowTextureSpec());
      vtkShadowDrawSetup setup;
      setup.View = &light.Map;
      setup.Colours = { receivers };
      std::fill(setup.ClearColour, setup.ClearColour + 4, Far);
      setup.Blend = vtkShadowDrawSetup::Blending::Min;
      setup.DepthTest = false;
      this->Internal->LinearDepth.SetSlopeBias(this->SlopeScaledBias);
      setup.Stage = &this->Internal->LinearDepth;
      if (!this->Draw(s, setup))
      {
        return false;
      }
    }

    // 2. The smoothie buffer: depth and alpha', MIN blended.
    vtkShadowTextureSpec bufferSpec;
    bufferSpec.Components = 2;
    bufferSpec.Cube = light.Point;
    vtkTextureObject* buffer = this->Maps->GetTexture(light, 1, bufferSpec);

    // The thickness in screen units (2 across the map): fixed, or K for
    // the outer penumbra's width, R (1/b - 1/r) over a texel's width per unit
    // of distance behind a spot or point light, tan(angular radius) (r - b)
    // over a texel's width behind a directional one.
    const vtkShadowFrustum& frustum = light.Point ? light.Faces[0] : light.Map;
    const double unit = 2.0 / this->MapSize; // a texel in screen units
    const float thickness[4] = { static_cast<float>(this->Thickness * unit),
      static_cast<float>(
        this->PenumbraScale * light.GetHalfSize() / frustum.GetTexelSize(this->MapSize) * unit),
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
    // Each frustum (a point light's six faces in turn): its uniforms, and
    // on the CPU its smoothie triangles, built again when the caster's
    // edges or its model-to-clip matrix changed.
    const Sizing sizing{ frustum.Eye, frustum.Direction,
      glm::dvec4(thickness[0], thickness[1], thickness[2], thickness[3]), frustum.Far };
    auto draw = [&](const vtkShadowFrustum& view, int face)
    {
      const glm::dmat4 worldToClip = view.Projection * view.View;
      const glm::mat4 clipToWorld(glm::inverse(worldToClip));
      const glm::vec3 eye(view.Eye);
      const glm::vec3 axis(view.Direction);
      const float far = static_cast<float>(view.Far);
      const int unitIndex = receivers->GetTextureUnit();
      const std::string& fragment =
        light.Point ? this->Internal->CubeFaceFragmentShader : this->Internal->FragmentShader;
      setup.Geometry.clear();
      for (const auto& caster : casters)
      {
        SlotEdges& entry = (*caster.second)[slot];
        vtkShadowGeometry* geometry = entry.Geometry.get();
        if (this->BuildOnGPU)
        {
          geometry->SetShaders(vtkSmoothieEdgesVS, fragment,
            light.Point ? this->Internal->CubeFaceGeometryShader : this->Internal->GeometryShader);
        }
        else
        {
          auto& quads = entry.Quads[face];
          const glm::dmat4 modelToClip = worldToClip * caster.first->ModelToWorld;
          if (!quads || entry.QuadsFor[face] != modelToClip ||
            entry.QuadsFrom[face] != entry.Chained)
          {
            const auto built = std::chrono::steady_clock::now();
            quads = quads ? quads : vtkShadowGeometry::NewShared();
            QuadBuilder builder(modelToClip, caster.first->ModelToWorld, sizing);
            quads->SetInput(builder.Build(entry.Chained));
            entry.QuadsFor[face] = modelToClip;
            entry.QuadsFrom[face] = entry.Chained;
            cpu +=
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - built)
                .count();
          }
          quads->SetModelToWorld(caster.first->ModelToWorld);
          quads->SetShaders(vtkSmoothieQuadsVS, fragment);
          geometry = quads.get();
        }
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
        setup.Geometry.push_back(geometry);
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
        drawn = draw(light.Faces[setup.CubeFace], setup.CubeFace);
      }
    }
    else
    {
      setup.View = &light.Map;
      drawn = draw(light.Map, 0);
    }
    receivers->Deactivate();
    if (!drawn)
    {
      vtkErrorMacro("The smoothie pass failed (its shaders, or its target): drawing without "
                    "shadows.");
      return false;
    }
  }
  this->TechniqueCPUTime = cpu;
  return true;
}

//------------------------------------------------------------------------------
void vtkSmoothieShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Internal->Casters.Clear();
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::ReceiverCode vtkSmoothieShadowPass::GetReceiverCode()
{
  ReceiverCode code;
  code.Declarations = vtkSmoothieLookupFS;
  const auto& lights = this->Maps->GetLights();
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    const std::string i = std::to_string(slot);
    if (lights[slot].Point)
    {
      code.Textures.push_back({ "smoothieBuffer" + i, "samplerCube", lights[slot].Textures[1] });
      continue;
    }
    code.Textures.push_back({ "smoothieDepths" + i, "sampler2D", lights[slot].Textures[0] });
    code.Textures.push_back({ "smoothieBuffer" + i, "sampler2D", lights[slot].Textures[1] });
  }
  code.Visibility = [this](int slot)
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
      ", vtkShadowPositionWC, vtkShadowNormalWC), vtkShadowEye[" + i + "], vtkShadowAxis[" + i +
      "])";
  };
  code.Uniforms = [this](vtkShaderProgram* program)
  {
    if (program->IsUniformUsed("smoothieMapSize"))
    {
      program->SetUniformf("smoothieMapSize", static_cast<float>(this->MapSize));
    }
  };
  return code;
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
  os << indent << "BuildOnGPU: " << this->BuildOnGPU << "\n";
  os << indent << "NumberOfSilhouetteEdges: " << this->NumberOfSilhouetteEdges << "\n";
}
