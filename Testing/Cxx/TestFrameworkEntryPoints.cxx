// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// The framework's entry points for techniques that draw their own geometry,
// each used by a test-only technique and checked by number:
// - technique-owned geometry (a 9-component attribute split into vec3s)
//   drawn MIN-blended into a light-space colour target, per light;
// - those per-light textures bound in the receivers and read back there;
// - a compute pass (image store, SSBO atomics) writing a visibility texture
//   the receivers read;
// - the casters: each actor's polydata, a composite mapper's visible
//   blocks, and an assembly's part;
// - a per-caster cache that rebuilds when a polydata is modified, and not
//   otherwise, and forgets casters that left the scene;
// - lights in a transformed actor's model space, the actor a part of a
//   transformed assembly (silhouettes match those of the transformed mesh
//   under the world light);
// - a mapper whose shader lacks the lines the shadow term edits gets one
//   warning naming it.
#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCubeSource.h"
#include "vtkDoubleArray.h"
#include "vtkHardShadowPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightSilhouetteFilter.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOutputWindow.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShaderProperty.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowCompute.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowGeometry.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkShadowShaderHooks.h"
#include "vtkShadowVTKVersion.h"
#include "vtkSoftShadowPass.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkUnsignedCharArray.h"

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace
{
int Failures = 0;
void Check(bool ok, const std::string& what)
{
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what.c_str());
  Failures += ok ? 0 : 1;
}

// Two bands in a light's clip space, x in [-1, 0.2] and [-0.2, 1], y in
// [-0.5, 0.5], drawn in that order, whose values come from the middle vec3
// of a 9-component point array (the attribute `triple1`).
vtkSmartPointer<vtkPolyData> Bands(double left, double right)
{
  auto bands = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkDoubleArray> triple;
  triple->SetName("triple");
  triple->SetNumberOfComponents(9);
  auto band = [&](double x0, double x1, double value)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    for (double y : { -0.5, 0.5 })
    {
      for (double x : { x0, x1 })
      {
        points->InsertNextPoint(x, y, 0.0);
        const double t[9] = { -1, -1, -1, 0.0, value, 0.0, -1, -1, -1 };
        triple->InsertNextTuple(t);
      }
    }
    const vtkIdType a[3] = { first, first + 1, first + 3 };
    const vtkIdType b[3] = { first, first + 3, first + 2 };
    polys->InsertNextCell(3, a);
    polys->InsertNextCell(3, b);
  };
  band(-1.0, 0.2, left);
  band(-0.2, 1.0, right);
  bands->SetPoints(points);
  bands->SetPolys(polys);
  bands->GetPointData()->AddArray(triple);
  return bands;
}

const char* const BandVS = R"(//VTK::System::Dec
in vec3 vtkShadowVertexMC;
in vec3 triple1;
uniform mat4 vtkShadowModelToClip;
out float bandValue;
void main()
{
  gl_Position = vtkShadowModelToClip * vec4(vtkShadowVertexMC, 1.0);
  bandValue = triple1.y;
}
)";

const char* const BandFS = R"(//VTK::System::Dec
//VTK::Output::Dec
in float bandValue;
void main()
{
  gl_FragData[0] = vec4(bandValue);
}
)";

// Visibility 1 on the left half of the viewport, 0.25 on the right; every
// invocation counted with an atomic add.
const char* const PatternCS = R"(#version 430
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f, binding = 0) uniform writeonly image2D visibility;
layout(std430, binding = 0) buffer Counter { uint invocations; };
uniform ivec2 size;
void main()
{
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= size.x || p.y >= size.y)
  {
    return;
  }
  imageStore(visibility, p, vec4(p.x < size.x / 2 ? 1.0 : 0.25));
  atomicAdd(invocations, 1u);
}
)";
}

// The test-only technique.
class vtkFrameworkProbePass : public vtkSoftShadowPass
{
public:
  static vtkFrameworkProbePass* New();
  vtkTypeMacro(vtkFrameworkProbePass, vtkSoftShadowPass);

  bool UseCompute = false;
  // Results of the last frame.
  std::vector<std::vector<float>> LightTexels; ///< per light, the MIN-blended target
  unsigned int Invocations = 0;
  std::map<vtkActor*, vtkIdType> Silhouettes; ///< per caster, with the model-space light
  std::vector<std::pair<vtkProp*, unsigned int>> CastersSeen; ///< prop and block of each caster
  struct Derived
  {
    vtkSmartPointer<vtkLightSilhouetteFilter> Filter;
  };
  vtkShadowCasterCache<Derived> Cache;

  static constexpr int TargetSize = 64;

protected:
  bool RenderShadowMaps(const vtkRenderState* s) override
  {
    if (!this->RenderLightDepthMaps(s, true))
    {
      return false;
    }
    auto* context = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
    auto& lights = this->Maps->GetLights();

    // Per caster: silhouettes of light 0 in the caster's model space, from
    // a filter built once per polydata.
    this->Silhouettes.clear();
    this->CastersSeen.clear();
    for (const vtkShadowCaster& caster : this->Casters->GetCasters())
    {
      this->CastersSeen.emplace_back(caster.Prop, caster.FlatIndex);
      Derived& derived = this->Cache.Get(caster,
        [](vtkPolyData* data, Derived& value)
        {
          value.Filter = vtkSmartPointer<vtkLightSilhouetteFilter>::New();
          value.Filter->SetInputData(data);
        });
      const glm::dvec3 light = caster.PointToModel(lights[0].Position);
      derived.Filter->SetLightPosition(light.x, light.y, light.z);
      derived.Filter->Update();
      this->Silhouettes[caster.Actor] = derived.Filter->GetNumberOfSilhouetteEdges();
    }
    this->Cache.Prune(*this->Casters);

    if (this->UseCompute)
    {
      return this->RenderCompute(s, context);
    }

    // Per light: the bands drawn MIN-blended through the light's frustum
    // into a texture of the light's own.
    this->LightTexels.assign(lights.size(), {});
    for (size_t slot = 0; slot < lights.size(); ++slot)
    {
      auto& light = lights[slot];
      vtkShadowTextureSpec spec;
      spec.Size = TargetSize;
      vtkTextureObject* target = this->Maps->GetTexture(light, 0, spec);
      if (this->Geometry.size() <= slot)
      {
        this->Geometry.emplace_back(new vtkShadowGeometry);
        const double scale = slot == 0 ? 1.0 : 0.7;
        this->Geometry[slot]->SetInput(Bands(0.3 * scale, 0.6 * scale));
        this->Geometry[slot]->SetShaders(BandVS, BandFS);
      }
      // Bands given in the light's clip space: model = clip.
      this->Geometry[slot]->SetModelToWorld(glm::inverse(light.Map.Projection * light.Map.View));

      vtkShadowDrawSetup setup;
      setup.View = &light.Map;
      setup.Colours = { target };
      std::fill(setup.ClearColour, setup.ClearColour + 4, 1.0f);
      setup.Blend = vtkShadowDrawSetup::Blending::Min;
      setup.DepthTest = false;
      setup.Draw = vtkShadowDrawSetup::Props::None;
      setup.Geometry = { this->Geometry[slot].get() };
      if (!this->Draw(s, setup))
      {
        return false;
      }
      std::vector<float>& texels = this->LightTexels[slot];
      texels.resize(TargetSize * TargetSize);
      target->Bind();
      glGetTexImage(GL_TEXTURE_2D, 0, GL_RED, GL_FLOAT, texels.data());
      target->Deactivate();
    }
    return true;
  }

  // The framework checked compute first: the traits ask for it.
  Traits GetTraits() const override
  {
    Traits traits;
    traits.Compute = this->UseCompute;
    return traits;
  }

  bool RenderCompute(const vtkRenderState* s, vtkOpenGLRenderWindow* context)
  {
    s->GetRenderer()->GetTiledSizeAndOrigin(
      &this->Size[0], &this->Size[1], &this->Origin[0], &this->Origin[1]);
    if (!this->ScreenVisibility)
    {
      this->ScreenVisibility =
        vtkShadowScreenBuffers::NewFloatTexture(context, this->Size[0], this->Size[1], 1);
    }
    this->ScreenVisibility->Resize(this->Size[0], this->Size[1]);
    if (!this->Pattern.IsBuilt())
    {
      std::string log;
      if (!this->Pattern.Build(PatternCS, &log))
      {
        vtkErrorMacro("Compute shader: " << log);
        return false;
      }
      this->Counter.Allocate(sizeof(unsigned int));
    }
    this->Counter.Clear(0);
    this->Pattern.Use(context);
    this->Pattern.SetUniform2i("size", this->Size[0], this->Size[1]);
    vtkShadowCompute::BindImage(0, this->ScreenVisibility, GL_WRITE_ONLY, GL_R32F);
    this->Counter.BindStorage(0);
    this->Pattern.Dispatch((this->Size[0] + 7) / 8, (this->Size[1] + 7) / 8);
    vtkShadowCompute::Barrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    this->Counter.Read(&this->Invocations, sizeof(unsigned int));
    return true;
  }

  ReceiverCode GetReceiverCode() override
  {
    ReceiverCode code;
    if (this->UseCompute)
    {
      code.Textures.push_back({ "probeScreen", "sampler2D", this->ScreenVisibility });
    }
    else
    {
      const auto& lights = this->Maps->GetLights();
      for (size_t slot = 0; slot < lights.size(); ++slot)
      {
        code.Textures.push_back(
          { "probeLight" + std::to_string(slot), "sampler2D", lights[slot].Textures[0] });
      }
    }
    code.Declarations = "uniform ivec2 probeOrigin;\n"
                        "float probeLookup(sampler2D target, vec4 p)\n"
                        "{\n"
                        "  p.xyz /= p.w;\n"
                        "  return texture(target, p.xy).r;\n"
                        "}\n";
    code.Visibility = [this](int slot) -> std::string
    {
      if (this->UseCompute)
      {
        return "texelFetch(probeScreen, ivec2(gl_FragCoord.xy) - probeOrigin, 0).r";
      }
      const std::string i = std::to_string(slot);
      return "probeLookup(probeLight" + i + ", vtkShadowWorldToMap[" + i +
        "] * vtkShadowPositionWC)";
    };
    code.Uniforms = [this](vtkShaderProgram* program)
    { program->SetUniform2i("probeOrigin", this->Origin); };
    return code;
  }

  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    this->Superclass::ReleaseGraphicsResources(w);
    for (auto& geometry : this->Geometry)
    {
      geometry->ReleaseGraphicsResources(w);
    }
    if (this->ScreenVisibility)
    {
      this->ScreenVisibility->ReleaseGraphicsResources(w);
    }
    this->Pattern.Release();
    this->Counter.Release();
  }

private:
  std::vector<std::unique_ptr<vtkShadowGeometry>> Geometry;
  vtkSmartPointer<vtkTextureObject> ScreenVisibility;
  vtkShadowCompute::Program Pattern;
  vtkShadowCompute::Buffer Counter;
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };
};
vtkStandardNewMacro(vtkFrameworkProbePass);

// A technique whose shader hooks the test can see.
class vtkHooksProbePass : public vtkHardShadowPass
{
public:
  static vtkHooksProbePass* New();
  vtkTypeMacro(vtkHooksProbePass, vtkHardShadowPass);
  /// The most references any stage's hooks hold.
  int GetHooksReferences()
  {
    int most = 0;
    for (const auto& hooks : this->Drawer->GetAllHooks())
    {
      most = std::max(most, hooks.second->GetReferenceCount());
    }
    return most;
  }
};
vtkStandardNewMacro(vtkHooksProbePass);

namespace
{
// Share of the geometry pixels (red > 0 on a black background) of each grey
// value, and of pixels near none of `expected`.
std::map<int, double> Greys(vtkRenderWindow* window, const std::vector<double>& expected,
  double& strays, int x0 = 0, int x1 = -1)
{
  int* size = window->GetSize();
  x1 = x1 < 0 ? size[0] : x1;
  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, rgb);
  std::map<int, double> shares;
  int total = 0, off = 0;
  for (int y = 0; y < size[1]; ++y)
  {
    for (int x = x0; x < x1; ++x)
    {
      const int v = rgb->GetValue(3 * (y * size[0] + x));
      if (v == 0)
      {
        continue;
      }
      ++total;
      bool near = false;
      for (double e : expected)
      {
        if (std::abs(v - e * 255.0) <= 1.5)
        {
          shares[static_cast<int>(std::lround(e * 1000))] += 1.0;
          near = true;
        }
      }
      off += near ? 0 : 1;
    }
  }
  for (auto& share : shares)
  {
    share.second /= std::max(total, 1);
  }
  strays = static_cast<double>(off) / std::max(total, 1);
  return shares;
}

// References to a pass's shader hooks once a scene with an assembly has been
// drawn with it and then destroyed: 1 (its own) unless a prop's keys kept one.
// vtkAssembly swaps its parts' property keys for its own while drawing them,
// so the hooks must leave the keys they joined, not the part's current ones.
int HooksReferencesAfterScene()
{
  vtkNew<vtkHooksProbePass> pass;
  {
    vtkNew<vtkRenderer> renderer;
    renderer->AutomaticLightCreationOff();
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetPosition(0.0, 5.0, 1.0);
    light->SetConeAngle(40.0);
    renderer->AddLight(light);
    vtkNew<vtkPlaneSource> floor;
    floor->SetOrigin(-2, 0, -2);
    floor->SetPoint1(2, 0, -2);
    floor->SetPoint2(-2, 0, 2);
    vtkNew<vtkCubeSource> box;
    box->SetCenter(0.0, 1.0, 0.0);
    vtkNew<vtkAssembly> assembly;
    for (vtkAlgorithm* source : std::vector<vtkAlgorithm*>{ floor, box })
    {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(source->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      assembly->AddPart(actor);
    }
    renderer->AddViewProp(assembly);
    renderer->SetPass(pass);
    vtkNew<vtkRenderWindow> window;
    window->SetSize(64, 64);
    window->AddRenderer(renderer);
    window->Render();
    window->Render();
  }
  return pass->GetHooksReferences();
}

// Warnings the framework prints, caught by message.
struct WarningCatcher
{
  std::vector<std::string> Messages;
  static void Catch(vtkObject*, unsigned long, void* self, void* data)
  {
    static_cast<WarningCatcher*>(self)->Messages.emplace_back(static_cast<const char*>(data));
  }
};
}

int TestFrameworkEntryPoints(int, char*[])
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->AutomaticLightCreationOff();

  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-3, 0, -3);
  floor->SetPoint1(3, 0, -3);
  floor->SetPoint2(-3, 0, 3);
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(0.5);
  ball->SetCenter(0.0, 1.2, 0.0);
  vtkNew<vtkCubeSource> box;
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (vtkAlgorithm* source : std::vector<vtkAlgorithm*>{ floor, ball, box })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    actors.push_back(actor);
  }
  // Blocks of a composite mapper: pebbles at flat indices 1, 3 and 4, the
  // one at 3 inside a block (2) that is hidden, which hides it too.
  auto pebble = [](double x)
  {
    vtkNew<vtkSphereSource> source;
    source->SetCenter(x, 0.15, 1.5);
    source->SetRadius(0.12);
    source->Update();
    return vtkSmartPointer<vtkPolyData>(source->GetOutput());
  };
  vtkNew<vtkMultiBlockDataSet> blocks;
  vtkNew<vtkMultiBlockDataSet> hidden;
  hidden->SetBlock(0, pebble(-1.1));
  blocks->SetBlock(0, pebble(-1.5));
  blocks->SetBlock(1, hidden);
  blocks->SetBlock(2, pebble(-0.7));
  vtkNew<vtkShadowVTKVersion::CompositeMapper> compositeMapper;
  compositeMapper->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  compositeMapper->SetCompositeDataDisplayAttributes(attributes);
  compositeMapper->SetBlockVisibility(2, false);
  vtkNew<vtkActor> pebbles;
  pebbles->SetMapper(compositeMapper);
  renderer->AddActor(pebbles);

  // The box: rotated, scaled unevenly and moved, inside an assembly turned
  // and moved too.
  vtkActor* boxActor = actors[2];
  boxActor->SetOrientation(20.0, 35.0, 10.0);
  boxActor->SetScale(0.6, 0.3, 0.9);
  boxActor->SetPosition(1.0, 0.4, 0.2);
  renderer->RemoveActor(boxActor);
  vtkNew<vtkAssembly> assembly;
  assembly->AddPart(boxActor);
  assembly->SetOrientation(0.0, 15.0, 0.0);
  assembly->SetPosition(0.3, 0.0, 0.4);
  renderer->AddViewProp(assembly);

  for (double x : { 1.0, -1.5 })
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(true);
    light->SetPosition(x, 6.0, 1.5);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetConeAngle(40.0);
    renderer->AddLight(light);
  }
  renderer->GetActiveCamera()->SetPosition(0.0, 7.0, 6.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.3, 0.0);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkFrameworkProbePass> pass;
  pass->SetMapSize(256);
  pass->SetShadowOnlyLight(0);
  renderer->SetPass(pass);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(200, 160);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->Render();

  // MIN-blended light-space targets, per light: 1 outside the bands, the
  // band's value where one covers a texel, the smaller where both do.
  const int n = vtkFrameworkProbePass::TargetSize;
  for (size_t slot = 0; slot < 2; ++slot)
  {
    const double scale = slot == 0 ? 1.0 : 0.7;
    int wrong = 0, checked = 0;
    const auto& texels =
      pass->LightTexels.size() > slot ? pass->LightTexels[slot] : std::vector<float>();
    for (int j = 0; j < n && !texels.empty(); ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const double x = 2.0 * (i + 0.5) / n - 1.0, y = 2.0 * (j + 0.5) / n - 1.0;
        const double margin = 1.5 * 2.0 / n; // texels next to an edge may go either way
        const bool nearEdge = std::abs(std::abs(y) - 0.5) < margin || std::abs(x - 0.2) < margin ||
          std::abs(x + 0.2) < margin;
        if (nearEdge)
        {
          continue;
        }
        double expected = 1.0;
        if (std::abs(y) < 0.5)
        {
          expected = x < 0.2 ? 0.3 * scale : 0.6 * scale; // drawn second, larger: MIN keeps 0.3
        }
        ++checked;
        wrong += std::abs(texels[j * n + i] - expected) < 1e-5 ? 0 : 1;
      }
    }
    Check(checked > n * n / 2 && wrong == 0,
      "light " + std::to_string(slot) + "'s MIN-blended target holds the bands (" +
        std::to_string(wrong) + " of " + std::to_string(checked) + " texels wrong)");
  }

  // Receivers read each light's own texture where the light projects them.
  for (int light = 0; light < 2; ++light)
  {
    pass->SetShadowOnlyLight(light);
    window->Render();
    const double scale = light == 0 ? 1.0 : 0.7;
    double strays = 0.0;
    auto shares = Greys(window, { 1.0, 0.6 * scale, 0.3 * scale }, strays);
    const bool all = shares.size() == 3 &&
      std::all_of(shares.begin(), shares.end(), [](const auto& s) { return s.second > 0.005; });
    Check(all && strays < 0.01,
      "light " + std::to_string(light) + "'s receivers show its texture's three values (" +
        std::to_string(strays * 100.0) + "% other pixels)");
  }

  // The casters: two actors' polydata, the assembly's box, and the
  // composite's visible blocks (flat indices 1 and 4).
  std::vector<unsigned int> pebbleBlocks;
  for (const auto& seen : pass->CastersSeen)
  {
    if (seen.first == pebbles.Get())
    {
      pebbleBlocks.push_back(seen.second);
    }
  }
  const bool boxSeen = std::count(pass->CastersSeen.begin(), pass->CastersSeen.end(),
                         std::make_pair(static_cast<vtkProp*>(assembly.Get()), 0u)) == 1;
  Check(
    pass->CastersSeen.size() == 5 && boxSeen && pebbleBlocks == std::vector<unsigned int>{ 1, 4 },
    "five casters: two actors, the assembly's box and the composite's two visible blocks (" +
      std::to_string(pass->CastersSeen.size()) + ")");

  // The per-caster cache: built once per polydata...
  Check(pass->Cache.GetNumberOfBuilds() == 5 && pass->Cache.GetNumberOfEntries() == 5,
    "five casters, five builds (" + std::to_string(pass->Cache.GetNumberOfBuilds()) + ")");
  // ...rebuilt when one is modified...
  ball->SetThetaResolution(24);
  window->Render();
  Check(pass->Cache.GetNumberOfBuilds() == 6, "a modified polydata is rebuilt, once");
  window->Render();
  Check(pass->Cache.GetNumberOfBuilds() == 6, "nothing modified, nothing rebuilt");

  // Model-space light: the transformed box's silhouettes are those of the
  // box transformed into the world, under the world light.
  vtkNew<vtkTransformPolyDataFilter> world;
  vtkNew<vtkTransform> transform;
  vtkNew<vtkMatrix4x4> boxToWorld;
  vtkMatrix4x4::Multiply4x4(assembly->GetMatrix(), boxActor->GetMatrix(), boxToWorld);
  transform->SetMatrix(boxToWorld);
  world->SetTransform(transform);
  world->SetInputConnection(box->GetOutputPort());
  vtkNew<vtkLightSilhouetteFilter> reference;
  reference->SetInputConnection(world->GetOutputPort());
  vtkLight* first = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
  reference->SetLightPosition(first->GetTransformedPosition());
  reference->Update();
  const vtkIdType modelSpace = pass->Silhouettes[boxActor];
  Check(modelSpace > 0 && modelSpace == reference->GetNumberOfSilhouetteEdges(),
    "the transformed box's model-space silhouette matches the world one (" +
      std::to_string(modelSpace) + " and " +
      std::to_string(reference->GetNumberOfSilhouetteEdges()) + " edges)");

  // ...and forgets a caster that left the scene.
  renderer->RemoveViewProp(assembly);
  window->Render();
  Check(pass->Cache.GetNumberOfEntries() == 4, "a removed caster leaves the cache");
  renderer->AddViewProp(assembly);

  // A compute pass writes the visibility the receivers read.
  pass->UseCompute = true;
  pass->SetShadowOnlyLight(0);
  window->Render();
  const int* size = window->GetSize();
  Check(pass->Invocations == static_cast<unsigned int>(size[0] * size[1]),
    "the compute pass counted every pixel (" + std::to_string(pass->Invocations) + ")");
  double strays = 0.0;
  auto left = Greys(window, { 1.0 }, strays, 0, size[0] / 2);
  Check(left.size() == 1 && strays < 0.005, "left half lit by the compute pass");
  auto right = Greys(window, { 0.25 }, strays, size[0] / 2, size[0]);
  Check(right.size() == 1 && strays < 0.005, "right half at 0.25 from the compute pass");

  // A mapper whose shader lacks the lighting the shadow term edits: one
  // warning naming the mapper, not a silent unshadowed actor.
  pass->UseCompute = false;
  WarningCatcher catcher;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(&WarningCatcher::Catch);
  callback->SetClientData(&catcher);
  actors[1]->GetShaderProperty()->AddFragmentShaderReplacement(
    "//VTK::Light::Impl", true, "gl_FragData[0] = vec4(1.0, 0.0, 0.0, 1.0);\n", false);
  const unsigned long tag =
    vtkOutputWindow::GetInstance()->AddObserver(vtkCommand::WarningEvent, callback);
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  window->Render();
  window->Render();
  vtkOutputWindow::GetInstance()->RemoveObserver(tag);
  vtkOutputWindow::GetInstance()->SetDisplayModeToDefault();
  int named = 0;
  for (const std::string& m : catcher.Messages)
  {
    named += m.find("vtkOpenGLPolyDataMapper") != std::string::npos ? 1 : 0;
  }
  Check(named == 1 && catcher.Messages.size() == 1,
    "an unshadowable mapper is named in one warning (" + std::to_string(catcher.Messages.size()) +
      " warnings)");

  const int references = HooksReferencesAfterScene();
  Check(references == 1,
    "the shader hooks leave an assembly's parts (" + std::to_string(references) + " references)");

  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
