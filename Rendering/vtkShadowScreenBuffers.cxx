// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowScreenBuffers.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowMapManager.h"
#include "vtkShadowMatrices.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"

#include "vtkShadowPackFS.h"
#include "vtkShadowScreenCodeFS.h"
#include "vtkShadowScreenCommonFS.h"
#include "vtkShadowScreenTilesVS.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm> // for std::any_of, std::fill, std::max, std::none_of
#include <cmath>     // for std::log2, std::tan
#include <sstream>
#include <string>

vtkShadowScreenBuffers::vtkShadowScreenBuffers() = default;
vtkShadowScreenBuffers::~vtkShadowScreenBuffers() = default;

//------------------------------------------------------------------------------
bool vtkShadowScreenBuffers::Update(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!context)
  {
    return false;
  }
  if (context != this->Context)
  {
    this->ReleaseGraphicsResources(this->Context);
    this->Context = context;
    // A constant of the context: asked once, not each frame.
    GLfloat range[2] = { 1.0f, 1.0f };
    glGetFloatv(GL_POINT_SIZE_RANGE, range);
    this->MaximumPointSize = range[1];
  }
  renderer->GetTiledSizeAndOrigin(
    this->ViewportSize, this->ViewportSize + 1, this->Origin, this->Origin + 1);
  this->Width = (this->ViewportSize[0] + this->Divisor - 1) / this->Divisor;
  this->Height = (this->ViewportSize[1] + this->Divisor - 1) / this->Divisor;
  this->UpdateLayoutDeclarations();

  if (!this->CameraDepth)
  {
    this->CameraDepth = vtkSmartPointer<vtkTextureObject>::New();
    this->CameraDepth->SetContext(context);
    this->CameraDepth->SetMinificationFilter(vtkTextureObject::Nearest);
    this->CameraDepth->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->CameraDepth->SetWrapS(vtkTextureObject::ClampToEdge);
    this->CameraDepth->SetWrapT(vtkTextureObject::ClampToEdge);
    this->CameraDepth->AllocateDepth(this->Width, this->Height, vtkTextureObject::Float32);
  }
  this->CameraDepth->Resize(this->Width, this->Height);
  for (auto& texture : this->Visibility)
  {
    texture->Resize(this->Width, this->Height);
  }
  for (auto& texture : this->Packed)
  {
    texture->Resize(this->Width, this->Height);
  }
  std::fill(this->Writer.begin(), this->Writer.end(), Written::None);

  // Clip to world for this frame's camera and aspect ratio.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->GetPosition(this->CameraPosition);
  // Packed camera distances: a log scale over the clipping range, with a
  // factor of two to spare either way.
  const double* range = camera->GetClippingRange();
  const double logNear = std::log2(std::max(range[0], 1e-30) * 0.5);
  const double logFar = std::log2(std::max(range[1], range[0] * 1.001) * 2.0);
  this->LogNear = static_cast<float>(logNear);
  this->CodesPerLog = static_cast<float>(2046.0 / (logFar - logNear));
  // A buffer pixel's world size, to turn world lengths into pixels.
  if (camera->GetParallelProjection())
  {
    this->PixelFootprint[0] = static_cast<float>(2.0 * camera->GetParallelScale() / this->Height);
    this->PixelFootprint[1] = 0.0f;
  }
  else
  {
    this->PixelFootprint[0] = 0.0f;
    this->PixelFootprint[1] = static_cast<float>(
      2.0 * std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0) / this->Height);
  }
  vtkNew<vtkMatrix4x4> clipToWorld;
  vtkMatrix4x4::Multiply4x4(
    camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1),
    camera->GetModelViewTransformMatrix(), clipToWorld);
  clipToWorld->Invert();
  const glm::mat4 single(vtkShadowMatrices::FromVTK(clipToWorld));
  std::copy(glm::value_ptr(single), glm::value_ptr(single) + 16, this->ClipToWorld);
  return true;
}

//------------------------------------------------------------------------------
std::unique_ptr<vtkOpenGLQuadHelper> vtkShadowScreenBuffers::CreateQuad(
  vtkOpenGLRenderWindow* context, const std::string& fragmentSource, Coverage coverage) const
{
  std::string fs =
    std::string(vtkShadowScreenCommonFS) + "\n" + vtkShadowScreenCodeFS + "\n" + fragmentSource;
  std::string vs = vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader();
  if (coverage == Coverage::Tiles)
  {
    vtkShaderProgram::Substitute(
      fs, "//VTK::System::Dec", "//VTK::System::Dec\n#define VTK_SHADOW_TILES", false);
    vs = vtkShadowScreenTilesVS;
  }
  return std::unique_ptr<vtkOpenGLQuadHelper>(
    new vtkOpenGLQuadHelper(context, vs.c_str(), fs.c_str(), ""));
}

//------------------------------------------------------------------------------
vtkOpenGLQuadHelper* vtkShadowScreenBuffers::GetQuad(const std::string& name,
  const std::string& variant, const std::function<std::string()>& source, bool* failed,
  Coverage coverage)
{
  auto found = this->Quads.find(name);
  if (found != this->Quads.end() && found->second.Variant == variant &&
    found->second.Covers == coverage)
  {
    return found->second.Quad.get();
  }
  KeptQuad& kept = this->Quads[name];
  kept.Variant = variant;
  kept.Covers = coverage;
  kept.Quad = this->CreateQuad(this->Context, source(), coverage);
  if (!kept.Quad->Program)
  {
    kept.Quad.reset();
    if (failed)
    {
      *failed = true;
    }
  }
  return kept.Quad.get();
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::DrawQuad(vtkOpenGLQuadHelper* quad,
  const std::function<void(vtkShaderProgram*)>& setUniforms, QuadMask mask, float quadDepth)
{
  this->DrawPass(quad->Program, setUniforms, mask, quadDepth, [quad]() { quad->Render(); });
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::DrawTiles(vtkOpenGLQuadHelper* quad, vtkTextureObject* tiles,
  int tileSize, const std::function<void(vtkShaderProgram*)>& setUniforms, QuadMask mask,
  float quadDepth)
{
  // The pass may read the tiles itself, already active.
  const bool active = tiles->GetTextureUnit() >= 0;
  if (!active)
  {
    tiles->Activate();
  }
  this->DrawPass(
    quad->Program,
    [&](vtkShaderProgram* program)
    {
      program->SetUniformi("vtkShadowTiles", tiles->GetTextureUnit());
      program->SetUniformi("vtkShadowTileSize", tileSize);
      const float size[2] = { static_cast<float>(this->Width), static_cast<float>(this->Height) };
      program->SetUniform2f("vtkShadowTileTargetSize", size);
      setUniforms(program);
    },
    mask, quadDepth,
    [&]()
    {
      // A point a tile from gl_VertexID (vtkShadowScreenTilesVS.glsl), no
      // vertex arrays. (vtkOpenGLState does not track the point size mode.)
      if (!this->TilesArray)
      {
        glGenVertexArrays(1, &this->TilesArray);
      }
      const GLboolean pointSize = glIsEnabled(GL_PROGRAM_POINT_SIZE);
      glEnable(GL_PROGRAM_POINT_SIZE);
      glBindVertexArray(this->TilesArray);
      glDrawArrays(GL_POINTS, 0, tiles->GetWidth() * tiles->GetHeight());
      glBindVertexArray(0);
      if (!pointSize)
      {
        glDisable(GL_PROGRAM_POINT_SIZE);
      }
    });
  if (!active)
  {
    tiles->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::DrawPass(vtkShaderProgram* program,
  const std::function<void(vtkShaderProgram*)>& setUniforms, QuadMask mask, float quadDepth,
  const std::function<void()>& draw)
{
  vtkOpenGLState* state = this->Context->GetState();
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  double depthRange[2] = { 0.0, 1.0 };
  switch (mask)
  {
    case QuadMask::None:
      state->vtkglDisable(GL_DEPTH_TEST);
      break;
    case QuadMask::Write: // the shader writes gl_FragDepth
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglDepthFunc(GL_ALWAYS);
      state->vtkglDepthMask(GL_TRUE);
      break;
    case QuadMask::Test: // the quad at quadDepth: pixels stored below it pass
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglDepthFunc(GL_GREATER);
      state->vtkglDepthMask(GL_FALSE);
      // The quad's vertices lie at z = 0: a degenerate depth range puts every
      // fragment at quadDepth. (The state cache does not track depth ranges.)
      glGetDoublev(GL_DEPTH_RANGE, depthRange);
      glDepthRange(quadDepth, quadDepth);
      break;
  }
  this->Context->GetShaderCache()->ReadyShaderProgram(program);
  this->CameraDepth->Activate();
  program->SetUniformi("vtkShadowCameraDepth", this->CameraDepth->GetTextureUnit());
  program->SetUniformMatrix4x4("vtkShadowCameraClipToWorld", this->ClipToWorld);
  program->SetUniform3f("vtkShadowCameraPosition", this->CameraPosition);
  if (program->IsUniformUsed("vtkShadowCodesPerLog"))
  {
    this->SetCodeUniforms(program);
  }
  setUniforms(program);
  draw();
  if (mask == QuadMask::Test)
  {
    glDepthRange(depthRange[0], depthRange[1]);
  }
  this->CameraDepth->Deactivate();
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkTextureObject> vtkShadowScreenBuffers::NewFloatTexture(
  vtkOpenGLRenderWindow* context, int width, int height, int components, const float* data,
  bool linear)
{
  auto texture = vtkSmartPointer<vtkTextureObject>::New();
  texture->SetContext(context);
  const int filter = linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(filter);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  vtkShadowTextureSpec::SetFloatFormat(texture, components);
  if (data)
  {
    texture->Create2DFromRaw(width, height, components, VTK_FLOAT, const_cast<float*>(data));
  }
  else
  {
    texture->Allocate2D(width, height, components, VTK_FLOAT);
  }
  return texture;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkShadowScreenBuffers::GetVisibility(int slot)
{
  while (static_cast<int>(this->Visibility.size()) <= slot)
  {
    this->Visibility.push_back(NewFloatTexture(this->Context, this->Width, this->Height, 4));
  }
  this->MarkWritten(slot, Written::Visibility);
  return this->Visibility[slot];
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkShadowScreenBuffers::GetPacked(int slot)
{
  while (static_cast<int>(this->Packed.size()) <= slot)
  {
    this->Packed.push_back(NewFloatTexture(this->Context, this->Width, this->Height, 1));
  }
  this->MarkWritten(slot, Written::Packed);
  return this->Packed[slot];
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::MarkWritten(int slot, Written writer)
{
  if (static_cast<int>(this->Writer.size()) <= slot)
  {
    this->Writer.resize(slot + 1, Written::None);
  }
  this->Writer[slot] = writer;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkShadowScreenBuffers::GetTexture(
  const std::string& name, int components, int width, int height)
{
  width = width > 0 ? width : this->Width;
  height = height > 0 ? height : this->Height;
  vtkSmartPointer<vtkTextureObject>& texture = this->Textures[name];
  if (!texture)
  {
    if (components > 0)
    {
      texture = NewFloatTexture(this->Context, width, height, components);
    }
    else
    {
      texture = vtkSmartPointer<vtkTextureObject>::New();
      texture->SetContext(this->Context);
      texture->AllocateDepth(width, height, vtkTextureObject::Fixed24);
    }
  }
  texture->Resize(width, height);
  return texture;
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::ReleaseTexture(const std::string& name)
{
  auto it = this->Textures.find(name);
  if (it != this->Textures.end())
  {
    it->second->ReleaseGraphicsResources(this->Context);
    this->Textures.erase(it);
  }
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::BindTargets(
  const std::vector<vtkTextureObject*>& colours, vtkTextureObject* depth, int width, int height)
{
  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(this->Context);
  }
  this->Framebuffer->Bind();
  if (depth)
  {
    this->Framebuffer->AddDepthAttachment(depth);
  }
  const auto count = static_cast<unsigned int>(colours.size());
  for (unsigned int i = 0; i < count; ++i)
  {
    this->Framebuffer->AddColorAttachment(i, colours[i]);
  }
  this->Framebuffer->ActivateDrawBuffers(count);
  this->BoundTargets = count;
  this->BoundDepth = depth != nullptr;
  width = width > 0 ? width : this->Width;
  height = height > 0 ? height : this->Height;
  vtkOpenGLState* state = this->Context->GetState();
  state->vtkglViewport(0, 0, width, height);
  state->vtkglScissor(0, 0, width, height);
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::UnbindTargets()
{
  this->Framebuffer->RemoveColorAttachments(this->BoundTargets);
  if (this->BoundDepth)
  {
    this->Framebuffer->RemoveDepthAttachment();
  }
  this->BoundTargets = 0;
  this->BoundDepth = false;
}

//------------------------------------------------------------------------------
int vtkShadowScreenBuffers::GetMaximumTargets()
{
  if (this->MaximumTargets == 0)
  {
    GLint drawBuffers = 1;
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &drawBuffers);
    this->MaximumTargets = std::max(1, std::min(static_cast<int>(drawBuffers), 8));
  }
  return this->MaximumTargets;
}

//------------------------------------------------------------------------------
bool vtkShadowScreenBuffers::SupportsSamplers() const
{
  return VTK_SHADOW_GL_HAS(VERSION_3_3) || VTK_SHADOW_GL_HAS(ARB_sampler_objects);
}

//------------------------------------------------------------------------------
bool vtkShadowScreenBuffers::SupportsTiles(int tileSize) const
{
  return this->MaximumPointSize >= static_cast<float>(tileSize);
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::CreateSamplers()
{
  if (this->RawDepthSampler)
  {
    return;
  }
  glGenSamplers(1, &this->RawDepthSampler);
  glSamplerParameteri(this->RawDepthSampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  glSamplerParameteri(this->RawDepthSampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(this->RawDepthSampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(this->RawDepthSampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(this->RawDepthSampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glGenSamplers(1, &this->BilinearSampler);
  glSamplerParameteri(this->BilinearSampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(this->BilinearSampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(this->BilinearSampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(this->BilinearSampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

//------------------------------------------------------------------------------
//------------------------------------------------------------------------------
vtkShadowScreenBuffers::Sampler::Sampler(
  vtkShadowScreenBuffers* buffers, vtkTextureObject* texture, Reading reading)
  : Texture(texture)
{
  buffers->CreateSamplers();
  texture->Activate();
  glBindSampler(texture->GetTextureUnit(),
    reading == Reading::RawDepth ? buffers->RawDepthSampler : buffers->BilinearSampler);
}

vtkShadowScreenBuffers::Sampler::Sampler(Sampler&& other) noexcept
  : Texture(other.Texture)
{
  other.Texture = nullptr;
}

vtkShadowScreenBuffers::Sampler::~Sampler()
{
  if (this->Texture)
  {
    glBindSampler(this->Texture->GetTextureUnit(), 0);
    this->Texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
vtkShadowScreenBuffers::Targets::Targets(vtkShadowScreenBuffers* buffers,
  const std::vector<vtkTextureObject*>& colours, vtkTextureObject* depth, int width, int height)
  : Buffers(buffers)
{
  buffers->BindTargets(colours, depth, width, height);
}

vtkShadowScreenBuffers::Targets::~Targets()
{
  this->Buffers->UnbindTargets();
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::BeginVisibility(int slot, float clear)
{
  vtkTextureObject* visibility = this->GetVisibility(slot);
  vtkOpenGLState* state = this->Context->GetState();
  state->PushFramebufferBindings();
  this->BindTargets({ visibility }, nullptr, 0, 0);
  state->vtkglClearColor(clear, 0.0f, 0.0f, 0.0f);
  state->vtkglClear(GL_COLOR_BUFFER_BIT);
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::EndVisibility()
{
  this->UnbindTargets();
  this->Context->GetState()->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
bool vtkShadowScreenBuffers::Pack(int numberOfLights)
{
  if (!(VTK_SHADOW_GL_HAS(VERSION_4_0) || VTK_SHADOW_GL_HAS(ARB_texture_gather)))
  {
    if (!this->GatherReported)
    {
      vtkGenericWarningMacro("Screen-space shadows need OpenGL 4.0 or ARB_texture_gather for "
                             "the receivers' lookup; drawing without shadows.");
      this->GatherReported = true;
    }
    return false;
  }
  if (static_cast<int>(this->Writer.size()) < numberOfLights ||
    std::any_of(this->Writer.begin(), this->Writer.begin() + numberOfLights,
      [](Written w) { return w == Written::None; }))
  {
    vtkGenericWarningMacro("A screen-space technique left a light's visibility unwritten.");
    return false;
  }
  if (std::none_of(this->Writer.begin(), this->Writer.begin() + numberOfLights,
        [](Written w) { return w == Written::Visibility; }))
  {
    return true;
  }
  if (!this->PackQuad)
  {
    this->PackQuad = this->CreateQuad(this->Context, vtkShadowPackFS);
  }
  if (!this->PackQuad->Program)
  {
    return false;
  }
  vtkOpenGLState* state = this->Context->GetState();
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  state->vtkglDisable(GL_BLEND);
  state->PushFramebufferBindings();
  for (int slot = 0; slot < numberOfLights; ++slot)
  {
    if (this->Writer[slot] != Written::Visibility)
    {
      continue;
    }
    Targets bound(this, { this->GetPacked(slot) });
    vtkTextureObject* visibility = this->Visibility[slot];
    visibility->Activate();
    this->DrawQuad(this->PackQuad.get(),
      [&](vtkShaderProgram* program)
      { program->SetUniformi("vtkShadowVisibility", visibility->GetTextureUnit()); });
    visibility->Deactivate();
  }
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
std::string vtkShadowScreenBuffers::GetCodeDeclarations()
{
  return vtkShadowScreenCodeFS;
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::SetCodeUniforms(vtkShaderProgram* program) const
{
  program->SetUniformf("vtkShadowLogNear", this->LogNear);
  program->SetUniformf("vtkShadowCodesPerLog", this->CodesPerLog);
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::ActivateTextures()
{
  for (auto& texture : this->Packed)
  {
    texture->Activate();
  }
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::DeactivateTextures()
{
  for (auto& texture : this->Packed)
  {
    texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::UpdateLayoutDeclarations()
{
  this->LayoutDeclarations.clear();
  if (this->Width * this->Divisor != this->ViewportSize[0] ||
    this->Height * this->Divisor != this->ViewportSize[1])
  {
    return;
  }
  std::ostringstream dec;
  dec << "#define VTK_SHADOW_SCREEN_DIVISOR " << this->Divisor << ".0\n"
      << "#define VTK_SHADOW_SCREEN_ORIGIN vec2(" << this->Origin[0] << ".0, " << this->Origin[1]
      << ".0)\n";
  this->LayoutDeclarations = dec.str();
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::SetUniforms(vtkShaderProgram* program, int numberOfLights) const
{
  float origin[2] = { static_cast<float>(this->Origin[0]), static_cast<float>(this->Origin[1]) };
  program->SetUniform2f("vtkShadowViewportOrigin", origin);
  // Viewport pixels to buffer texels.
  float scale[2] = { static_cast<float>(this->Width) / std::max(this->ViewportSize[0], 1),
    static_cast<float>(this->Height) / std::max(this->ViewportSize[1], 1) };
  program->SetUniform2f("vtkShadowScreenScale", scale);
  program->SetUniform2f("vtkShadowTexelFootprint", this->PixelFootprint);
  this->SetCodeUniforms(program);
  for (int i = 0; i < numberOfLights && i < static_cast<int>(this->Packed.size()); ++i)
  {
    const std::string name = "vtkShadowScreen[" + std::to_string(i) + "]";
    program->SetUniformi(name.c_str(), this->Packed[i]->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkShadowScreenBuffers::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->CameraDepth)
  {
    this->CameraDepth->ReleaseGraphicsResources(w);
  }
  for (auto& texture : this->Visibility)
  {
    texture->ReleaseGraphicsResources(w);
  }
  for (auto& texture : this->Packed)
  {
    texture->ReleaseGraphicsResources(w);
  }
  this->Packed.clear();
  for (auto& texture : this->Textures)
  {
    texture.second->ReleaseGraphicsResources(w);
  }
  this->Textures.clear();
  if (this->RawDepthSampler)
  {
    glDeleteSamplers(1, &this->RawDepthSampler);
    glDeleteSamplers(1, &this->BilinearSampler);
    this->RawDepthSampler = this->BilinearSampler = 0;
  }
  if (this->TilesArray)
  {
    glDeleteVertexArrays(1, &this->TilesArray);
    this->TilesArray = 0;
  }
  this->MaximumTargets = 0;
  this->Writer.clear();
  this->PackQuad.reset();
  this->Quads.clear();
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
  }
  this->CameraDepth = nullptr;
  this->Visibility.clear();
  this->Framebuffer = nullptr;
}
