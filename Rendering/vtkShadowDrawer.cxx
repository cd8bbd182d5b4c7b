// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowDrawer.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowGeometry.h"
#include "vtkShadowMapperTwins.h"
#include "vtkShadowMatrices.h"
#include "vtkShadowShaderHooks.h"
#include "vtkShadowStage.h"
#include "vtkShadowVTKVersion.h"
#include "vtkTextureObject.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>

vtkShadowDrawer::vtkShadowDrawer(const vtkShadowCasterRegistry& casters)
  : Casters(casters)
  , Twins(new vtkShadowMapperTwins)
{
}

vtkShadowDrawer::~vtkShadowDrawer() = default;

//------------------------------------------------------------------------------
void vtkShadowDrawer::SetCamera(const vtkShadowDrawSetup::Frustum& frustum)
{
  if (!this->Camera)
  {
    this->Camera = vtkSmartPointer<vtkOpenGLCamera>::New();
  }
  // The explicit projection is the frustum's own: the camera's view angle
  // and aspect then play no part.
  vtkCamera* camera = this->Camera;
  camera->SetPosition(frustum.Eye.x, frustum.Eye.y, frustum.Eye.z);
  const glm::dvec3 focal = frustum.Eye + frustum.Direction;
  camera->SetFocalPoint(focal.x, focal.y, focal.z);
  camera->SetViewUp(frustum.Up.x, frustum.Up.y, frustum.Up.z);
  camera->SetParallelProjection(frustum.Parallel);
  camera->SetClippingRange(frustum.Near, frustum.Far);
  vtkNew<vtkMatrix4x4> projection;
  vtkShadowMatrices::ToVTK(frustum.Projection, projection);
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->SetUseExplicitProjectionTransformMatrix(true);
}

//------------------------------------------------------------------------------
bool vtkShadowDrawer::BindLayered(vtkOpenGLRenderWindow* context, vtkTextureObject* cube)
{
  vtkOpenGLState* state = context->GetState();
  const int size = static_cast<int>(cube->GetWidth());
  if (this->LayeredContext != context)
  {
    this->LayeredFramebuffer = 0;
    this->LayeredDepth = 0;
    this->LayeredContext = context;
  }
  if (!this->LayeredFramebuffer)
  {
    glGenFramebuffers(1, &this->LayeredFramebuffer);
  }
  if (!this->LayeredDepth || this->LayeredDepthSize != size)
  {
    if (!this->LayeredDepth)
    {
      glGenTextures(1, &this->LayeredDepth);
    }
    glBindTexture(GL_TEXTURE_CUBE_MAP, this->LayeredDepth);
    for (int f = 0; f < 6; ++f)
    {
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_DEPTH_COMPONENT32F, size, size, 0,
        GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    this->LayeredDepthSize = size;
  }
  state->vtkglBindFramebuffer(GL_FRAMEBUFFER, this->LayeredFramebuffer);
  glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, cube->GetHandle(), 0);
  glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, this->LayeredDepth, 0);
  state->vtkglDrawBuffer(GL_COLOR_ATTACHMENT0);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
  {
    vtkGenericWarningMacro("Layered cube-map framebuffer incomplete: no point-light shadows.");
    glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0);
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, 0, 0);
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowDrawer::BindTarget(
  vtkOpenGLRenderWindow* context, const vtkShadowDrawSetup& setup, int& width, int& height)
{
  vtkTextureObject* first = !setup.Colours.empty() ? setup.Colours[0] : setup.Depth;
  if (!first)
  {
    vtkGenericWarningMacro("vtkShadowDrawer: a draw without a target.");
    return false;
  }
  width = static_cast<int>(first->GetWidth());
  height = static_cast<int>(first->GetHeight());
  if (setup.Faces && setup.CubeFace < 0)
  {
    return this->BindLayered(context, setup.Colours[0]);
  }

  if (!this->Framebuffer)
  {
    this->Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->Framebuffer->SetContext(context);
  }
  vtkTextureObject* depth = setup.Depth;
  if (!depth)
  {
    if (!this->ScratchDepth || this->ScratchDepth->GetContext() != context)
    {
      this->ScratchDepth = vtkSmartPointer<vtkTextureObject>::New();
      this->ScratchDepth->SetContext(context);
      this->ScratchDepth->AllocateDepth(width, height, vtkTextureObject::Float32);
    }
    this->ScratchDepth->Resize(width, height);
    depth = this->ScratchDepth;
  }
  this->Framebuffer->Bind();
  const auto colours = static_cast<unsigned int>(setup.Colours.size());
  const unsigned int face =
    setup.Faces ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<unsigned int>(setup.CubeFace) : 0;
  for (unsigned int i = 0; i < colours; ++i)
  {
    this->Framebuffer->AddColorAttachment(i, setup.Colours[i], 0, face);
  }
  this->Framebuffer->AddDepthAttachment(depth);
  if (colours > 0)
  {
    this->Framebuffer->ActivateDrawBuffers(colours);
  }
  else
  {
    this->Framebuffer->DeactivateDrawBuffers();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowDrawer::UnbindTarget(const vtkShadowDrawSetup& setup)
{
  if (setup.Faces && setup.CubeFace < 0)
  {
    glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, 0, 0);
    glFramebufferTexture(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, 0, 0);
    return;
  }
  this->Framebuffer->RemoveColorAttachments(static_cast<unsigned int>(setup.Colours.size()));
  this->Framebuffer->RemoveDepthAttachment();
}

//------------------------------------------------------------------------------
bool vtkShadowDrawer::Draw(const vtkRenderState* s, const vtkShadowDrawSetup& setup)
{
  vtkRenderer* renderer = s->GetRenderer();
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!context)
  {
    return false;
  }
  vtkOpenGLState* state = context->GetState();
  const bool layered = setup.Faces && setup.CubeFace < 0;
  const vtkShadowDrawSetup::Frustum* frustum =
    setup.Faces ? &(*setup.Faces)[std::max(setup.CubeFace, 0)] : setup.View;

  state->PushFramebufferBindings();
  int width = 0, height = 0;
  if (!this->BindTarget(context, setup, width, height))
  {
    state->PopFramebufferBindings();
    return false;
  }

  // Layered: the vertex shader draws for face 0; the geometry shader takes
  // face 0's clip space to each face's, P V_f V_0^-1 P^-1 (all faces share
  // P and the eye).
  float faceFromFirst[6][16];
  if (layered)
  {
    const auto& faces = *setup.Faces;
    const glm::dmat4 fromFirstClip = glm::inverse(faces[0].Projection * faces[0].View);
    for (int f = 0; f < 6; ++f)
    {
      const glm::mat4 m(faces[f].Projection * faces[f].View * fromFirstClip);
      std::copy(glm::value_ptr(m), glm::value_ptr(m) + 16, faceFromFirst[f]);
    }
  }

  vtkSmartPointer<vtkCamera> viewCamera = renderer->GetActiveCamera();
  if (frustum)
  {
    this->SetCamera(*frustum);
    renderer->SetActiveCamera(this->Camera);
  }

  const bool colour = !setup.Colours.empty();
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglScissor scissorSaver(state);
  vtkOpenGLState::ScopedglEnableDisable scissorTest(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blending(state, GL_BLEND);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglClearColor clearColor(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);

  state->vtkglViewport(0, 0, width, height);
  state->vtkglScissor(0, 0, width, height);
  state->vtkglDisable(GL_SCISSOR_TEST);
  if (setup.DepthTest)
  {
    state->vtkglEnable(GL_DEPTH_TEST);
  }
  else
  {
    state->vtkglDisable(GL_DEPTH_TEST);
  }
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglColorMask(colour, colour, colour, colour);
  state->vtkglClearColor(
    setup.ClearColour[0], setup.ClearColour[1], setup.ClearColour[2], setup.ClearColour[3]);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT | (colour ? GL_COLOR_BUFFER_BIT : 0));
  for (size_t i = 0; colour && i < setup.ClearColours.size() && i < setup.Colours.size(); ++i)
  {
    glClearBufferfv(GL_COLOR, static_cast<GLint>(i), setup.ClearColours[i].data());
  }
  if (setup.Blend == vtkShadowDrawSetup::Blending::None)
  {
    state->vtkglDisable(GL_BLEND);
  }
  else
  {
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFunc(GL_ONE, GL_ONE);
    state->vtkglBlendEquation(setup.Blend == vtkShadowDrawSetup::Blending::Min ? GL_MIN
        : setup.Blend == vtkShadowDrawSetup::Blending::Max                     ? GL_MAX
                                                                               : GL_FUNC_ADD);
  }
  const bool bias = setup.SlopeBias != 0.0 || setup.ConstantBias != 0.0;
  if (bias)
  {
    // vtkOpenGLState does not track polygon offset: set and reset here.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(static_cast<float>(setup.SlopeBias), static_cast<float>(setup.ConstantBias));
  }

  bool ok = true;
  if (setup.Draw != vtkShadowDrawSetup::Props::None && setup.Stage)
  {
    std::vector<vtkProp*> props;
    if (setup.Draw == vtkShadowDrawSetup::Props::Casters)
    {
      props = this->Casters.GetProps();
    }
    else if (setup.Draw == vtkShadowDrawSetup::Props::DepthMapCasters)
    {
      props = this->Casters.GetDepthMapProps();
    }
    else
    {
      props.assign(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
    }
    vtkRenderState drawState(renderer);
    drawState.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
    drawState.SetFrameBuffer(this->Framebuffer);
    setup.Stage->Begin(setup);
    vtkShadowShaderHooks* hooks = this->GetHooks(setup.Stage);
    hooks->SetStage(setup.Stage, layered ? faceFromFirst : nullptr);
    hooks->Attach(&drawState);
    for (vtkProp* prop : props)
    {
      if (!this->Twins->RenderOpaqueGeometry(prop, renderer, setup.Stage))
      {
        prop->RenderOpaqueGeometry(renderer);
      }
    }
    this->Twins->EndDraw();
    hooks->Detach(&drawState);
    hooks->SetStage(nullptr);
    setup.Stage->End();
  }
  if (!setup.Geometry.empty())
  {
    const glm::dmat4 worldToClip = frustum ? frustum->Projection * frustum->View : glm::dmat4(1.0);
    for (const vtkShadowDrawSetup::GeometryDraw& draw : setup.Geometry)
    {
      ok =
        (draw.Placed ? draw.Geometry->Draw(context, worldToClip, draw.ModelToWorld, draw.Uniforms)
                     : draw.Geometry->Draw(context, worldToClip)) &&
        ok;
    }
  }

  if (bias)
  {
    glPolygonOffset(0.0f, 0.0f);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }
  if (setup.Blend != vtkShadowDrawSetup::Blending::None)
  {
    state->vtkglBlendEquation(GL_FUNC_ADD);
  }
  renderer->SetActiveCamera(viewCamera);
  this->UnbindTarget(setup);
  state->PopFramebufferBindings();
  return ok;
}

//------------------------------------------------------------------------------
void vtkShadowDrawer::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->ScratchDepth)
  {
    this->ScratchDepth->ReleaseGraphicsResources(w);
    this->ScratchDepth = nullptr;
  }
  // Raw objects of layered draws: the window's context is current here.
  if (this->LayeredFramebuffer)
  {
    glDeleteFramebuffers(1, &this->LayeredFramebuffer);
    this->LayeredFramebuffer = 0;
  }
  if (this->LayeredDepth)
  {
    glDeleteTextures(1, &this->LayeredDepth);
    this->LayeredDepth = 0;
  }
  this->LayeredContext = nullptr;
  if (this->Framebuffer)
  {
    this->Framebuffer->ReleaseGraphicsResources(w);
    this->Framebuffer = nullptr;
  }
  for (auto& hooks : this->Hooks)
  {
    hooks.second->ReleaseGraphicsResources(w);
  }
  this->Twins->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
vtkShadowShaderHooks* vtkShadowDrawer::GetHooks(vtkShadowStage* stage)
{
  vtkSmartPointer<vtkShadowShaderHooks>& hooks = this->Hooks[stage];
  if (!hooks)
  {
    hooks = vtkSmartPointer<vtkShadowShaderHooks>::New();
    hooks->SetOwner(this->Owner);
  }
  return hooks;
}

//------------------------------------------------------------------------------
void vtkShadowDrawer::SetOwner(vtkObject* owner)
{
  this->Owner = owner;
  for (auto& hooks : this->Hooks)
  {
    hooks.second->SetOwner(owner);
  }
}
