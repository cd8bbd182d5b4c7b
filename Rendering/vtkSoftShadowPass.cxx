// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSoftShadowPass.h"

#include "vtkLight.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowCameraStage.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowCompute.h"
#include "vtkShadowDepthStage.h"
#include "vtkShadowDistanceStage.h"
#include "vtkShadowDrawer.h"
#include "vtkShadowLightSize.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowParallelMaps.h"
#include "vtkShadowReceiverStage.h"
#include "vtkShadowSceneDelegate.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkShadowShaderHooks.h"
#include "vtkShadowStage.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"

#include <algorithm>

//------------------------------------------------------------------------------
vtkSoftShadowPass::vtkSoftShadowPass()
  : Casters(new vtkShadowCasterRegistry)
  , Maps(new vtkShadowMapManager)
  , Screen(new vtkShadowScreenBuffers)
  , Drawer(new vtkShadowDrawer(*Casters))
  , DepthStage(new vtkShadowDepthStage)
  , PrePassStage(new vtkShadowDepthStage)
  , DistanceStage(new vtkShadowDistanceStage)
  , CameraStage(new vtkShadowCameraStage)
  , ReceiverStage(new vtkShadowReceiverStage)
  , Parallel(new vtkShadowParallelMaps)
  , Scene(new vtkShadowSceneDelegate)
{
  this->SetDelegatePass(this->Scene->GetDefaultSteps());
  this->PrePassStage->SetLightSpace(false);
  this->Drawer->SetOwner(this); // names the technique in its errors
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
  return this->TextureUnits -
    std::max(this->ReservedTextureUnits, this->ReceiverStage->GetOwnTextures()) -
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
                     "cast on another's receivers are missing or hard. Techniques that draw "
                     "only the framework's depth and distance maps combine all they draw.");
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
  this->ReceiverStage->SetFrame(this->GetReceiverFrame());
  const ReceiverCode& code = this->ReceiverStage->GetFrame().Code;
  for (auto& texture : code.Textures)
  {
    texture.Texture->Activate();
  }

  // Cube maps are looked up across faces: filter across their seams.
  vtkOpenGLState* state =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable seamless(state, GL_TEXTURE_CUBE_MAP_SEAMLESS);
  state->vtkglEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

  // Gerasimov's depth-only pre-pass (section 12.3.4): opaque depth first, so
  // the shading pass runs only on visible fragments.
  std::function<void(const vtkRenderState*)> prePass;
  if (this->DepthPrePass && !shadowed.empty())
  {
    prePass = [this](const vtkRenderState* state) { this->RenderDepthPrePass(state); };
  }
  vtkShadowShaderHooks* hooks = this->Drawer->GetHooks(this->ReceiverStage.get());
  hooks->SetStage(this->ReceiverStage.get());
  hooks->Attach(s);
  this->NumberOfRenderedProps += this->Scene->Render(s, this->DelegatePass, prePass);
  hooks->Detach(s);
  hooks->SetStage(nullptr);
  this->ReceiversDrawn();

  for (auto& texture : code.Textures)
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
vtkShadowReceiverStage::Frame vtkSoftShadowPass::GetReceiverFrame()
{
  vtkShadowReceiverStage::Frame frame;
  frame.Maps = this->Maps.get();
  frame.Screen = this->FrameTraits.ScreenSpace ? this->Screen.get() : nullptr;
  if (!this->Maps->GetLights().empty())
  {
    frame.Code = this->GetReceiverCode();
  }
  frame.DefaultVisibility = [this](int slot) { return this->GetDefaultVisibility(slot); };
  frame.Shading = [this](const vtkShadowShaderSources& sources)
  { return this->GetReceiverShading(sources); };
  frame.ShadingUniforms = [this](vtkShaderProgram* program, vtkProp* prop)
  { this->SetReceiverShadingUniforms(program, prop); };
  frame.Extensions = this->FrameTraits.ReceiverExtensions;
  frame.TextureUnits = this->TextureUnits;
  frame.TexturesPerFrame = this->FrameTraits.ReceiverTexturesPerFrame;
  frame.TexturesPerLight = this->ReceiverTextures();
  frame.MapSize = this->MapSize;
  frame.NormalBias = this->NormalBias;
  frame.DistanceBias = this->DistanceBias;
  frame.PCFRadius = this->GetPCFRadius();
  frame.PCFBilinear = this->GetPCFBilinear();
  frame.PackedCubeMaps = this->DrawsPackedCubeMaps();
  frame.ShadowOnlyLight = this->ShadowOnlyLight;
  frame.Technique = this->GetClassName();
  // GetReceiverShading() depends on the technique's properties.
  frame.ShadingKey = std::to_string(this->GetMTime());
  return frame;
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
vtkOpenGLQuadHelper* vtkSoftShadowPass::GetScreenQuad(const std::string& name,
  const std::function<std::string()>& source, const std::string& variant, bool tiled)
{
  bool failed = false;
  vtkOpenGLQuadHelper* quad = this->Screen->GetQuad(name, variant, source, &failed,
    tiled ? vtkShadowScreenBuffers::Coverage::Tiles : vtkShadowScreenBuffers::Coverage::Screen);
  if (failed)
  {
    vtkErrorMacro("The screen-space pass " << name
                                           << " did not build (the shader log is above): drawing "
                                              "without shadows.");
  }
  return quad;
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
  setup.ClearColours = code.ClearColours;
  setup.Draw = vtkShadowDrawSetup::Props::Camera;
  setup.Stage = this->CameraStage.get();
  this->CameraStage->SetCode(&code, s->GetRenderer());
  const bool drawn = setup.Depth && this->Drawer->Draw(s, setup);
  this->CameraStage->SetCode(nullptr, nullptr);
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
  vtkShadowShaderHooks* hooks = this->Drawer->GetHooks(this->ReceiverStage.get());
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
  return vtkShadowReceiverStage::GetLightSpaceLookupCode();
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
  return "vtkShadowReceiverLookup(" + map + ", " + i +
    ", vtkShadowPositionVC, vtkShadowNormalVC, vtkShadowPCFRadius)";
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
