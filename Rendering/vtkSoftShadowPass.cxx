// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSoftShadowPass.h"

#include "vtkAbstractMapper.h"
#include "vtkCamera.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkLight.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkProp.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkSequencePass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowCompute.h"
#include "vtkShadowDepthStage.h"
#include "vtkShadowDistanceStage.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowLightSize.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowMapperCode.h"
#include "vtkShadowMatrices.h"
#include "vtkShadowParallelMaps.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkShadowShaderHooks.h"
#include "vtkShadowStage.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"
#include "vtkVolumetricPass.h"

#include "vtkShadowCubeLookupFS.h"
#include "vtkShadowNormalOffsetFS.h"
#include "vtkShadowSurfaceFS.h"
#include "vtkSoftShadowReceiverFS.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <sstream>

// The depth-only pre-pass as a step of the delegate's opaque sequence: it
// runs after the camera pass has cleared and set up the frame.
class vtkSoftShadowPass::vtkDepthPrePassStep : public vtkRenderPass
{
public:
  static vtkDepthPrePassStep* New();
  vtkTypeMacro(vtkDepthPrePassStep, vtkRenderPass);
  vtkSoftShadowPass* Owner = nullptr;
  void Render(const vtkRenderState* s) override { this->Owner->RenderDepthPrePass(s); }
};
vtkStandardNewMacro(vtkSoftShadowPass::vtkDepthPrePassStep);

namespace
{
void SetMatrix(vtkShaderProgram* program, const std::string& name, const glm::dmat4& m)
{
  glm::mat4 single(m);
  program->SetUniformMatrix4x4(name.c_str(), glm::value_ptr(single));
}

// Each lit fragment's surface (vtkShadowSurfaceFS.glsl), as the camera pass
// and the receivers' visibility expressions see it: from the fragment's
// view-space position, which sphere and stick imposters compute in the
// fragment shader (vertexVC), and its shading normal.
std::string SurfaceCode(const std::string& fragmentShader)
{
  const bool computed = fragmentShader.find("vec4 vertexVC") != std::string::npos;
  const bool shaded = fragmentShader.find("normalVCVSOutput") != std::string::npos;
  return std::string("  vec4 vtkShadowPositionWC;\n"
                     "  vec3 vtkShadowNormalWC;\n"
                     "  bool vtkShadowFaceDefined = vtkShadowSurface(") +
    (computed ? "vertexVC.xyz" : "vertexVCVSOutput.xyz") + ", " +
    (shaded ? "normalVCVSOutput" : "vec3(0.0, 0.0, 1.0)") + ", " +
    (vtkShadowMapperCode::MovesDepthOnly(fragmentShader) ? "true" : "false") +
    ", vtkShadowPositionWC, vtkShadowNormalWC);\n";
}

// The camera's view to world matrix, for the surface code.
void SetViewToWorld(vtkShaderProgram* program, vtkRenderer* renderer)
{
  SetMatrix(program, "vtkShadowViewToWorld",
    glm::inverse(
      vtkShadowMatrices::FromVTK(renderer->GetActiveCamera()->GetModelViewTransformMatrix())));
}

std::string Indexed(const char* name, int i)
{
  return std::string(name) + "[" + std::to_string(i) + "]";
}
}

//------------------------------------------------------------------------------
// The camera pass (RenderCameraDepth()): depth, and the technique's code on
// every fragment the camera sees, writing its colour targets.
class vtkSoftShadowPass::vtkCameraStage : public vtkShadowStage
{
public:
  explicit vtkCameraStage(vtkSoftShadowPass* pass)
    : Pass(pass)
  {
  }

  void Begin(const vtkShadowDrawSetup& setup) override
  {
    this->Targets = static_cast<int>(setup.Colours.size());
  }

  void PreReplace(vtkShadowShaderSources& sources) override
  {
    using namespace vtkShadowMapperCode;
    vtkShadowShaderSources::Before(sources.Fragment, LightDec, ShadowDec);
    sources.Require(sources.Fragment, LightImpl,
      std::string(ShadowImpl) + "\n  return;\n  " + LightImpl, "the camera pass");
  }

  void PostReplace(vtkShadowShaderSources& sources) override
  {
    // Without lighting the mapper declares no view-space position: such
    // fragments write 0.
    std::string dec, impl;
    if (this->Targets > 0 && sources.IsLit())
    {
      dec = std::string(vtkShadowSurfaceFS) + "\n" + this->Code->Declarations;
      impl = SurfaceCode(sources.Fragment) + this->Code->Implementation;
    }
    else
    {
      for (int i = 0; i < std::max(this->Targets, 1); ++i)
      {
        impl += "  gl_FragData[" + std::to_string(i) + "] = vec4(0.0);\n";
      }
    }
    sources.Require(sources.Fragment, vtkShadowMapperCode::ShadowDec, dec, "the camera pass");
    sources.Require(sources.Fragment, vtkShadowMapperCode::ShadowImpl, impl, "the camera pass");
  }

  std::string GetName() const override { return "the camera pass"; }

  void SetUniforms(vtkShaderProgram* program, vtkProp*) override
  {
    if (program->IsUniformUsed("vtkShadowViewToWorld"))
    {
      SetViewToWorld(program, this->Pass->Maps->GetRenderer());
      if (this->Code->Uniforms)
      {
        this->Code->Uniforms(program);
      }
    }
  }

  const CameraPassCode* Code = nullptr; ///< RenderCameraDepth()'s, while it draws

private:
  vtkSoftShadowPass* Pass;
  int Targets = 0;
};

//------------------------------------------------------------------------------
// The receivers, drawn by the delegate: tags are placed before the mapper
// writes its lighting code, and filled after, once it is known whether the
// shader has lighting at all; then each shadowed light's contribution is
// scaled by its shadow factor.
class vtkSoftShadowPass::vtkReceiverStage : public vtkShadowStage
{
public:
  explicit vtkReceiverStage(vtkSoftShadowPass* pass)
    : Pass(pass)
  {
  }

  void PreReplace(vtkShadowShaderSources& sources) override
  {
    using namespace vtkShadowMapperCode;
    if (this->Pass->FrameTraits.ScreenSpace)
    {
      // textureGather (vtkShadowScreenVisibility) in the mappers' GLSL 1.50.
      sources.AddFragmentExtension("GL_ARB_texture_gather");
    }
    const auto& lights = this->Pass->Maps->GetLights();
    if (std::any_of(lights.begin(), lights.end(),
          [](const vtkShadowMapManager::Light& l) { return l.Point; }))
    {
      // The cube maps' lookups in one loop where it is supported
      // (vtkShadowCubeHardAll, vtkSoftShadowReceiverFS.glsl; omni's Poisson
      // lookup, vtkOmniPoissonAll, needs it).
      sources.AddFragmentExtension("GL_ARB_gpu_shader5");
    }
    for (const std::string& extension : this->Pass->FrameTraits.ReceiverExtensions)
    {
      sources.AddFragmentExtension(extension);
    }
    // Shaders without lighting (no tags) are not shadowed: no word needed.
    vtkShadowShaderSources::Before(sources.Fragment, LightDec, ShadowDec);
    vtkShadowShaderSources::Before(sources.Fragment, LightImpl, ShadowImpl);
    // The technique's vertex code (GetReceiverShading()), if any.
    vtkShadowShaderSources::Before(sources.Vertex, LightDec, ShadowDec);
    vtkShadowShaderSources::Before(sources.Vertex, LightImpl, ShadowImpl);
  }

  void PostReplace(vtkShadowShaderSources& sources) override;
  void SetUniforms(vtkShaderProgram* program, vtkProp*) override;
  std::string GetName() const override { return "the receivers"; }

private:
  vtkSoftShadowPass* Pass;
};

//------------------------------------------------------------------------------
void vtkSoftShadowPass::vtkReceiverStage::PostReplace(vtkShadowShaderSources& sources)
{
  vtkSoftShadowPass* pass = this->Pass;
  std::string& fragmentShader = sources.Fragment;
  const auto& lights = pass->Maps->GetLights();
  const bool lit = sources.IsLit();
  if (!lights.empty() && sources.Mapper && sources.Mapper->IsA("vtkVolumeMapper"))
  {
    sources.AddMiss("volumes receive no shadows from " + std::string(pass->GetClassName()) +
      "; they are drawn as VTK draws them without it");
  }

  // The shadowed lights were chosen to fit beside ReservedTextureUnits of
  // the mappers' own textures; a shader with more of its own shadows the
  // first lights that fit (arrays indexed by slot stay compact), and raises
  // the reserve for the next frames.
  const int own = lit ? sources.CountTextures() : 0;
  pass->ReceiverOwnTextures = std::max(pass->ReceiverOwnTextures, own);
  const int room = pass->TextureUnits - own - pass->FrameTraits.ReceiverTexturesPerFrame;
  const size_t count =
    std::min(lights.size(), static_cast<size_t>(std::max(room, 0) / pass->ReceiverTextures()));
  if (lit && count < lights.size())
  {
    sources.AddMiss("its own " + std::to_string(own) + " textures leave room for the shadows of " +
      std::to_string(count) + " of the " + std::to_string(lights.size()) +
      " shadowed lights; the others light it unshadowed");
  }
  const bool active = lit && count > 0;

  std::string onlyVisibility = "1.0";
  std::string unscaled; // lights whose lighting lines were not found
  std::ostringstream dec, impl;
  if (active)
  {
    const auto cubes = std::count_if(lights.begin(), lights.begin() + count,
      [](const vtkShadowMapManager::Light& l) { return l.Point; });
    dec << "#define VTK_SHADOW_LIGHTS " << count << "\n"
        << "#define VTK_SHADOW_MAPS " << count - cubes << "\n"
        << "#define VTK_SHADOW_CUBES " << cubes << "\n";
    if (pass->FrameTraits.ScreenSpace)
    {
      dec << "#define VTK_SHADOW_SCREEN_SPACE\n";
    }
    dec << vtkShadowSurfaceFS << "\n"
        << vtkSoftShadowPass::GetLightSpaceLookupCode() << vtkSoftShadowReceiverFS << "\n";
    for (const auto& texture : pass->FrameReceiverCode.Textures)
    {
      dec << "uniform " << texture.Sampler << " " << texture.Name << ";\n";
    }
    dec << pass->FrameReceiverCode.Declarations << "\n";
    const ReceiverShading shading = pass->GetReceiverShading(sources);
    dec << shading.FragmentDeclarations << "\n";
    vtkShaderProgram::Substitute(
      sources.Vertex, vtkShadowMapperCode::ShadowDec, shading.VertexDeclarations, false);
    vtkShaderProgram::Substitute(
      sources.Vertex, vtkShadowMapperCode::ShadowImpl, shading.VertexImplementation, false);

    impl << SurfaceCode(fragmentShader);
    if (pass->FrameTraits.ScreenSpace)
    {
      impl << "  vtkShadowScreenSetup(vtkShadowPositionWC);\n";
    }
    impl << pass->FrameReceiverCode.Setup;
    for (size_t slot = 0; slot < count; ++slot)
    {
      const int n = lights[slot].ShaderIndex;
      const int i = static_cast<int>(slot);
      const auto& visibility = pass->FrameReceiverCode.Visibility;
      impl << "  float vtkShadowVisibility" << n << " = "
           << (visibility ? visibility(i) : pass->GetDefaultVisibility(i)) << ";\n"
           << "  float vtkShadowFactor" << n << " = mix(1.0, vtkShadowVisibility" << n
           << ", vtkShadowAttenuation[" << i << "]);\n";
      if (!vtkShadowMapperCode::ScaleLight(fragmentShader, n, "vtkShadowFactor" + std::to_string(n),
            slot < shading.PhongScales.size() ? shading.PhongScales[slot] : ""))
      {
        unscaled += (unscaled.empty() ? "" : ", ") + std::to_string(n);
      }
      if (lights[slot].SceneIndex == pass->ShadowOnlyLight)
      {
        onlyVisibility = "vtkShadowVisibility" + std::to_string(n);
      }
    }
    // A lit shader must have kept the tags and the lighting lines; others
    // only lose the tags. One word per shader: the first thing missing.
    const std::string what = "the shadow term";
    if (sources.Require(fragmentShader, vtkShadowMapperCode::ShadowDec, dec.str(), what) &&
      sources.Require(fragmentShader, vtkShadowMapperCode::ShadowImpl, impl.str(), what) &&
      !unscaled.empty())
    {
      sources.AddMiss("its lighting code has no line the shadow of light " + unscaled +
        " can scale, so its actors are drawn without that shadow (a custom shader replacement, "
        "or mapper code other than vtkShadowMapperCode.h expects)");
    }
  }
  else
  {
    vtkShaderProgram::Substitute(fragmentShader, vtkShadowMapperCode::ShadowDec, "", false);
    vtkShaderProgram::Substitute(fragmentShader, vtkShadowMapperCode::ShadowImpl, "", false);
    vtkShaderProgram::Substitute(sources.Vertex, vtkShadowMapperCode::ShadowDec, "", false);
    vtkShaderProgram::Substitute(sources.Vertex, vtkShadowMapperCode::ShadowImpl, "", false);
  }

  if (pass->ShadowOnlyLight >= 0)
  {
    vtkShaderProgram::Substitute(fragmentShader, vtkShadowMapperCode::LightImpl,
      "gl_FragData[0] = vec4(vec3(" + onlyVisibility + "), 1.0);\n  " +
        vtkShadowMapperCode::LightImpl,
      false);
  }
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::vtkReceiverStage::SetUniforms(vtkShaderProgram* program, vtkProp* prop)
{
  vtkSoftShadowPass* pass = this->Pass;
  // Only programs with the shadow term; a visibility that does not depend
  // on the position (or only in the shadow-only view) may have left
  // vtkShadowViewToWorld unused.
  bool receiver = program->IsUniformUsed("vtkShadowViewToWorld") ||
    program->IsUniformUsed("vtkShadowAttenuation[0]");
  for (const auto& texture : pass->FrameReceiverCode.Textures)
  {
    receiver = receiver || program->IsUniformUsed(texture.Name.c_str());
  }
  if (!receiver)
  {
    return;
  }
  SetViewToWorld(program, pass->Maps->GetRenderer());
  program->SetUniformf("vtkShadowMapTexel", 1.0f / static_cast<float>(pass->MapSize));
  program->SetUniformi("vtkShadowPCFRadius", pass->GetPCFRadius());
  program->SetUniformi("vtkShadowPCFBilinear", pass->GetPCFBilinear() ? 1 : 0);
  vtkShadowMapManager::SetLookupUniforms(
    program, "vtkShadow", pass->MapSize, pass->NormalBias, pass->DistanceBias);

  const auto& lights = pass->Maps->GetLights();
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    const auto& light = lights[slot];
    const int i = static_cast<int>(slot);
    program->SetUniformf(
      Indexed("vtkShadowAttenuation", i).c_str(), static_cast<float>(light.Attenuation));
    if (light.Point)
    {
      program->SetUniformi(
        Indexed("vtkShadowCube", light.MapIndex).c_str(), light.CubeMap->GetTextureUnit());
      vtkShadowMapManager::SetCubeUniforms(program, "vtkShadow",
        "[" + std::to_string(light.MapIndex) + "]", light.Faces, pass->DrawsPackedCubeMaps());
      continue;
    }
    vtkShadowMapManager::SetFrustumUniforms(
      program, "vtkShadow", "[" + std::to_string(i) + "]", light.Map, pass->MapSize);
    if (light.DepthMap) // techniques with maps of their own may not draw it
    {
      program->SetUniformi(
        Indexed("vtkShadowMap", light.MapIndex).c_str(), light.DepthMap->GetTextureUnit());
    }
  }
  if (pass->FrameTraits.ScreenSpace)
  {
    pass->Screen->SetUniforms(program, static_cast<int>(lights.size()));
  }
  for (const auto& texture : pass->FrameReceiverCode.Textures)
  {
    program->SetUniformi(texture.Name.c_str(), texture.Texture->GetTextureUnit());
  }
  if (pass->FrameReceiverCode.Uniforms)
  {
    pass->FrameReceiverCode.Uniforms(program);
  }
  pass->SetReceiverShadingUniforms(program, prop);
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::vtkSoftShadowPass()
  : Casters(new vtkShadowCasterRegistry)
  , Maps(new vtkShadowMapManager)
  , Screen(new vtkShadowScreenBuffers)
  , Drawer(new vtkShadowDrawer(*Casters))
  , DepthStage(new vtkShadowDepthStage)
  , PrePassStage(new vtkShadowDepthStage)
  , DistanceStage(new vtkShadowDistanceStage)
  , CameraStage(new vtkCameraStage(this))
  , ReceiverStage(new vtkReceiverStage(this))
  , Parallel(new vtkShadowParallelMaps)
{
  // The default delegate draws translucency as VTK's renderer does without a
  // pass: order independent, or depth-peeled when the renderer asks.
  this->DefaultSteps = vtkSmartPointer<vtkRenderStepsPass>::New();
  this->OrderIndependent->SetTranslucentPass(this->Translucent);
  this->DepthPeeling->SetTranslucentPass(this->Translucent);
  this->DefaultSteps->SetTranslucentPass(this->OrderIndependent);
  this->SetDelegatePass(this->DefaultSteps);
  this->PrePassStage->SetLightSpace(false);
  this->Drawer->GetHooks()->SetOwner(this); // names the technique in its errors
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::~vtkSoftShadowPass()
{
  this->SetDelegatePass(nullptr);
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::SetController(vtkMultiProcessController* controller)
{
  if (controller != this->Parallel->GetController())
  {
    this->Parallel->SetController(controller);
    this->UncombinedReported = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkSoftShadowPass::GetController() const
{
  return this->Parallel->GetController();
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::SetRadius(double radius, vtkLight* light)
{
  vtkShadowLightSize::SetRadius(radius, light);
}

//------------------------------------------------------------------------------
double vtkSoftShadowPass::GetRadius(vtkLight* light)
{
  return vtkShadowLightSize::GetRadius(light);
}

//------------------------------------------------------------------------------
vtkInformationDoubleKey* vtkSoftShadowPass::RADIUS()
{
  return vtkShadowLightSize::RADIUS();
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::SetDelegatePass(vtkRenderPass* pass)
{
  vtkSetObjectBodyMacro(DelegatePass, vtkRenderPass, pass);
}

//------------------------------------------------------------------------------
int vtkSoftShadowPass::GetNumberOfShadowedLights() const
{
  return static_cast<int>(this->Maps->GetLights().size());
}

//------------------------------------------------------------------------------
int vtkSoftShadowPass::GetNumberOfUnshadowedLights() const
{
  return this->Maps->GetNumberOfUnshadowedLights();
}

//------------------------------------------------------------------------------
// A point light takes the same units as any light.
int vtkSoftShadowPass::GetMaximumNumberOfShadowedLights(bool vtkNotUsed(pointLights)) const
{
  return std::max(this->ShadowTextureUnits(), 0) / this->ReceiverTextures();
}

//------------------------------------------------------------------------------
int vtkSoftShadowPass::ShadowTextureUnits() const
{
  return this->TextureUnits - std::max(this->ReservedTextureUnits, this->ReceiverOwnTextures) -
    this->FrameTraits.ReceiverTexturesPerFrame;
}

//------------------------------------------------------------------------------
int vtkSoftShadowPass::ReceiverTextures() const
{
  // The light's map (or cube map), its screen-space texture, the technique's.
  const Traits& traits = this->FrameTraits;
  return 1 + (traits.ScreenSpace ? 1 : 0) + traits.ReceiverTexturesPerLight;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::DrawsPackedCubeMaps() const
{
  return this->PackedCubeMaps && !this->FrameTraits.FloatCubeMaps;
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkErrorMacro("No delegate pass: nothing to render.");
    return;
  }

  vtkRenderer* renderer = s->GetRenderer();
  int width = 0, height = 0;
  renderer->GetTiledSize(&width, &height);
  if (width <= 0 || height <= 0)
  {
    vtkErrorMacro("Renderer has an empty viewport (" << width << "x" << height << ").");
    return;
  }

  // 1. Decide: which lights cast shadows, and their frusta; what casts.
  // As many lights as the receivers' texture units have room for.
  this->FrameTraits = this->GetTraits();
  const Traits& traits = this->FrameTraits;
  GLint fragmentUnits = 0, combinedUnits = 0;
  glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &fragmentUnits);
  glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &combinedUnits);
  this->TextureUnits = std::min(fragmentUnits, combinedUnits);
  vtkShadowMapManager::Budget budget;
  budget.PointLights = traits.PointLights;
  budget.TextureUnits = std::max(this->ShadowTextureUnits(), 0);
  if (this->Parallel->IsParallel())
  {
    // Every process must shadow the same lights: their maps are reduced together.
    budget.TextureUnits = this->Parallel->CombineMinimum(budget.TextureUnits);
  }
  budget.UnitsPerLight = this->ReceiverTextures();
  this->Maps->SetMapSize(this->MapSize);
  this->Maps->Update(renderer, budget, this->Parallel.get());
  this->Casters->SetBuildGlyphInstances(traits.CasterGeometry);
  this->Casters->Update(renderer);
  auto& shadowed = this->Maps->GetLights();
  const int points = this->Maps->GetNumberOfSkippedPointLights();
  if (points > 0 && !this->PointLightReported)
  {
    vtkErrorMacro(<< points
                  << " point light(s) (positional, cone angle >= 90): " << this->GetClassName()
                  << " does not shadow point lights yet; they are drawn without shadows.");
    this->PointLightReported = true;
  }
  const char* uncombined = traits.UncombinedLightSpaceData;
  if (uncombined && this->Parallel->IsParallel() && !this->UncombinedReported)
  {
    vtkErrorMacro(<< this->GetClassName() << " does not combine its " << uncombined
                  << " across the " << this->Parallel->GetController()->GetNumberOfProcesses()
                  << " processes of a parallel render yet: shadows that casters on one process "
                     "cast on another's receivers are missing or hard. hard, reference, contact "
                     "and omni combine all they draw.");
    this->UncombinedReported = true;
  }
  const int unshadowed = this->Maps->GetNumberOfUnshadowedLights();
  if (unshadowed != this->ReportedUnshadowed)
  {
    if (unshadowed > 0)
    {
      vtkWarningMacro(<< unshadowed << " of " << shadowed.size() + unshadowed
                      << " lights are drawn without shadows: " << this->GetClassName()
                      << "'s receivers have " << budget.TextureUnits
                      << " texture units for shadows here and a light takes "
                      << this->ReceiverTextures()
                      << "; the brightest, then those nearest the focal point, are shadowed.");
    }
    this->ReportedUnshadowed = unshadowed;
  }

  // 2-3. Draw the technique's maps and screen-space passes, each step timed
  // on the GPU.
  bool drawn = !shadowed.empty() &&
    this->CheckRequirements(vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow()));
  if (drawn)
  {
    this->LightSpaceTimer.Start();
    drawn = this->RenderShadowMaps(s);
    this->LightSpaceTimer.Stop();
  }
  if (drawn && traits.ScreenSpace)
  {
    this->Screen->SetResolutionDivisor(traits.ScreenResolutionDivisor);
    this->ScreenSpaceTimer.Start();
    drawn = this->Screen->Update(s) && this->RenderScreenSpace(s) &&
      this->Screen->Pack(static_cast<int>(shadowed.size()));
    this->ScreenSpaceTimer.Stop();
  }
  if (!drawn)
  {
    shadowed.clear();
  }

  // 4. Draw the scene with the shadow term in every receiver's shader.
  this->ReceiversTimer.Start();
  this->RenderReceivers(s, drawn && traits.ScreenSpace);
  this->ReceiversTimer.Stop();
  vtkOpenGLCheckErrorMacro("failed after Render");
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::RenderReceivers(const vtkRenderState* s, bool screenSpace)
{
  auto& shadowed = this->Maps->GetLights();
  for (auto& light : shadowed)
  {
    if (vtkTextureObject* map = light.Point ? light.CubeMap : light.DepthMap)
    {
      map->Activate();
    }
  }
  if (screenSpace)
  {
    this->Screen->ActivateTextures();
  }
  this->FrameReceiverCode = shadowed.empty() ? ReceiverCode() : this->GetReceiverCode();
  for (auto& texture : this->FrameReceiverCode.Textures)
  {
    texture.Texture->Activate();
  }

  // Cube maps are looked up across faces: filter across their seams.
  vtkOpenGLState* state =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable seamless(state, GL_TEXTURE_CUBE_MAP_SEAMLESS);
  state->vtkglEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

  if (this->DelegatePass == this->DefaultSteps)
  {
    this->ChooseTranslucency(s->GetRenderer());
  }

  // Gerasimov's depth-only pre-pass (section 12.3.4): opaque depth first, so
  // the shading pass runs only on visible fragments. It is a step slotted
  // before the default delegate's opaque pass, after its camera pass cleared.
  auto* steps = vtkRenderStepsPass::SafeDownCast(this->DelegatePass);
  vtkSmartPointer<vtkRenderPass> opaque = steps ? steps->GetOpaquePass() : nullptr;
  const bool prePass = this->DepthPrePass && !shadowed.empty() && opaque;
  if (prePass)
  {
    vtkNew<vtkDepthPrePassStep> step;
    step->Owner = this;
    vtkNew<vtkRenderPassCollection> passes;
    passes->AddItem(step);
    passes->AddItem(opaque);
    vtkNew<vtkSequencePass> sequence;
    sequence->SetPasses(passes);
    steps->SetOpaquePass(sequence);
  }

  vtkShadowShaderHooks* hooks = this->Drawer->GetHooks();
  hooks->SetStage(this->ReceiverStage.get());
  hooks->Attach(s);
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
  hooks->Detach(s);
  hooks->SetStage(nullptr);
  this->ReceiversDrawn();
  if (prePass)
  {
    steps->SetOpaquePass(opaque);
  }

  for (auto& texture : this->FrameReceiverCode.Textures)
  {
    texture.Texture->Deactivate();
  }
  if (screenSpace)
  {
    this->Screen->DeactivateTextures();
  }
  for (auto& light : shadowed)
  {
    if (vtkTextureObject* map = light.Point ? light.CubeMap : light.DepthMap)
    {
      map->Deactivate();
    }
  }
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::ChooseTranslucency(vtkRenderer* renderer)
{
  // As vtkOpenGLRenderer::DeviceRenderTranslucentPolygonalGeometry() does.
  vtkRenderStepsPass* steps = this->DefaultSteps;
  if (!renderer->GetUseDepthPeeling())
  {
    steps->SetTranslucentPass(this->OrderIndependent);
    steps->SetVolumetricPass(this->Volumetric);
    this->DepthPeeling->SetVolumetricPass(nullptr);
    return;
  }
  this->DepthPeeling->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
  this->DepthPeeling->SetOcclusionRatio(renderer->GetOcclusionRatio());
  // Volumes peeled with the translucent geometry, or drawn after it.
  const bool volumes = renderer->GetUseDepthPeelingForVolumes();
  this->DepthPeeling->SetVolumetricPass(volumes ? this->Volumetric.Get() : nullptr);
  steps->SetVolumetricPass(volumes ? nullptr : this->Volumetric.Get());
  steps->SetTranslucentPass(this->DepthPeeling);
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::Draw(const vtkRenderState* s, const vtkShadowDrawSetup& setup)
{
  return this->Drawer->Draw(s, setup);
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::RenderDepthMap(const vtkRenderState* s, const vtkShadowFrustum& frustum,
  vtkTextureObject* target, bool beyondFaces)
{
  vtkShadowDrawSetup setup;
  setup.Draw =
    beyondFaces ? vtkShadowDrawSetup::Props::DepthMapCasters : vtkShadowDrawSetup::Props::Casters;
  setup.View = &frustum;
  setup.Depth = target;
  setup.Stage = this->DepthStage.get();
  // Slope-scaled bias: acne-free lit surfaces. PCF taps reach (r + 1)
  // texels from the looked-up point (bilinear footprint included), so the
  // slope term grows with the kernel.
  setup.SlopeBias = this->SlopeScaledBias * (1.0 + this->GetPCFRadius());
  setup.ConstantBias = this->ConstantBias;
  if (!this->Drawer->Draw(s, setup))
  {
    return false;
  }
  if (this->Parallel->IsParallel())
  {
    this->Parallel->CombineDepth(target);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::OnAnyProcess(bool value)
{
  return this->Parallel->IsParallel() ? this->Parallel->CombineMinimum(value ? 0 : 1) == 0 : value;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::RenderDistanceCube(const vtkRenderState* s,
  const std::array<vtkShadowFrustum, 6>& faces, vtkTextureObject* cube, bool beyondFaces)
{
  vtkShadowDrawSetup setup;
  setup.Draw =
    beyondFaces ? vtkShadowDrawSetup::Props::DepthMapCasters : vtkShadowDrawSetup::Props::Casters;
  setup.Faces = &faces;
  setup.Colours = { cube };
  // Nothing drawn is infinitely far (packed: the largest value): lit.
  const float far = this->DrawsPackedCubeMaps() ? 1.0f : VTK_FLOAT_MAX;
  std::fill(setup.ClearColour, setup.ClearColour + 4, far);
  this->DistanceStage->SetPacked(this->DrawsPackedCubeMaps());
  setup.Stage = this->DistanceStage.get();
  if (this->SinglePassCubeMaps)
  {
    if (!this->Drawer->Draw(s, setup)) // all six faces, layered
    {
      return false;
    }
  }
  else
  {
    for (setup.CubeFace = 0; setup.CubeFace < 6; ++setup.CubeFace)
    {
      if (!this->Drawer->Draw(s, setup))
      {
        return false;
      }
    }
  }
  if (this->Parallel->IsParallel())
  {
    this->Parallel->CombineCube(cube);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::RenderLightDepthMaps(const vtkRenderState* s, bool linear)
{
  this->LinearMaps = linear;
  for (auto& light : this->Maps->GetLights())
  {
    if (light.Point)
    {
      this->Maps->AllocateCubeMap(light, this->DrawsPackedCubeMaps());
      if (!this->RenderDistanceCube(s, light.Faces, light.CubeMap))
      {
        return false;
      }
      continue;
    }
    this->Maps->AllocateDepthMap(light, linear);
    if (!this->RenderDepthMap(s, light.Map, light.DepthMap))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::RenderCameraDepth(const vtkRenderState* s,
  const std::vector<vtkTextureObject*>& targets, const CameraPassCode& code)
{
  if (!targets.empty())
  {
    // Mappers write lighting code, where the camera pass code goes, only for
    // the renderer's lighting complexity, which its lights pass updates
    // later in the frame (and on the first frame, not yet at all).
    this->UpdateLightGeometry(s->GetRenderer());
    this->UpdateLights(s->GetRenderer());
  }
  vtkShadowDrawSetup setup;
  setup.Depth = this->Screen->GetCameraDepth();
  setup.Colours = targets;
  setup.Draw = vtkShadowDrawSetup::Props::Camera;
  setup.Stage = this->CameraStage.get();
  this->CameraStage->Code = &code;
  const bool drawn = setup.Depth && this->Drawer->Draw(s, setup);
  this->CameraStage->Code = nullptr;
  return drawn;
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::RenderDepthPrePass(const vtkRenderState* s)
{
  // The props carry the hooks already (receivers): only the stage changes,
  // to the shading-free depth shaders, then back.
  vtkOpenGLState* state =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDepthMask(GL_TRUE);
  vtkShadowShaderHooks* hooks = this->Drawer->GetHooks();
  hooks->SetStage(this->PrePassStage.get());
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    s->GetPropArray()[i]->RenderOpaqueGeometry(s->GetRenderer());
  }
  hooks->SetStage(this->ReceiverStage.get());
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::CheckRequirements(vtkOpenGLRenderWindow* context)
{
  const Traits& traits = this->FrameTraits;
  std::string missing;
  if (traits.Compute && !vtkShadowCompute::IsSupported(context, &missing))
  {
    if (!this->ComputeReported)
    {
      vtkErrorMacro(<< this->GetClassName() << " needs OpenGL 4.3 compute, and this context lacks "
                    << missing << ": drawing without its shadows.");
      this->ComputeReported = true;
    }
    return false;
  }
  if (traits.Samplers && !this->Screen->SupportsSamplers())
  {
    if (!this->SamplersReported)
    {
      vtkErrorMacro(<< this->GetClassName()
                    << " needs OpenGL 3.3 or ARB_sampler_objects to read shadow-map depths: "
                       "drawing without its shadows.");
      this->SamplersReported = true;
    }
    return false;
  }
  if (traits.FloatCubeMaps && this->PackedCubeMaps && !this->PackedReported)
  {
    vtkWarningMacro(<< "PackedCubeMaps: " << this->GetClassName()
                    << " reads float cube maps; drawing those.");
    this->PackedReported = true;
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkSoftShadowPass::GetLightSpaceLookupCode()
{
  return std::string(vtkShadowNormalOffsetFS) + "\n" + vtkShadowCubeLookupFS + "\n";
}

//------------------------------------------------------------------------------
bool vtkSoftShadowPass::IsFirstPointLight(int slot) const
{
  const auto& lights = this->Maps->GetLights();
  return lights[slot].Point &&
    std::none_of(lights.begin(), lights.begin() + slot,
      [](const vtkShadowMapManager::Light& l) { return l.Point; });
}

//------------------------------------------------------------------------------
std::string vtkSoftShadowPass::GetDefaultVisibility(int slot) const
{
  const std::string hard = this->GetHardVisibility(slot);
  return this->FrameTraits.ScreenSpace
    ? "vtkShadowScreenVisibility(vtkShadowScreen[" + std::to_string(slot) + "], " + hard + ")"
    : hard;
}

//------------------------------------------------------------------------------
std::string vtkSoftShadowPass::GetHardVisibility(int slot) const
{
  const auto& light = this->Maps->GetLights()[slot];
  const std::string m = std::to_string(light.MapIndex);
  return light.Point
    ? std::string(this->IsFirstPointLight(slot) ? "vtkShadowCubeHardAll" : "vtkShadowCubeHardOf") +
      "(vtkShadowPositionWC, vtkShadowNormalWC, " + m + ")"
    : this->GetHardLookupExpression(slot, "vtkShadowMap[" + m + "]");
}

//------------------------------------------------------------------------------
std::string vtkSoftShadowPass::GetHardLookupExpression(int slot, const std::string& map) const
{
  const auto& light = this->Maps->GetLights()[slot];
  const std::string i = std::to_string(slot);
  if (light.Point)
  {
    const std::string m = std::to_string(light.MapIndex);
    return "vtkShadowCubeLookup(" + map + ", vtkShadowCubeCenter[" + m +
      "], vtkShadowPositionWC, vtkShadowNormalWC, vtkShadowCubeTexel, vtkShadowNormalBias, "
      "vtkShadowDistanceBias, vtkShadowCubeRange[" +
      m + "], vtkShadowPCFRadius)";
  }
  return "vtkShadowLookup(" + map + ", vtkShadowWorldToMap[" + i + "], vtkShadowReceiver(" + i +
    ", vtkShadowPositionWC, vtkShadowNormalWC), vtkShadowPCFRadius)";
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->Maps->ReleaseGraphicsResources(w);
  this->Screen->ReleaseGraphicsResources(w);
  this->Drawer->ReleaseGraphicsResources(w);
  this->LightSpaceTimer.ReleaseGraphicsResources();
  this->ScreenSpaceTimer.ReleaseGraphicsResources();
  this->ReceiversTimer.ReleaseGraphicsResources();
  this->TechniqueTimer.ReleaseGraphicsResources();
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
}

//------------------------------------------------------------------------------
void vtkSoftShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MapSize: " << this->MapSize << "\n";
  os << indent << "SlopeScaledBias: " << this->SlopeScaledBias << "\n";
  os << indent << "ConstantBias: " << this->ConstantBias << "\n";
  os << indent << "NormalBias: " << this->NormalBias << "\n";
  os << indent << "DistanceBias: " << this->DistanceBias << "\n";
  os << indent << "SinglePassCubeMaps: " << this->SinglePassCubeMaps << "\n";
  os << indent << "PackedCubeMaps: " << this->PackedCubeMaps << "\n";
  os << indent << "DepthPrePass: " << this->DepthPrePass << "\n";
  os << indent << "ShadowOnlyLight: " << this->ShadowOnlyLight << "\n";
  os << indent << "ReservedTextureUnits: " << this->ReservedTextureUnits << "\n";
  os << indent << "Controller: " << this->Parallel->GetController() << "\n";
  os << indent << "DelegatePass: ";
  if (this->DelegatePass)
  {
    os << this->DelegatePass->GetClassName() << "\n";
  }
  else
  {
    os << "(none)\n";
  }
}
