// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowMapManager.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkShadowLightSize.h"
#include "vtkShadowMatrices.h"
#include "vtkShadowParallelMaps.h"
#include "vtkShadowVTKVersion.h" // for GL_R32F..., through GLEW or glad
#include "vtkTextureObject.h"

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
double vtkShadowMapManager::Light::GetSize() const
{
  return vtkShadowLightSize::GetWidth(this->Radius, this->Directional);
}

//------------------------------------------------------------------------------
glm::dvec4 vtkShadowMapManager::Light::GetHomogeneous() const
{
  return this->Directional ? glm::dvec4(-this->Map.Direction, 0.0)
                           : glm::dvec4(this->Position, 1.0);
}

//------------------------------------------------------------------------------
double vtkShadowMapManager::Light::GetHalfSize() const
{
  return this->GetSize() / 2.0;
}

//------------------------------------------------------------------------------
int vtkShadowMapManager::Update(vtkRenderer* renderer)
{
  return this->Update(renderer, Budget());
}

//------------------------------------------------------------------------------
int vtkShadowMapManager::Update(
  vtkRenderer* renderer, const Budget& budget, vtkShadowParallelMaps* parallel)
{
  this->Renderer = renderer;
  this->Unshadowed = 0;
  this->SkippedPointLights = 0;
  std::vector<Light> previous;
  previous.swap(this->Lights);

  renderer->ComputeVisiblePropBounds(this->SceneBounds);
  bool finite = std::all_of(
    this->SceneBounds, this->SceneBounds + 6, [](double v) { return std::isfinite(v); });
  if (parallel && parallel->IsParallel())
  {
    finite = parallel->CombineBounds(this->SceneBounds, finite);
  }
  if (finite && !vtkMath::AreBoundsInitialized(this->SceneBounds))
  {
    return 0; // nothing to shadow
  }
  if (!finite)
  {
    vtkGenericWarningMacro("Scene bounds are not finite (NaN or infinite points in a visible "
                           "prop): no shadows this frame.");
    vtkMath::UninitializeBounds(this->SceneBounds);
    return 0;
  }
  renderer->UpdateLightsGeometryToFollowCamera();

  // Mappers number the lights that are switched on, in collection order.
  std::vector<Light> candidates;
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
    Light light;
    light.Source = source;
    light.SceneIndex = sceneIndex;
    light.ShaderIndex = shaderIndex;
    light.Directional = !source->GetPositional();
    light.Radius = vtkShadowLightSize::GetRadius(source);
    light.ConeAngle = source->GetConeAngle();
    light.Attenuation = source->GetShadowAttenuation();
    const double* p = source->GetTransformedPosition();
    const double* f = source->GetTransformedFocalPoint();
    light.Position = glm::dvec3(p[0], p[1], p[2]);
    light.Point = vtkShadowLightSize::IsPointLight(source);
    glm::dvec3 axis = light.Point ? this->SceneCenter() - light.Position
                                  : glm::dvec3(f[0], f[1], f[2]) - light.Position;
    if (light.Point && !(glm::length(axis) > 0.0))
    {
      axis = glm::dvec3(0.0, -1.0, 0.0); // any: it only orients the sampling disc
    }
    if (!(glm::length(axis) > 0.0))
    {
      continue; // no direction: position == focal point, or NaN
    }
    light.Direction = glm::normalize(axis);
    if (light.Point && !budget.PointLights)
    {
      ++this->SkippedPointLights;
      continue;
    }
    candidates.push_back(light);
  }
  this->Choose(candidates, budget);

  for (Light& light : candidates)
  {
    if (light.Point)
    {
      light.Faces = this->CubeFaces(light.Position);
    }
    else
    {
      light.Map = this->FitFrustum(light, light.Position, light.Direction);
    }
    // Keep last frame's textures for the same slot.
    const size_t slot = this->Lights.size();
    if (slot < previous.size())
    {
      light.DepthMap = previous[slot].DepthMap;
      light.CubeMap = previous[slot].CubeMap;
      light.Textures = previous[slot].Textures;
    }
    this->Lights.push_back(light);
  }
  int maps = 0, cubes = 0;
  for (auto& light : this->Lights)
  {
    light.MapIndex = light.Point ? cubes++ : maps++;
  }
  return static_cast<int>(this->Lights.size());
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::Choose(std::vector<Light>& candidates, const Budget& budget)
{
  const int needed = static_cast<int>(candidates.size()) * budget.UnitsPerLight;
  if (budget.TextureUnits < 0 || needed <= budget.TextureUnits)
  {
    return;
  }

  // Brightest first; then nearest the focal point, where the camera looks.
  glm::dvec3 focus = this->SceneCenter();
  if (this->Renderer->IsActiveCameraCreated())
  {
    const double* f = this->Renderer->GetActiveCamera()->GetFocalPoint();
    focus = glm::dvec3(f[0], f[1], f[2]);
  }
  // (NaN keys would break the sort's ordering: they rank last.)
  auto key = [](double v, double otherwise) { return std::isnan(v) ? otherwise : v; };
  std::vector<size_t> order(candidates.size());
  std::vector<double> intensity(candidates.size()), distance(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i)
  {
    const Light& light = candidates[i];
    order[i] = i;
    intensity[i] = key(light.Source->GetIntensity(), -VTK_DOUBLE_MAX);
    distance[i] =
      light.Directional ? 0.0 : key(glm::length(light.Position - focus), VTK_DOUBLE_MAX);
  }
  std::sort(order.begin(), order.end(),
    [&](size_t a, size_t b)
    {
      if (intensity[a] != intensity[b])
      {
        return intensity[a] > intensity[b];
      }
      if (distance[a] != distance[b])
      {
        return distance[a] < distance[b];
      }
      return a < b;
    });
  std::vector<bool> chosen(candidates.size(), false);
  int left = budget.TextureUnits;
  for (size_t i : order)
  {
    if (budget.UnitsPerLight <= left)
    {
      chosen[i] = true;
      left -= budget.UnitsPerLight;
    }
  }
  std::vector<Light> shadowed;
  for (size_t i = 0; i < candidates.size(); ++i)
  {
    if (chosen[i])
    {
      shadowed.push_back(candidates[i]);
    }
  }
  this->Unshadowed = static_cast<int>(candidates.size() - shadowed.size());
  candidates.swap(shadowed);
}

//------------------------------------------------------------------------------
glm::dvec3 vtkShadowMapManager::SceneCenter() const
{
  const double* b = this->SceneBounds;
  return glm::dvec3(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
}

//------------------------------------------------------------------------------
std::array<vtkShadowMapManager::Frustum, 6> vtkShadowMapManager::CubeFaces(
  const glm::dvec3& eye) const
{
  // OpenGL's cube map faces: looking along +x -x +y -y +z -z, with the up
  // vectors that make a lookup by direction land on the texel drawn there.
  static const double axes[6][6] = { { 1, 0, 0, 0, -1, 0 }, { -1, 0, 0, 0, -1, 0 },
    { 0, 1, 0, 0, 0, 1 }, { 0, -1, 0, 0, 0, -1 }, { 0, 0, 1, 0, -1, 0 }, { 0, 0, -1, 0, -1, 0 } };
  double farthest = 0.0;
  for (const auto& c : BoxCorners(this->SceneBounds))
  {
    farthest = std::max(farthest, glm::length(c - eye));
  }
  std::array<Frustum, 6> faces;
  for (int f = 0; f < 6; ++f)
  {
    Frustum& face = faces[f];
    face.Eye = eye;
    face.Direction = glm::dvec3(axes[f][0], axes[f][1], axes[f][2]);
    face.Up = glm::dvec3(axes[f][3], axes[f][4], axes[f][5]);
    face.Far = std::max(farthest * 1.001, 1e-6);
    face.Near = face.Far * 1e-4;
    face.View = glm::lookAt(eye, eye + face.Direction, face.Up);
    face.Projection = glm::perspective(glm::radians(90.0), 1.0, face.Near, face.Far);
    face.WorldToMap = ClipToMap * face.Projection * face.View;
    face.Footprint = glm::dvec2(0.0, 2.0);
  }
  return faces;
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
vtkShadowTextureSpec vtkShadowTextureSpec::DepthMap(bool linear)
{
  vtkShadowTextureSpec spec;
  spec.Type = Format::Depth;
  spec.Linear = linear;
  return spec;
}

//------------------------------------------------------------------------------
vtkShadowTextureSpec vtkShadowTextureSpec::DistanceCube(bool packed)
{
  vtkShadowTextureSpec spec;
  spec.Type = packed ? Format::Byte : Format::Float;
  spec.Components = packed ? 4 : 1;
  spec.Cube = true;
  return spec;
}

//------------------------------------------------------------------------------
void vtkShadowTextureSpec::SetFloatFormat(vtkTextureObject* texture, int components)
{
  static const unsigned int formats[4][2] = { { GL_R32F, GL_RED }, { GL_RG32F, GL_RG },
    { GL_RGB32F, GL_RGB }, { GL_RGBA32F, GL_RGBA } };
  texture->SetInternalFormat(formats[components - 1][0]);
  texture->SetFormat(formats[components - 1][1]);
  texture->SetDataType(GL_FLOAT);
}

//------------------------------------------------------------------------------
bool vtkShadowTextureSpec::operator==(const vtkShadowTextureSpec& other) const
{
  return this->Type == other.Type && this->Components == other.Components &&
    this->Cube == other.Cube && this->Linear == other.Linear && this->Size == other.Size;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkShadowLightTexture::Get() const
{
  return this->Texture;
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::Make(vtkShadowLightTexture& texture, const vtkShadowTextureSpec& spec)
{
  auto* context = vtkOpenGLRenderWindow::SafeDownCast(
    this->Renderer ? this->Renderer->GetRenderWindow() : nullptr);
  const int size = spec.Size > 0 ? spec.Size : this->MapSize;
  if (texture.Texture && texture.Texture->GetContext() == context && texture.Spec == spec &&
    texture.Size == size)
  {
    return;
  }
  texture.Spec = spec;
  texture.Size = size;
  texture.Texture = vtkSmartPointer<vtkTextureObject>::New();
  vtkTextureObject* made = texture.Texture;
  made->SetContext(context);
  made->SetWrapS(vtkTextureObject::ClampToEdge);
  made->SetWrapT(vtkTextureObject::ClampToEdge);
  made->SetWrapR(vtkTextureObject::ClampToEdge);
  const int filter = spec.Linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest;
  made->SetMinificationFilter(filter);
  made->SetMagnificationFilter(filter);
  if (spec.Type == vtkShadowTextureSpec::Format::Depth)
  {
    made->SetDepthTextureCompare(true);
    made->SetDepthTextureCompareFunction(vtkTextureObject::Lequal);
    made->AllocateDepth(size, size, vtkTextureObject::Float32);
    return;
  }
  int type = VTK_UNSIGNED_CHAR;
  if (spec.Type == vtkShadowTextureSpec::Format::Float)
  {
    vtkShadowTextureSpec::SetFloatFormat(made, spec.Components);
    type = VTK_FLOAT;
  }
  if (spec.Cube)
  {
    made->CreateCubeFromRaw(size, size, spec.Components, type, nullptr);
  }
  else
  {
    made->Allocate2D(size, size, spec.Components, type);
  }
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::AllocateCubeMap(Light& light, bool packed)
{
  this->Make(light.CubeMap, vtkShadowTextureSpec::DistanceCube(packed));
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::AllocateDepthMap(Light& light, bool linear)
{
  this->Make(light.DepthMap, vtkShadowTextureSpec::DepthMap(linear));
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkShadowMapManager::GetTexture(
  Light& light, size_t index, const vtkShadowTextureSpec& spec)
{
  if (light.Textures.size() <= index)
  {
    light.Textures.resize(index + 1);
  }
  this->Make(light.Textures[index], spec);
  return light.Textures[index];
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkShadowMapManager::GetScratch(size_t index, const vtkShadowTextureSpec& spec)
{
  if (this->Scratch.size() <= index)
  {
    this->Scratch.resize(index + 1);
  }
  this->Make(this->Scratch[index], spec);
  return this->Scratch[index];
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
vtkShadowMapManager::ViewLookup vtkShadowMapManager::GetViewLookup(const Frustum& frustum,
  int mapSize, double texels, const glm::dmat4& viewToWorld, const glm::dmat4& worldToView)
{
  const glm::dvec4 light = worldToView *
    (frustum.Parallel ? glm::dvec4(-frustum.Direction, 0.0) : glm::dvec4(frustum.Eye, 1.0));
  // A texel's size at p is x + y * dot(p - eye, axis) over mapSize.
  const glm::dvec3 axis(worldToView * glm::dvec4(frustum.Direction, 0.0));
  const glm::dvec3 eye(worldToView * glm::dvec4(frustum.Eye, 1.0));
  const double scale = texels / mapSize;
  const glm::dvec4 offset(scale * frustum.Footprint.y * axis,
    scale * (frustum.Footprint.x - frustum.Footprint.y * glm::dot(axis, eye)));
  ViewLookup lookup;
  lookup.ViewToMap = glm::mat4(frustum.WorldToMap * viewToWorld);
  lookup.Light = glm::vec4(light);
  lookup.Offset = glm::vec4(offset);
  return lookup;
}

//------------------------------------------------------------------------------
std::vector<vtkShadowMapManager::ViewLookup> vtkShadowMapManager::GetViewLookups(
  int mapSize, double texels) const
{
  std::vector<ViewLookup> lookups;
  if (!this->Renderer)
  {
    return lookups;
  }
  const glm::dmat4 worldToView = vtkShadowMatrices::WorldToView(this->Renderer->GetActiveCamera());
  const glm::dmat4 viewToWorld = glm::inverse(worldToView);
  for (const auto& light : this->Lights)
  {
    lookups.push_back(light.Point
        ? ViewLookup()
        : GetViewLookup(light.Map, mapSize, texels, viewToWorld, worldToView));
  }
  return lookups;
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::SetViewLookupUniforms(vtkShaderProgram* program,
  const std::string& prefix, const std::string& index, const ViewLookup& lookup)
{
  auto name = [&](const char* what) { return prefix + what + index; };
  program->SetUniformMatrix4x4(
    name("ViewToMap").c_str(), const_cast<float*>(glm::value_ptr(lookup.ViewToMap)));
  program->SetUniform4f(name("LightVC").c_str(), glm::value_ptr(lookup.Light));
  program->SetUniform4f(name("OffsetVC").c_str(), glm::value_ptr(lookup.Offset));
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::SetCubeUniforms(vtkShaderProgram* program, const std::string& prefix,
  const std::string& index, const std::array<Frustum, 6>& faces, bool packed)
{
  const glm::vec3 center(faces[0].Eye);
  const double far = faces[0].Far;
  program->SetUniform3f((prefix + "CubeCenter" + index).c_str(), glm::value_ptr(center));
  program->SetUniformf(
    (prefix + "CubeRange" + index).c_str(), packed ? static_cast<float>(far * far) : 0.0f);
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::SetLookupUniforms(vtkShaderProgram* program, const std::string& prefix,
  int mapSize, double normalBias, double distanceBias)
{
  program->SetUniformf((prefix + "NormalBias").c_str(), static_cast<float>(normalBias));
  program->SetUniformf((prefix + "CubeTexel").c_str(), 2.0f / static_cast<float>(mapSize));
  program->SetUniformf((prefix + "DistanceBias").c_str(), static_cast<float>(distanceBias));
}

//------------------------------------------------------------------------------
void vtkShadowMapManager::ReleaseGraphicsResources(vtkWindow* w)
{
  auto release = [w](vtkTextureObject* texture)
  {
    if (texture)
    {
      texture->ReleaseGraphicsResources(w);
    }
  };
  for (auto& light : this->Lights)
  {
    release(light.DepthMap);
    release(light.CubeMap);
    for (auto& texture : light.Textures)
    {
      release(texture);
    }
  }
  for (auto& texture : this->Scratch)
  {
    release(texture);
  }
  this->Lights.clear();
  this->Scratch.clear();
}
