// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkContactHardeningShadowPass.h"

#include "vtkCamera.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowSampling.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"

#include "vtkContactCoarseFS.h"
#include "vtkContactCommonFS.h"
#include "vtkContactDistanceFS.h"
#include "vtkContactGaussianFS.h"
#include "vtkContactMultiPassFS.h"
#include "vtkContactPCFFS.h"
#include "vtkContactPrepareFS.h"
#include "vtkContactPrepareTexelFS.h"
#include "vtkContactResolveFS.h"
#include "vtkContactTileSpreadFS.h"
#include "vtkContactTilesFS.h"
#include "vtkContactUpsampleFS.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace
{
constexpr int MaximumTaps = 64;
// Pixels (of the distance map) on a side of a classification tile.
constexpr int TileSize = 8;
// Taps count as the same surface within this share of the camera distance
// (vtkContactSameSurface()).
constexpr float DepthTolerance = 0.1f;
// vtkShadowPackTexel() of a texel with no surface: not valid (255), distance 0.
constexpr float NoSurfaceCode = 255.0f * 2048.0f;

// Taps (x, y in [-1,1], weight) with x and y scaled to a kernel `size`
// pixels wide and, when `round`, rounded to whole pixels as the shaders
// fetch them (floor(x + 0.5)).
std::vector<float> ScaledTaps(const std::vector<float>& taps, int size, bool round = true)
{
  std::vector<float> scaled(taps);
  for (size_t i = 0; i + 2 < scaled.size(); i += 3)
  {
    for (size_t k = i; k < i + 2; ++k)
    {
      scaled[k] *= 0.5f * static_cast<float>(size);
      scaled[k] = round ? std::floor(scaled[k] + 0.5f) : scaled[k];
    }
  }
  return scaled;
}
}

class vtkContactHardeningShadowPass::vtkInternals
{
public:
  /// Whether the camera pass writes the codes of the pixels the PCF pass
  /// leaves alone, which then draws only the tiles with work.
  bool CameraCodes = false;
  // This frame's buffer pixel's world size (contactPixelSize), set as its
  // screen-space passes begin, for them and the camera pass.
  float PixelSize = 0.0f;
  // The screen-space passes' constants, and the settings they were made of.
  std::string ConstantsKey;
  std::string Constants;
  // This frame's screen-space passes, kept by the screen buffers.
  vtkOpenGLQuadHelper *Tiles = nullptr, *TileSpread = nullptr, *Prepare = nullptr,
                      *MultiPass = nullptr, *Coarse = nullptr, *PCF = nullptr, *Gaussian = nullptr,
                      *Resolve = nullptr;
  unsigned int Queries[2] = { 0, 0 }; // did the last blur pass draw any pixel?
  size_t CameraPassFirst = 0;         // the first light the camera pass draws
  std::vector<int> CameraPassUnits;   // texture units of its lights' maps
  // Every light's lookup from view coordinates, composed once a camera pass.
  std::vector<vtkShadowMapManager::ViewLookup> CameraPassLookups;
  // See vtkContactPassesFor() in vtkContactDistanceFS.glsl.
  std::vector<float> PassStarts;           // variance before each pass
  std::vector<float> PassInverseVariances; // 1 / each pass's variance
  std::vector<float> FrameTaps;            // this frame's Taps(PoissonTaps)

  // Section 3.1: up to 64 Poisson-disk points in [-1,1]^2, the first at the
  // origin.
  std::vector<glm::vec2> Poisson = vtkShadowSampling::PoissonDisk(MaximumTaps, 7, false, true);

  /// Offsets and normalised Gaussian weights of the first `count` points,
  /// with sigma = size / 3 for offsets scaled by size / 2 (the weights do not
  /// depend on the size).
  std::vector<float> Taps(int count) const
  {
    std::vector<float> taps;
    float total = 0.0f;
    for (int i = 0; i < count; ++i)
    {
      const float r2 = glm::dot(this->Poisson[i], this->Poisson[i]);
      const float w = std::exp(-r2 * 9.0f / 8.0f);
      taps.insert(taps.end(), { this->Poisson[i].x, this->Poisson[i].y, w });
      total += w;
    }
    for (int i = 0; i < count; ++i)
    {
      taps[3 * i + 2] /= total;
    }
    return taps;
  }

  /// A pass over the whole buffer, or with `tiles` only over the tiles
  /// with work (vtkContactTileSpreadFS.glsl).
  void Draw(vtkShadowScreenBuffers* screen, vtkOpenGLQuadHelper* quad, vtkTextureObject* input,
    const std::function<void(vtkShaderProgram*)>& uniforms,
    vtkShadowScreenBuffers::QuadMask mask = vtkShadowScreenBuffers::QuadMask::None,
    float quadDepth = 0.5f, vtkTextureObject* tiles = nullptr)
  {
    if (input)
    {
      input->Activate();
    }
    auto setUniforms = [&](vtkShaderProgram* program)
    {
      if (input)
      {
        program->SetUniformi("contactMap", input->GetTextureUnit());
      }
      program->SetUniformf("contactPixelSize", this->PixelSize);
      uniforms(program);
    };
    if (tiles)
    {
      screen->DrawTiles(quad, tiles, TileSize, setUniforms, mask, quadDepth);
    }
    else
    {
      screen->DrawQuad(quad, setUniforms, mask, quadDepth);
    }
    if (input)
    {
      input->Deactivate();
    }
  }
};

vtkStandardNewMacro(vtkContactHardeningShadowPass);

//------------------------------------------------------------------------------
vtkContactHardeningShadowPass::vtkContactHardeningShadowPass()
  : Internals(new vtkInternals)
{
}

vtkContactHardeningShadowPass::~vtkContactHardeningShadowPass() = default;

//------------------------------------------------------------------------------
int vtkContactHardeningShadowPass::KernelSize(int pass) const
{
  return this->GrowingKernel ? std::min(this->MinimumKernelSize + 2 * pass, this->MaximumKernelSize)
                             : this->MaximumKernelSize;
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::Traits vtkContactHardeningShadowPass::GetTraits() const
{
  Traits traits;
  traits.PointLights = true;
  traits.Samplers = true; // the distance map reads the light's depths raw
  traits.ScreenSpace = true;
  traits.ScreenResolutionDivisor = this->ResolutionDivisor;
  return traits;
}

//------------------------------------------------------------------------------
vtkSoftShadowPass::ReceiverCode vtkContactHardeningShadowPass::GetReceiverCode()
{
  // The screen-space visibility upsampled, guided by each fragment's own
  // hard shadow; with RefineUnresolved what it could not resolve is
  // filtered again in light space (vtkContactUpsampleFS.glsl).
  ReceiverCode code;
  const bool refine = this->RefineUnresolved;
  code.Declarations =
    std::string("#define CONTACT_REFINE ") + (refine ? "1\n" : "0\n") + vtkContactUpsampleFS;
  if (refine)
  {
    code.Setup = "  vtkContactScreenSetup(vtkShadowPositionVC);\n";
  }
  code.Visibility = [this, refine](int slot)
  {
    const auto& light = this->Maps->GetLights()[slot];
    const std::string i = std::to_string(slot);
    const std::string m = std::to_string(light.MapIndex);
    const std::string screen = "vtkContactScreenVisibility(vtkShadowScreen[" + i + "], " +
      this->GetHardVisibility(slot) + ")";
    if (!refine)
    {
      return screen;
    }
    return "vtkContactRefine(" + screen + ", " +
      (light.Point ? "vtkShadowCube[" + m + "], vtkShadowCubeCenter[" + m +
            "], vtkShadowCubeRange[" + m + "]"
                   : "vtkShadowMap[" + m + "], " + i) +
      ", vtkShadowPositionWC, vtkShadowNormalWC)";
  };
  return code;
}

//------------------------------------------------------------------------------
bool vtkContactHardeningShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  // Pass 1. Filtered bilinearly for the receivers' own hard shadow (where
  // no blur reaches, its edge is smoothed as `hard`'s is); pass 2 reads raw
  // depths through a nearest sampler.
  return this->RenderLightDepthMaps(s, true);
}

//------------------------------------------------------------------------------
bool vtkContactHardeningShadowPass::RenderScreenSpace(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkInternals& in = *this->Internals;
  // The passes' settings are compiled in, not uniforms: llvmpipe loads a
  // uniform for every fragment and use. A change rebuilds the passes.
  const std::string key = this->ScreenPassConstantsKey();
  if (key != in.ConstantsKey)
  {
    in.ConstantsKey = key;
    in.Constants = this->ScreenPassConstants();
  }
  // A buffer pixel's world size (vtkShadowScreenBuffers::GetPixelFootprint():
  // x + y * camera distance): x with a parallel camera, else y
  // (CONTACT_PARALLEL_CAMERA).
  in.PixelSize = this->Screen->GetPixelFootprint()[this->CameraIsParallel() ? 0 : 1];
  auto withCommon = [&in](const std::string& source)
  { return [&in, source]() { return in.Constants + vtkContactCommonFS + "\n" + source; }; };
  auto settling = [&](const char* source)
  { return withCommon(std::string(vtkContactPrepareTexelFS) + "\n" + source); };
  in.Tiles = this->GetScreenQuad("contact.tiles", withCommon(vtkContactTilesFS), key);
  in.TileSpread =
    this->GetScreenQuad("contact.tilespread", withCommon(vtkContactTileSpreadFS), key);
  // Without points a tile wide, PCF is drawn over every pixel, as for the
  // debug view, with the same result.
  in.CameraCodes =
    this->Variant == PCF && !this->DebugView && this->Screen->SupportsTiles(TileSize);
  in.Prepare = this->GetScreenQuad("contact.prepare", settling(vtkContactPrepareFS), key);
  in.MultiPass = this->GetScreenQuad("contact.multipass", withCommon(vtkContactMultiPassFS), key);
  in.Coarse = this->GetScreenQuad("contact.coarse", withCommon(vtkContactCoarseFS), key);
  in.PCF = this->GetScreenQuad("contact.pcf", settling(vtkContactPCFFS), key, in.CameraCodes);
  in.Gaussian = this->GetScreenQuad("contact.gaussian", withCommon(vtkContactGaussianFS), key);
  in.Resolve = this->GetScreenQuad("contact.resolve", withCommon(vtkContactResolveFS), key);
  if (!in.Tiles || !in.TileSpread || !in.Prepare || !in.MultiPass || !in.Coarse || !in.PCF ||
    !in.Gaussian || !in.Resolve)
  {
    return false;
  }

  // Only the single Gaussian blurs through a second buffer (rows, then
  // columns); only PCF taps a coarse level, and it needs no prepare pass.
  if (this->Variant != Gaussian)
  {
    this->Screen->ReleaseTexture("contact.filter1");
  }
  if (this->Variant != PCF)
  {
    this->Screen->ReleaseTexture("contact.coarse");
  }
  else
  {
    this->Screen->ReleaseTexture("contact.filter0");
    this->Screen->ReleaseTexture("contact.mask");
  }

  // Blur variances add: the variance before each pass, and each pass's, of
  // the taps as the pass fetches them (whole pixels).
  in.FrameTaps = in.Taps(this->PoissonTaps);
  in.PassStarts.clear();
  in.PassInverseVariances.clear();
  float variance = 0.0f;
  for (int pass = 0; pass < this->PassLimit; ++pass)
  {
    const std::vector<float> taps = ScaledTaps(in.FrameTaps, this->KernelSize(pass));
    float own = 0.0f; // per axis
    for (size_t i = 0; i + 2 < taps.size(); i += 3)
    {
      own += taps[i + 2] * 0.5f * (taps[i] * taps[i] + taps[i + 1] * taps[i + 1]);
    }
    own = std::max(own, 1.0e-3f);
    in.PassStarts.push_back(variance);
    in.PassInverseVariances.push_back(1.0f / own);
    variance += own;
  }

  // Pass 2 for as many lights at a time as a pass has colour targets, drawn
  // with the camera depth; then each light's filtering. The pass's targets:
  // the lights' distance maps, then with CameraCodes their receivers'
  // textures.
  const auto& lights = this->Maps->GetLights();
  const size_t targetsPerLight = in.CameraCodes ? 2 : 1;
  const size_t lightsPerPass = std::max<size_t>(1,
    std::min(
      lights.size(), static_cast<size_t>(this->Screen->GetMaximumTargets()) / targetsPerLight));
  for (size_t first = 0; first < lights.size(); first += lightsPerPass)
  {
    const size_t count = std::min(lightsPerPass, lights.size() - first);
    std::vector<vtkTextureObject*> targets;
    for (size_t k = 0; k < count; ++k)
    {
      targets.push_back(this->Screen->GetTexture("contact.distance" + std::to_string(k), 4));
    }
    for (size_t k = 0; in.CameraCodes && k < count; ++k)
    {
      targets.push_back(this->Screen->GetPacked(static_cast<int>(first + k)));
    }
    if (!this->RenderDistanceMaps(s, first, count, targets))
    {
      return false;
    }
    for (size_t k = 0; k < count; ++k)
    {
      this->FilterDistanceMap(context, static_cast<int>(first + k), targets[k]);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkContactHardeningShadowPass::RenderDistanceMaps(const vtkRenderState* s, size_t first,
  size_t count, const std::vector<vtkTextureObject*>& targets)
{
  vtkInternals& in = *this->Internals;
  const auto& lights = this->Maps->GetLights();
  in.CameraPassFirst = first;
  in.CameraPassUnits.clear();
  in.CameraPassLookups = this->Maps->GetViewLookups(this->MapSize, this->NormalBias);
  // 2D maps are read through the non-comparing sampler; cube maps hold
  // distances already.
  std::vector<vtkShadowScreenBuffers::Sampler> maps;
  maps.reserve(count);
  for (size_t k = 0; k < count; ++k)
  {
    const auto& light = lights[first + k];
    if (light.Point)
    {
      light.CubeMap->Activate();
    }
    else
    {
      maps.emplace_back(
        this->Screen.get(), light.DepthMap, vtkShadowScreenBuffers::Sampler::Reading::RawDepth);
    }
    in.CameraPassUnits.push_back((light.Point ? light.CubeMap : light.DepthMap)->GetTextureUnit());
  }
  // The background reads lit (r = 1, b = 0): no blur counts it
  // (vtkContactSameSurface()), and the tiles then find no shadow to dilate
  // where a surface meets it. Its code is that of no surface.
  CameraPassCode code{ this->DistanceMapDeclarations(), this->DistanceMapImplementation(),
    [this](vtkShaderProgram* program) { this->SetDistanceMapUniforms(program); }, {} };
  code.ClearColours.assign(count, { 1.0f, 0.0f, 0.0f, 0.0f });
  code.ClearColours.resize(targets.size(), { NoSurfaceCode, 0.0f, 0.0f, 0.0f });
  const bool ok = this->RenderCameraDepth(s, targets, code);
  maps.clear();
  for (size_t k = 0; k < count; ++k)
  {
    if (lights[first + k].Point)
    {
      lights[first + k].CubeMap->Deactivate();
    }
  }
  in.CameraPassUnits.clear();
  in.CameraPassLookups.clear();
  return ok;
}

//------------------------------------------------------------------------------
std::string vtkContactHardeningShadowPass::DistanceMapDeclarations() const
{
  const vtkInternals& in = *this->Internals;
  const auto& lights = this->Maps->GetLights();
  int maps = 0, cubes = 0;
  for (size_t k = 0; k < in.CameraPassUnits.size(); ++k)
  {
    ++(lights[in.CameraPassFirst + k].Point ? cubes : maps);
  }
  std::ostringstream dec;
  dec << "#define CONTACT_LIGHTS " << in.CameraPassUnits.size() << "\n"
      << "#define CONTACT_MAPS " << maps << "\n"
      << "#define CONTACT_CUBES " << cubes << "\n"
      << "#define CONTACT_LIGHT_SIZE " << (this->UseLightSize ? 1 : 0) << "\n"
      << "#define CONTACT_PARALLEL_CAMERA " << (this->CameraIsParallel() ? 1 : 0) << "\n"
      << "#define CONTACT_COUNT_PASSES " << (this->Variant == MultiPass ? 1 : 0) << "\n"
      << "#define CONTACT_PASS_LIMIT " << this->PassLimit << "\n"
      << "#define CONTACT_CODES " << (in.CameraCodes ? 1 : 0) << "\n";
  if (in.CameraCodes)
  {
    dec << vtkShadowScreenBuffers::GetCodeDeclarations() << "\n";
  }
  if (this->UseLightSize && this->Variant == MultiPass)
  {
    // Exact: 9 significant digits round-trip a float.
    dec << std::scientific << std::setprecision(9);
    auto constants = [&](const char* name, const std::vector<float>& values)
    {
      dec << "const float " << name << "[" << values.size() << "] = float[](";
      for (size_t k = 0; k < values.size(); ++k)
      {
        dec << (k > 0 ? ", " : "") << values[k];
      }
      dec << ");\n";
    };
    constants("contactPassStarts", in.PassStarts);
    constants("contactPassInverseVariances", in.PassInverseVariances);
  }
  dec << vtkSoftShadowPass::GetLightSpaceLookupCode() << vtkContactDistanceFS << "\n";
  return dec.str();
}

//------------------------------------------------------------------------------
std::string vtkContactHardeningShadowPass::DistanceMapImplementation() const
{
  const vtkInternals& in = *this->Internals;
  const auto& lights = this->Maps->GetLights();
  std::ostringstream impl;
  impl << "  vtkContactCameraSetup(vtkShadowPositionVC);\n";
  const size_t count = in.CameraPassUnits.size();
  int maps = 0, cubes = 0;
  for (size_t k = 0; k < count; ++k)
  {
    const auto& light = lights[in.CameraPassFirst + k];
    impl << "  vec4 contactTexel" << k << " = vtkContactDistance(";
    if (light.Point)
    {
      impl << "contactLightCube[" << cubes++ << "], " << k
           << ", vtkShadowPositionWC, vtkShadowNormalWC);\n";
    }
    else
    {
      // Perspective (spot) or parallel (directional) map, compiled in.
      impl << "contactLightDepth[" << maps++ << "], " << k << ", "
           << (light.Directional ? "false" : "true")
           << ", vtkShadowPositionVC, vtkShadowNormalVC);\n";
    }
    impl << "  gl_FragData[" << k << "] = contactTexel" << k << ";\n";
    if (in.CameraCodes)
    {
      impl << "  gl_FragData[" << count + k << "] = vec4(vtkContactSettledCode(contactTexel" << k
           << "));\n";
    }
  }
  return impl.str();
}

//------------------------------------------------------------------------------
bool vtkContactHardeningShadowPass::CameraIsParallel() const
{
  vtkRenderer* renderer = this->Maps->GetRenderer();
  return renderer && renderer->GetActiveCamera()->GetParallelProjection() != 0;
}

//------------------------------------------------------------------------------
std::string vtkContactHardeningShadowPass::ScreenPassConstantsKey() const
{
  std::ostringstream key;
  key << this->Variant << ' ' << this->DebugView << ' ' << this->MaximumKernelSize << ' '
      << this->UmbraEarlyOut << ' ' << this->EarlyOutKernelSize << ' ' << this->Dilation << ' '
      << this->DilationSize << ' ' << this->PoissonTaps << ' ' << this->RefineUnresolved << ' '
      << this->CameraIsParallel();
  return key.str();
}

//------------------------------------------------------------------------------
std::string vtkContactHardeningShadowPass::ScreenPassConstants() const
{
  const vtkInternals& in = *this->Internals;
  // How many tiles a pixel's neighbourhoods reach (vtkContactTileSpreadFS.glsl).
  const int earlyOutReach = this->EarlyOutKernelSize / 2;
  const int dilationReach = (this->DilationSize + 1) / 2;
  // The dilation's first taps, in whole pixels (vtkContactPrepareTexel()).
  const std::vector<float> dilationTaps =
    ScaledTaps(in.Taps(this->PoissonTaps), this->DilationSize);
  const int dilationCount = std::min(this->PoissonTaps, 8);
  auto boolean = [](bool value) { return value ? "true" : "false"; };
  std::ostringstream c;
  // Exact: 9 significant digits round-trip a float.
  c << std::scientific << std::setprecision(9)
    << "const float contactDepthTolerance = " << DepthTolerance << ";\n"
    << "const bool contactDebugView = " << boolean(this->DebugView) << ";\n"
    << "const int contactMaximumKernel = " << this->MaximumKernelSize << ";\n"
    << "const int contactTileSize = " << TileSize << ";\n"
    << "const bool contactEarlyOut = " << boolean(this->UmbraEarlyOut) << ";\n"
    << "const int contactEarlyOutTiles = " << (earlyOutReach + TileSize - 1) / TileSize << ";\n"
    << "const bool contactDilation = " << boolean(this->Dilation) << ";\n"
    << "const int contactDilationTiles = " << (dilationReach + TileSize - 1) / TileSize
    << ";\n"
    // D counts passes (a fraction blends the last in) or kernel pixels.
    << "const float contactSmallestD = " << (this->Variant == MultiPass ? 0.01f : 1.5f) << ";\n"
    << "const bool contactCountsPasses = " << boolean(this->Variant == MultiPass) << ";\n"
    << "#define CONTACT_WIDTHS " << (this->RefineUnresolved ? 1 : 0) << "\n"
    << "#define CONTACT_PARALLEL_CAMERA " << (this->CameraIsParallel() ? 1 : 0) << "\n"
    << "#define CONTACT_DILATION_TAPS " << dilationCount << "\n"
    << "const vec3 contactDilationTaps[" << dilationCount << "] = vec3[](";
  for (int i = 0; i < dilationCount; ++i)
  {
    c << (i > 0 ? ", " : "") << "vec3(" << dilationTaps[3 * i] << ", " << dilationTaps[3 * i + 1]
      << ", " << dilationTaps[3 * i + 2] << ")";
  }
  c << ");\n";
  return c.str();
}

//------------------------------------------------------------------------------
void vtkContactHardeningShadowPass::SetDistanceMapUniforms(vtkShaderProgram* program)
{
  const vtkInternals& in = *this->Internals;
  const auto& lights = this->Maps->GetLights();
  int maps = 0, cubes = 0;
  for (size_t k = 0; k < in.CameraPassUnits.size(); ++k)
  {
    const auto& light = lights[in.CameraPassFirst + k];
    const std::string index = "[" + std::to_string(k) + "]";
    if (light.Point)
    {
      program->SetUniformi(
        ("contactLightCube[" + std::to_string(cubes++) + "]").c_str(), in.CameraPassUnits[k]);
      vtkShadowMapManager::SetCubeUniforms(
        program, "contact", index, light.Faces, this->PackedCubeMaps);
    }
    else
    {
      program->SetUniformi(
        ("contactLightDepth[" + std::to_string(maps++) + "]").c_str(), in.CameraPassUnits[k]);
      vtkShadowMapManager::SetViewLookupUniforms(
        program, "contact", index, in.CameraPassLookups[in.CameraPassFirst + k]);
      // Each kind of map reads one of these (vtkContactDistance()).
      if (light.Directional)
      {
        const double span = light.Map.Far - light.Map.Near;
        const glm::vec2 parallel(span, span * light.GetSize());
        program->SetUniform2f(("contactParallelScale" + index).c_str(), glm::value_ptr(parallel));
      }
      else
      {
        const glm::vec2 range(light.Map.Near, light.Map.Far);
        program->SetUniform2f(("contactDepthRange" + index).c_str(), glm::value_ptr(range));
      }
    }
    program->SetUniformf(("contactLightSize" + index).c_str(), static_cast<float>(light.GetSize()));
  }
  vtkShadowMapManager::SetLookupUniforms(
    program, "contact", this->MapSize, this->NormalBias, this->DistanceBias);
  if (in.CameraCodes)
  {
    this->Screen->SetCodeUniforms(program);
  }
  if (!this->UseLightSize)
  {
    program->SetUniformf("contactDistancePower", static_cast<float>(this->DistancePower));
    program->SetUniformf("contactDistanceMultiplier", static_cast<float>(this->DistanceMultiplier));
    program->SetUniformf("contactResolutionDivisor", static_cast<float>(this->ResolutionDivisor));
    return;
  }
  program->SetUniformf("contactPixelSize", this->Internals->PixelSize);
}

//------------------------------------------------------------------------------
void vtkContactHardeningShadowPass::FilterDistanceMap(
  vtkOpenGLRenderWindow* context, int slot, vtkTextureObject* distance)
{
  vtkInternals& in = *this->Internals;
  vtkShadowScreenBuffers* screen = this->Screen.get();
  const int tilesW = (screen->GetWidth() + TileSize - 1) / TileSize;
  const int tilesH = (screen->GetHeight() + TileSize - 1) / TileSize;
  const std::array<vtkTextureObject*, 2> tiles = { screen->GetTexture(
                                                     "contact.tiles0", 4, tilesW, tilesH),
    screen->GetTexture("contact.tiles1", 4, tilesW, tilesH) };

  vtkOpenGLState* state = context->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  state->vtkglDisable(GL_BLEND);
  state->PushFramebufferBindings();
  // Which tiles the early-out's and the dilation's neighbourhoods find all
  // shadowed, or partly shadowed, and which have any work.
  using Targets = vtkShadowScreenBuffers::Targets;
  {
    Targets bound(screen, { tiles[0] }, nullptr, tilesW, tilesH);
    vtkShadowScreenBuffers::Sampler bilinear(
      screen, distance, vtkShadowScreenBuffers::Sampler::Reading::Bilinear);
    in.Draw(screen, in.Tiles, nullptr,
      [&](vtkShaderProgram* program)
      { program->SetUniformi("contactMap", distance->GetTextureUnit()); });
  }
  {
    Targets bound(screen, { tiles[1] }, nullptr, tilesW, tilesH);
    in.Draw(screen, in.TileSpread, tiles[0], [](vtkShaderProgram*) {});
  }

  // Umbra early-out and pass 3 (vtkContactPrepareTexelFS.glsl): what the
  // passes that settle each pixel's D need.
  tiles[1]->Activate();
  auto settling = [&](vtkShaderProgram* program)
  {
    program->SetUniformi("contactTiles", tiles[1]->GetTextureUnit());
    if (this->RefineUnresolved) // CONTACT_WIDTHS
    {
      // Summed variances of 0 .. 64 passes (those past the limit add none).
      std::vector<float> variances(in.PassStarts);
      variances.push_back(in.PassStarts.back() + 1.0f / in.PassInverseVariances.back());
      variances.resize(65, variances.back());
      program->SetUniform1fv("contactPassVariances", 65, variances.data());
    }
  };
  vtkTextureObject* packed = screen->GetPacked(slot);
  if (this->Variant == PCF)
  {
    this->FilterPCF(distance, tiles[1], packed, settling);
  }
  else
  {
    this->FilterBlurs(distance, packed, settling);
  }
  tiles[1]->Deactivate();
  state->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
void vtkContactHardeningShadowPass::FilterPCF(vtkTextureObject* distance, vtkTextureObject* tiles,
  vtkTextureObject* packed, const std::function<void(vtkShaderProgram*)>& settling)
{
  // The coarse level for the widest discs, then the discs: one pass that
  // settles each pixel's D itself, drawn (but for the debug view, which
  // marks every pixel) only over the tiles with work; the camera pass wrote
  // the other pixels' codes. The early-out and the dilation leave the
  // visibility and the distance as they are, so both passes tap the
  // distance map.
  vtkInternals& in = *this->Internals;
  vtkShadowScreenBuffers* screen = this->Screen.get();
  using Targets = vtkShadowScreenBuffers::Targets;
  const int coarseW = (screen->GetWidth() + 1) / 2;
  const int coarseH = (screen->GetHeight() + 1) / 2;
  vtkTextureObject* coarse = screen->GetTexture("contact.coarse", 4, coarseW, coarseH);
  {
    Targets bound(screen, { coarse }, nullptr, coarseW, coarseH);
    in.Draw(screen, in.Coarse, distance, [](vtkShaderProgram*) {});
  }
  coarse->Activate();
  {
    Targets bound(screen, { packed });
    in.Draw(
      screen, in.PCF, distance,
      [&](vtkShaderProgram* program)
      {
        settling(program);
        program->SetUniformi("contactCoarse", coarse->GetTextureUnit());
      },
      vtkShadowScreenBuffers::QuadMask::None, 0.5f, in.CameraCodes ? tiles : nullptr);
  }
  coarse->Deactivate();
}

//------------------------------------------------------------------------------
void vtkContactHardeningShadowPass::FilterBlurs(vtkTextureObject* distance,
  vtkTextureObject* packed, const std::function<void(vtkShaderProgram*)>& settling)
{
  vtkInternals& in = *this->Internals;
  vtkShadowScreenBuffers* screen = this->Screen.get();
  using Targets = vtkShadowScreenBuffers::Targets;
  const std::vector<float>& taps = in.FrameTaps;
  // The filtering passes' buffers: the prepare pass's target (the multi-pass
  // blur ping-pongs between it and the distance map), the single Gaussian's
  // intermediate, and a depth mask: which blur passes draw a pixel.
  vtkTextureObject* filtered = screen->GetTexture("contact.filter0", 4);
  vtkTextureObject* mask = screen->GetTexture("contact.mask", 0);

  // The ping-pong pair: the prepare pass's target and the distance map,
  // which holds the final value of every pixel no blur touches. The
  // receivers' texture holds codes (vtkShadowPackTexel()): the prepare pass
  // writes every pixel's, and each multi-pass blur those of the pixels it
  // draws, so that a pixel's last pass leaves its final code there without
  // a pass of its own. The Gaussian's last pass writes them all, as does
  // the debug view's, so there the chain writes none.
  const bool chainCodes = this->Variant == MultiPass && !this->DebugView;
  const std::array<vtkTextureObject*, 2> pair = { filtered, distance };
  // A chain target, and the receivers' codes alongside when the chain writes them.
  auto chainTargets = [&](vtkTextureObject* target)
  {
    return chainCodes ? std::vector<vtkTextureObject*>{ target, packed }
                      : std::vector<vtkTextureObject*>{ target };
  };
  // Over every pixel.
  auto toPacked = [&](vtkOpenGLQuadHelper* quad, vtkTextureObject* input,
                    const std::function<void(vtkShaderProgram*)>& uniforms)
  {
    Targets bound(screen, { packed });
    in.Draw(screen, quad, input, uniforms);
  };

  {
    Targets bound(screen, chainTargets(pair[0]), mask);
    in.Draw(screen, in.Prepare, distance, settling, vtkShadowScreenBuffers::QuadMask::Write);
  }

  // Pass 4, then pass 5's visibility.
  if (this->Variant == MultiPass)
  {
    // Pass k draws only the pixels the prepare pass's depth lets through
    // (D > k - 1), and only if pass k - 1 drew any: passes after the
    // widest penumbra's cost nothing. The condition stays on the GPU. A
    // pixel's last blur is followed by a pass that copies it into the
    // other buffer, unless the pass limit comes first; either way the last
    // target, pair[PassLimit % 2], holds every pixel's final value, and so
    // does the receivers' texture.
    if (!in.Queries[0])
    {
      glGenQueries(2, in.Queries);
    }
    for (int pass = 0; pass < this->PassLimit; ++pass)
    {
      const int size = this->KernelSize(pass);
      if (pass > 0)
      {
        glBeginConditionalRender(in.Queries[(pass - 1) % 2], GL_QUERY_WAIT);
      }
      glBeginQuery(GL_SAMPLES_PASSED, in.Queries[pass % 2]);
      {
        Targets bound(screen, chainTargets(pair[(pass + 1) % 2]), mask);
        in.Draw(
          screen, in.MultiPass, pair[pass % 2],
          [&](vtkShaderProgram* program)
          {
            // Unrounded: the shader scales and rounds them.
            const std::vector<float> passTaps = ScaledTaps(taps, size, false);
            program->SetUniform3fv("contactTaps", this->PoissonTaps, passTaps.data());
            program->SetUniformi("contactTapCount", this->PoissonTaps);
            program->SetUniformf("contactKernelSize", static_cast<float>(size));
          },
          vtkShadowScreenBuffers::QuadMask::Test, 1.0f - static_cast<float>(pass) / 256.0f);
      }
      glEndQuery(GL_SAMPLES_PASSED);
      if (pass > 0)
      {
        glEndConditionalRender();
      }
    }
    if (this->DebugView)
    {
      toPacked(in.Resolve, pair[this->PassLimit % 2], [](vtkShaderProgram*) {});
    }
  }
  else if (this->Variant == Gaussian)
  {
    vtkTextureObject* rows = screen->GetTexture("contact.filter1", 4);
    {
      Targets bound(screen, { rows });
      in.Draw(screen, in.Gaussian, filtered,
        [&](vtkShaderProgram* program)
        {
          program->SetUniform2i("contactDirection", std::array<int, 2>{ 1, 0 }.data());
          program->SetUniformi("contactLastPass", 0);
        });
    }
    toPacked(in.Gaussian, rows,
      [&](vtkShaderProgram* program)
      {
        program->SetUniform2i("contactDirection", std::array<int, 2>{ 0, 1 }.data());
        program->SetUniformi("contactLastPass", 1);
      });
  }
}

//------------------------------------------------------------------------------
void vtkContactHardeningShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  vtkInternals& in = *this->Internals;
  if (in.Queries[0])
  {
    glDeleteQueries(2, in.Queries);
    in.Queries[0] = in.Queries[1] = 0;
  }
}

//------------------------------------------------------------------------------
void vtkContactHardeningShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* names[] = { "PCF", "Gaussian", "MultiPass" };
  os << indent << "Variant: " << names[this->Variant] << "\n";
  os << indent << "UseLightSize: " << this->UseLightSize << "\n";
  os << indent << "DistancePower: " << this->DistancePower << "\n";
  os << indent << "DistanceMultiplier: " << this->DistanceMultiplier << "\n";
  os << indent << "PassLimit: " << this->PassLimit << "\n";
  os << indent << "MinimumKernelSize: " << this->MinimumKernelSize << "\n";
  os << indent << "MaximumKernelSize: " << this->MaximumKernelSize << "\n";
  os << indent << "GrowingKernel: " << this->GrowingKernel << "\n";
  os << indent << "PoissonTaps: " << this->PoissonTaps << "\n";
  os << indent << "Dilation: " << this->Dilation << "\n";
  os << indent << "DilationSize: " << this->DilationSize << "\n";
  os << indent << "UmbraEarlyOut: " << this->UmbraEarlyOut << "\n";
  os << indent << "EarlyOutKernelSize: " << this->EarlyOutKernelSize << "\n";
  os << indent << "ResolutionDivisor: " << this->ResolutionDivisor << "\n";
  os << indent << "RefineUnresolved: " << this->RefineUnresolved << "\n";
  os << indent << "DebugView: " << this->DebugView << "\n";
}
