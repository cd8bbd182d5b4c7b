// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowReceiverStage.h"

#include "vtkAbstractMapper.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowMapperCode.h"
#include "vtkShadowMatrices.h"
#include "vtkShadowScreenBuffers.h"
#include "vtkTextureObject.h"

#include "vtkShadowCubeLookupFS.h"
#include "vtkShadowNormalOffsetFS.h"
#include "vtkShadowSurfaceFS.h"
#include "vtkSoftShadowReceiverFS.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <sstream>

namespace
{
std::string Indexed(const char* name, int i)
{
  return std::string(name) + "[" + std::to_string(i) + "]";
}
}

// The camera's and the lights' uniforms, the same for every draw of a frame.
struct vtkShadowReceiverStage::FrameUniforms
{
  glm::mat4 ViewToWorld{ 1.0f };
  std::vector<vtkShadowMapManager::ViewLookup> Lookups; ///< per light slot
};

//------------------------------------------------------------------------------
vtkShadowReceiverStage::vtkShadowReceiverStage()
  : Uniforms(new FrameUniforms)
{
}

//------------------------------------------------------------------------------
vtkShadowReceiverStage::~vtkShadowReceiverStage() = default;

//------------------------------------------------------------------------------
void vtkShadowReceiverStage::SetFrame(Frame frame)
{
  this->Current = std::move(frame);
  FrameUniforms& uniforms = *this->Uniforms;
  uniforms.Lookups.clear();
  const vtkShadowMapManager* maps = this->Current.Maps;
  if (!maps || !maps->GetRenderer())
  {
    return;
  }
  uniforms.ViewToWorld =
    glm::mat4(vtkShadowMatrices::ViewToWorld(maps->GetRenderer()->GetActiveCamera()));
  uniforms.Lookups = maps->GetViewLookups(this->Current.MapSize, this->Current.NormalBias);
}

//------------------------------------------------------------------------------
std::string vtkShadowReceiverStage::GetLightSpaceLookupCode()
{
  return std::string(vtkShadowNormalOffsetFS) + "\n" + vtkShadowCubeLookupFS + "\n";
}

//------------------------------------------------------------------------------
void vtkShadowReceiverStage::PreReplace(vtkShadowShaderSources& sources)
{
  using namespace vtkShadowMapperCode;
  const Frame& frame = this->Current;
  if (frame.Screen)
  {
    // textureGather (vtkShadowScreenCodes) in the mappers' GLSL 1.50.
    sources.AddFragmentExtension("GL_ARB_texture_gather");
  }
  const auto& lights = frame.Maps->GetLights();
  if (std::any_of(
        lights.begin(), lights.end(), [](const vtkShadowMapManager::Light& l) { return l.Point; }))
  {
    // The cube maps' lookups in one loop where it is supported
    // (vtkShadowCubeHardAll, vtkSoftShadowReceiverFS.glsl; omni's Poisson
    // lookup, vtkOmniPoissonAll, needs it).
    sources.AddFragmentExtension("GL_ARB_gpu_shader5");
  }
  for (const std::string& extension : frame.Extensions)
  {
    sources.AddFragmentExtension(extension);
  }
  // Shaders without lighting (no tags) are not shadowed: no word needed.
  vtkShadowShaderSources::Before(sources.Fragment, LightDec, ShadowDec);
  vtkShadowShaderSources::Before(sources.Fragment, LightImpl, ShadowImpl);
  // The technique's vertex code (Frame::Shading), if any.
  vtkShadowShaderSources::Before(sources.Vertex, LightDec, ShadowDec);
  vtkShadowShaderSources::Before(sources.Vertex, LightImpl, ShadowImpl);
}

//------------------------------------------------------------------------------
void vtkShadowReceiverStage::PostReplace(vtkShadowShaderSources& sources)
{
  const Frame& frame = this->Current;
  std::string& fragmentShader = sources.Fragment;
  const auto& lights = frame.Maps->GetLights();
  const bool lit = sources.IsLit();
  if (!lights.empty() && sources.Mapper && sources.Mapper->IsA("vtkVolumeMapper"))
  {
    sources.AddMiss("volumes receive no shadows from " + frame.Technique +
      "; they are drawn as VTK draws them without it");
  }

  // The shadowed lights were chosen to fit beside the pass's reserve of
  // the mappers' own textures; a shader with more of its own shadows the
  // first lights that fit (arrays indexed by slot stay compact), and raises
  // the reserve for the next frames (GetOwnTextures()).
  const int own = lit ? sources.CountTextures() : 0;
  this->OwnTextures = std::max(this->OwnTextures, own);
  const int room = frame.TextureUnits - own - frame.TexturesPerFrame;
  const size_t count =
    std::min(lights.size(), static_cast<size_t>(std::max(room, 0) / frame.TexturesPerLight));
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
        << "#define VTK_SHADOW_PARALLEL bool[](";
    for (size_t slot = 0; slot < count; ++slot)
    {
      dec << (slot > 0 ? ", " : "") << (lights[slot].Directional ? "true" : "false");
    }
    dec << ")\n"
        << "#define VTK_SHADOW_MAPS " << count - cubes << "\n"
        << "#define VTK_SHADOW_CUBES " << cubes << "\n"
        << "#define VTK_SHADOW_PCF_RADIUS " << frame.PCFRadius << "\n"
        << "#define VTK_SHADOW_PCF_BILINEAR " << (frame.PCFBilinear ? 1 : 0) << "\n";
    if (frame.Screen)
    {
      dec << "#define VTK_SHADOW_SCREEN_SPACE\n" << frame.Screen->GetLayoutDeclarations();
    }
    dec << vtkShadowSurfaceFS << "\n"
        << GetLightSpaceLookupCode() << vtkSoftShadowReceiverFS << "\n";
    for (const auto& texture : frame.Code.Textures)
    {
      dec << "uniform " << texture.Sampler << " " << texture.Name << ";\n";
    }
    dec << frame.Code.Declarations << "\n";
    const vtkShadowReceiverShading shading =
      frame.Shading ? frame.Shading(sources) : vtkShadowReceiverShading();
    dec << shading.FragmentDeclarations << "\n";
    vtkShaderProgram::Substitute(
      sources.Vertex, vtkShadowMapperCode::ShadowDec, shading.VertexDeclarations, false);
    vtkShaderProgram::Substitute(
      sources.Vertex, vtkShadowMapperCode::ShadowImpl, shading.VertexImplementation, false);

    impl << sources.GetSurfaceCode();
    if (frame.Screen)
    {
      impl << "  vtkShadowScreenSetup(vtkShadowPositionVC);\n";
    }
    impl << frame.Code.Setup;
    for (size_t slot = 0; slot < count; ++slot)
    {
      const int n = lights[slot].ShaderIndex;
      const int i = static_cast<int>(slot);
      impl << "  float vtkShadowVisibility" << n << " = " << frame.Visibility(i) << ";\n"
           << "  float vtkShadowFactor" << n << " = mix(1.0, vtkShadowVisibility" << n
           << ", vtkShadowAttenuation[" << i << "]);\n";
      if (!vtkShadowMapperCode::ScaleLight(fragmentShader, n, "vtkShadowFactor" + std::to_string(n),
            slot < shading.PhongScales.size() ? shading.PhongScales[slot] : ""))
      {
        unscaled += (unscaled.empty() ? "" : ", ") + std::to_string(n);
      }
      if (lights[slot].SceneIndex == frame.ShadowOnlyLight)
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

  if (frame.ShadowOnlyLight >= 0)
  {
    vtkShaderProgram::Substitute(fragmentShader, vtkShadowMapperCode::LightImpl,
      "gl_FragData[0] = vec4(vec3(" + onlyVisibility + "), 1.0);\n  " +
        vtkShadowMapperCode::LightImpl,
      false);
  }
}

//------------------------------------------------------------------------------
bool vtkShadowReceiverStage::GetCodeKey(std::string& key) const
{
  const Frame& frame = this->Current;
  std::ostringstream k;
  k << (frame.Screen ? 1 : 0) << ' ' << frame.TextureUnits << ' ' << frame.TexturesPerFrame << ' '
    << frame.TexturesPerLight << ' ' << frame.ShadowOnlyLight << ' ' << frame.Technique << ' '
    << frame.ShadingKey << ' ' << frame.PCFRadius << ' ' << frame.PCFBilinear << '\n'
    << (frame.Screen ? frame.Screen->GetLayoutDeclarations() : std::string()) << '\n';
  for (const std::string& extension : frame.Extensions)
  {
    k << extension << ' ';
  }
  const auto& lights = frame.Maps->GetLights();
  for (const auto& light : lights)
  {
    k << light.ShaderIndex << ':' << light.SceneIndex << ':' << light.Point << light.Directional
      << ' ';
  }
  k << '\n' << frame.Code.Declarations << '\n' << frame.Code.Setup << '\n';
  for (const auto& texture : frame.Code.Textures)
  {
    k << texture.Sampler << ' ' << texture.Name << ';';
  }
  for (size_t slot = 0; slot < lights.size(); ++slot)
  {
    k << '\n' << frame.Visibility(static_cast<int>(slot));
  }
  key = k.str();
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowReceiverStage::SetUniforms(vtkShaderProgram* program, vtkProp* prop)
{
  const Frame& frame = this->Current;
  // Only programs with the shadow term; a visibility that does not depend
  // on the position (or only in the shadow-only view) may have left
  // vtkShadowViewToWorld unused, and lookups from view coordinates leave it
  // unused.
  bool receiver = program->IsUniformUsed("vtkShadowViewToWorld") ||
    program->IsUniformUsed("vtkShadowViewToMap[0]") ||
    program->IsUniformUsed("vtkShadowAttenuation[0]");
  for (const auto& texture : frame.Code.Textures)
  {
    receiver = receiver || program->IsUniformUsed(texture.Name.c_str());
  }
  if (!receiver)
  {
    return;
  }
  const FrameUniforms& uniforms = *this->Uniforms;
  program->SetUniformMatrix4x4(
    "vtkShadowViewToWorld", const_cast<float*>(glm::value_ptr(uniforms.ViewToWorld)));
  program->SetUniformf("vtkShadowMapTexel", 1.0f / static_cast<float>(frame.MapSize));
  vtkShadowMapManager::SetLookupUniforms(
    program, "vtkShadow", frame.MapSize, frame.NormalBias, frame.DistanceBias);

  const auto& lights = frame.Maps->GetLights();
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
        "[" + std::to_string(light.MapIndex) + "]", light.Faces, frame.PackedCubeMaps);
      continue;
    }
    const std::string index = "[" + std::to_string(i) + "]";
    vtkShadowMapManager::SetFrustumUniforms(program, "vtkShadow", index, light.Map, frame.MapSize);
    if (slot < uniforms.Lookups.size()) // set with the frame
    {
      vtkShadowMapManager::SetViewLookupUniforms(
        program, "vtkShadow", index, uniforms.Lookups[slot]);
    }
    if (light.DepthMap) // techniques with maps of their own may not draw it
    {
      program->SetUniformi(
        Indexed("vtkShadowMap", light.MapIndex).c_str(), light.DepthMap->GetTextureUnit());
    }
  }
  if (frame.Screen)
  {
    frame.Screen->SetUniforms(program, static_cast<int>(lights.size()));
  }
  for (const auto& texture : frame.Code.Textures)
  {
    program->SetUniformi(texture.Name.c_str(), texture.Texture->GetTextureUnit());
  }
  if (frame.Code.Uniforms)
  {
    frame.Code.Uniforms(program);
  }
  if (frame.ShadingUniforms)
  {
    frame.ShadingUniforms(program, prop);
  }
}
