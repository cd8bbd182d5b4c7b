#include "vtkShadowMapManager.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSoftShadowPass.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace
{
std::array<glm::dvec3, 8> BoxCorners(const double b[6])
{
  std::array<glm::dvec3, 8> corners;
  for (int i = 0; i < 8; ++i)
  {
    corners[i] = glm::dvec3(b[i & 1], b[2 + ((i >> 1) & 1)], b[4 + ((i >> 2) & 1)]);
  }
  return corners;
}

// Any unit vector perpendicular to `dir`, built from the world axis least
// aligned with it so that it is stable while the light moves a little.
glm::dvec3 PerpendicularUp(const glm::dvec3& dir)
{
  glm::dvec3 axis(0.0, 1.0, 0.0);
  if (std::abs(dir.y) > 0.9)
  {
    axis = glm::dvec3(0.0, 0.0, 1.0);
  }
  return glm::normalize(axis - dir * glm::dot(axis, dir));
}

// OpenGL clip space [-1,1]^3 to texture/depth space [0,1]^3.
const glm::dmat4 ClipToMap =
  glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)) * glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
}

//------------------------------------------------------------------------------
vtkShadowMapManager::vtkShadowMapManager()
{
  vtkMath::UninitializeBounds(this->SceneBounds);
}

vtkShadowMapManager::~vtkShadowMapManager() = default;

//------------------------------------------------------------------------------
int vtkShadowMapManager::Update(vtkRenderer* renderer, std::vector<vtkLight*>* unsupported)
{
  this->Renderer = renderer;
  std::vector<Light> previous;
  previous.swap(this->Lights);

  renderer->ComputeVisiblePropBounds(this->SceneBounds);
  if (!vtkMath::AreBoundsInitialized(this->SceneBounds))
  {
    return 0; // nothing to shadow
  }
  if (!std::all_of(
        this->SceneBounds, this->SceneBounds + 6, [](double v) { return std::isfinite(v); }))
  {
    vtkGenericWarningMacro("Scene bounds are not finite (NaN or infinite points in a visible "
                           "prop): no shadows this frame.");
    vtkMath::UninitializeBounds(this->SceneBounds);
    return 0;
  }
  renderer->UpdateLightsGeometryToFollowCamera();

  // Mappers number the lights that are switched on, in collection order.
  int sceneIndex = -1;
  int shaderIndex = -1;
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* source = lights->GetNextLight(it))
  {
    ++sceneIndex;
    if (!source->GetSwitch())
    {
      continue;
    }
    ++shaderIndex;
    if (source->LightTypeIsHeadlight())
    {
      continue; // lights the view direction: casts no visible shadow
    }
    if (source->GetPositional() && source->GetConeAngle() >= 90.0)
    {
      if (unsupported)
      {
        unsupported->push_back(source);
      }
      continue;
    }

    Light light;
    light.Source = source;
    light.SceneIndex = sceneIndex;
    light.ShaderIndex = shaderIndex;
    light.Directional = !source->GetPositional();
    light.Radius = vtkSoftShadowPass::GetRadius(source);
    light.ConeAngle = source->GetConeAngle();
    light.Attenuation = source->GetShadowAttenuation();
    const double* p = source->GetTransformedPosition();
    const double* f = source->GetTransformedFocalPoint();
    light.Position = glm::dvec3(p[0], p[1], p[2]);
    glm::dvec3 axis = glm::dvec3(f[0], f[1], f[2]) - light.Position;
    if (!(glm::length(axis) > 0.0))
    {
      continue; // no direction: position == focal point, or NaN
    }
    light.Direction = glm::normalize(axis);
    light.Map = this->FitFrustum(light, light.Position, light.Direction);

    // Keep last frame's texture for the same slot.
    const size_t slot = this->Lights.size();
    if (slot < previous.size())
    {
      light.DepthMap = previous[slot].DepthMap;
    }
    this->Lights.push_back(light);
  }
  return static_cast<int>(this->Lights.size());
}

//------------------------------------------------------------------------------
vtkShadowMapManager::Frustum vtkShadowMapManager::FitFrustum(
  const Light& light, const glm::dvec3& eye, const glm::dvec3& direction) const
{
  const auto corners = BoxCorners(this->SceneBounds);
  const glm::dvec3 center(0.5 * (this->SceneBounds[0] + this->SceneBounds[1]),
    0.5 * (this->SceneBounds[2] + this->SceneBounds[3]),
    0.5 * (this->SceneBounds[4] + this->SceneBounds[5]));
  const double sceneRadius = std::max(0.5 * glm::length(corners[7] - corners[0]), 1e-6);

  Frustum frustum;
  frustum.Direction = direction;
  frustum.Up = PerpendicularUp(direction);
  frustum.Parallel = light.Directional;

  if (light.Directional)
  {
    // Orthographic box around the scene bounds, seen along the direction.
    frustum.Eye = center - direction * (2.0 * sceneRadius);
    frustum.View = glm::lookAt(frustum.Eye, frustum.Eye + direction, frustum.Up);
    glm::dvec3 lo(VTK_DOUBLE_MAX), hi(-VTK_DOUBLE_MAX);
    for (const auto& c : corners)
    {
      const glm::dvec3 v(frustum.View * glm::dvec4(c, 1.0));
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    // A small margin keeps geometry on the box faces inside the map.
    const double margin = 1e-3 * sceneRadius;
    frustum.Near = -hi.z - margin;
    frustum.Far = -lo.z + margin;
    frustum.Projection = glm::ortho(
      lo.x - margin, hi.x + margin, lo.y - margin, hi.y + margin, frustum.Near, frustum.Far);
    frustum.Footprint = glm::dvec2(std::max(hi.x - lo.x, hi.y - lo.y) + 2.0 * margin, 0.0);
  }
  else
  {
    // Perspective cone of the spot light; depth range fitted to the scene.
    frustum.Eye = eye;
    frustum.View = glm::lookAt(frustum.Eye, frustum.Eye + direction, frustum.Up);
    double nearest = VTK_DOUBLE_MAX, farthest = -VTK_DOUBLE_MAX;
    for (const auto& c : corners)
    {
      const double d = glm::dot(c - eye, direction);
      nearest = std::min(nearest, d);
      farthest = std::max(farthest, d);
    }
    farthest = std::max(farthest, 1e-3 * sceneRadius);
    // Near plane as far out as the scene allows: depth precision.
    frustum.Far = farthest * 1.001;
    frustum.Near = std::max(nearest * 0.999, frustum.Far * 1e-4);
    const double fovy = glm::radians(std::min(2.0 * light.ConeAngle, 179.0));
    frustum.Projection = glm::perspective(fovy, 1.0, frustum.Near, frustum.Far);
    frustum.Footprint = glm::dvec2(0.0, 2.0 * std::tan(0.5 * fovy));
  }
  frustum.WorldToMap = ClipToMap * frustum.Projection * frustum.View;
  return frustum;
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::AllocateDepthMap(
  vtkOpenGLRenderWindow* context, Light& light, int size, bool linear)
{
  vtkTextureObject* map = light.DepthMap;
  const int filter = linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  if (map && map->GetContext() == context && static_cast<int>(map->GetWidth()) == size &&
    map->GetMagnificationFilter() == filter)
  {
    return;
  }
  light.DepthMap = vtkSmartPointer<vtkTextureObject>::New();
  map = light.DepthMap;
  map->SetContext(context);
  map->SetWrapS(vtkTextureObject::ClampToEdge);
  map->SetWrapT(vtkTextureObject::ClampToEdge);
  map->SetMinificationFilter(filter);
  map->SetMagnificationFilter(filter);
  map->SetDepthTextureCompare(true);
  map->SetDepthTextureCompareFunction(vtkTextureObject::Lequal);
  map->AllocateDepth(size, size, vtkTextureObject::Float32);
}

//------------------------------------------------------------------------------
bool vtkShadowMapManager::RenderDepth(const vtkRenderState* s, vtkSoftShadowPass* pass,
  const Frustum& frustum, vtkTextureObject* target)
{
  if (!this->LightCamera)
  {
    this->LightCamera = vtkSmartPointer<vtkOpenGLCamera>::New();
  }
  // The mappers draw with exactly the matrices the receivers look up with:
  // explicit projection, so the window's aspect ratio plays no part.
  vtkCamera* camera = this->LightCamera;
  camera->SetPosition(frustum.Eye.x, frustum.Eye.y, frustum.Eye.z);
  const glm::dvec3 focal = frustum.Eye + frustum.Direction;
  camera->SetFocalPoint(focal.x, focal.y, focal.z);
  camera->SetViewUp(frustum.Up.x, frustum.Up.y, frustum.Up.z);
  camera->SetParallelProjection(frustum.Parallel);
  camera->SetClippingRange(frustum.Near, frustum.Far);
  vtkNew<vtkMatrix4x4> projection;
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      projection->SetElement(row, col, frustum.Projection[col][row]);
    }
  }
  camera->SetExplicitProjectionTransformMatrix(projection);
  camera->SetUseExplicitProjectionTransformMatrix(true);

  vtkRenderer* renderer = s->GetRenderer();
  vtkSmartPointer<vtkCamera> viewCamera = renderer->GetActiveCamera();
  renderer->SetActiveCamera(camera);
  const bool ok = this->DrawDepth(s, pass, target, true, true);
  renderer->SetActiveCamera(viewCamera);
  return ok;
}

//------------------------------------------------------------------------------
bool vtkShadowMapManager::RenderCameraDepth(
  const vtkRenderState* s, vtkSoftShadowPass* pass, vtkTextureObject* target)
{
  return this->DrawDepth(s, pass, target, false, false);
}

//------------------------------------------------------------------------------
bool vtkShadowMapManager::DrawDepth(const vtkRenderState* s, vtkSoftShadowPass* pass,
  vtkTextureObject* target, bool allProps, bool bias)
{
  vtkRenderer* renderer = s->GetRenderer();
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!context || !target)
  {
    return false;
  }
  vtkOpenGLState* state = context->GetState();

  // Shadow casters include props outside the view: they may shadow what is in it.
  std::vector<vtkProp*> props;
  if (allProps)
  {
    vtkCollectionSimpleIterator it;
    vtkPropCollection* viewProps = renderer->GetViewProps();
    viewProps->InitTraversal(it);
    while (vtkProp* prop = viewProps->GetNextProp(it))
    {
      if (prop->GetVisibility())
      {
        props.push_back(prop);
      }
    }
  }
  else
  {
    props.assign(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
  }

  if (!this->DepthFramebuffer)
  {
    this->DepthFramebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->DepthFramebuffer->SetContext(context);
  }
  const int width = static_cast<int>(target->GetWidth());
  const int height = static_cast<int>(target->GetHeight());

  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglScissor scissorSaver(state);
  vtkOpenGLState::ScopedglEnableDisable scissorTest(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglColorMask colorMask(state);

  state->PushFramebufferBindings();
  this->DepthFramebuffer->Bind();
  this->DepthFramebuffer->AddDepthAttachment(target);
  this->DepthFramebuffer->DeactivateDrawBuffers();
  state->vtkglViewport(0, 0, width, height);
  state->vtkglScissor(0, 0, width, height);
  state->vtkglDisable(GL_SCISSOR_TEST);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglClearDepth(1.0);
  state->vtkglClear(GL_DEPTH_BUFFER_BIT);
  if (bias)
  {
    // Slope-scaled bias: acne-free lit surfaces. PCF taps reach (r + 1)
    // texels from the looked-up point (bilinear footprint included), so the
    // slope term grows with the kernel. vtkOpenGLState does not track polygon
    // offset: it is set and reset here directly.
    const double reach = 1.0 + pass->GetPCFRadius();
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(static_cast<float>(pass->GetSlopeScaledBias() * reach),
      static_cast<float>(pass->GetConstantBias()));
  }

  vtkRenderState depthState(renderer);
  depthState.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  depthState.SetFrameBuffer(this->DepthFramebuffer);
  pass->SetStage(vtkSoftShadowPass::Stage::LightDepth);
  pass->PreRender(&depthState);
  for (vtkProp* prop : props)
  {
    prop->RenderOpaqueGeometry(renderer);
  }
  pass->PostRender(&depthState);
  pass->SetStage(vtkSoftShadowPass::Stage::Idle);
  if (bias)
  {
    glPolygonOffset(0.0f, 0.0f);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }

  this->DepthFramebuffer->RemoveDepthAttachment();
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::SetFrustumUniforms(vtkShaderProgram* program, const std::string& prefix,
  const std::string& index, const Frustum& frustum, int mapSize)
{
  const glm::mat4 worldToMap(frustum.WorldToMap);
  const glm::vec4 eye(glm::vec3(frustum.Eye), frustum.Parallel ? 0.0f : 1.0f);
  const glm::vec3 axis(frustum.Direction);
  const glm::vec2 footprint(frustum.Footprint / static_cast<double>(mapSize));
  auto name = [&](const char* what) { return prefix + what + index; };
  program->SetUniformMatrix4x4(
    name("WorldToMap").c_str(), const_cast<float*>(glm::value_ptr(worldToMap)));
  program->SetUniform4f(name("Eye").c_str(), glm::value_ptr(eye));
  program->SetUniform3f(name("Axis").c_str(), glm::value_ptr(axis));
  program->SetUniform2f(name("Footprint").c_str(), glm::value_ptr(footprint));
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::ReleaseGraphicsResources(vtkWindow* w)
{
  for (auto& light : this->Lights)
  {
    if (light.DepthMap)
    {
      light.DepthMap->ReleaseGraphicsResources(w);
    }
  }
  this->Lights.clear();
  if (this->DepthFramebuffer)
  {
    this->DepthFramebuffer->ReleaseGraphicsResources(w);
    this->DepthFramebuffer = nullptr;
  }
}
