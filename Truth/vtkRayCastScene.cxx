// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkRayCastScene.h"

#include "vtkCellArray.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowLightSize.h"
#include "vtkShadowMatrices.h"
#include "vtkTriangleFilter.h"

// Embree 3 (Debian 12) or 4 (Debian 13 on), as CMake found it.
#if SOFTSHADOWS_EMBREE_MAJOR >= 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
// Owning handles of Embree objects.
struct DeviceDeleter
{
  void operator()(RTCDeviceTy* device) const { rtcReleaseDevice(device); }
};
struct SceneDeleter
{
  void operator()(RTCSceneTy* scene) const { rtcReleaseScene(scene); }
};
using Device = std::unique_ptr<RTCDeviceTy, DeviceDeleter>;
using Scene = std::unique_ptr<RTCSceneTy, SceneDeleter>;

// The nearest hit and the any-hit test of one ray. Embree 4 dropped the
// intersection context Embree 3 takes (its arguments are optional there).
void Intersect1(RTCScene scene, RTCRayHit& hit)
{
#if SOFTSHADOWS_EMBREE_MAJOR >= 4
  rtcIntersect1(scene, &hit);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &hit);
#endif
}

void Occluded1(RTCScene scene, RTCRay& ray)
{
#if SOFTSHADOWS_EMBREE_MAJOR >= 4
  rtcOccluded1(scene, &ray);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded1(scene, &context, &ray);
#endif
}

// One actor's (or block's) triangles, in world coordinates.
struct Surface
{
  std::vector<glm::vec3> Points;
  std::vector<unsigned int> Triangles; // three indices each
  bool Opaque = true;
};

// A scene of the surfaces (all, or only the opaque ones); geometry ids are
// indices into `surfaces`.
Scene BuildScene(RTCDevice device, const std::vector<Surface>& surfaces, bool opaqueOnly)
{
  Scene scene(rtcNewScene(device));
  for (size_t i = 0; i < surfaces.size(); ++i)
  {
    const Surface& surface = surfaces[i];
    if (opaqueOnly && !surface.Opaque)
    {
      continue;
    }
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
      RTC_FORMAT_FLOAT3, 3 * sizeof(float), surface.Points.size()));
    for (size_t p = 0; p < surface.Points.size(); ++p)
    {
      points[3 * p] = surface.Points[p].x;
      points[3 * p + 1] = surface.Points[p].y;
      points[3 * p + 2] = surface.Points[p].z;
    }
    auto* triangles =
      static_cast<unsigned int*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
        RTC_FORMAT_UINT3, 3 * sizeof(unsigned int), surface.Triangles.size() / 3));
    std::copy(surface.Triangles.begin(), surface.Triangles.end(), triangles);
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(scene.get(), geometry, static_cast<unsigned int>(i));
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(scene.get());
  return scene;
}
}

struct vtkRayCastScene::Internals
{
  std::vector<Surface> Surfaces;
  Device Embree;
  Scene Visible; // every surface
  Scene Casters; // the opaque ones
};

//------------------------------------------------------------------------------
vtkRayCastScene::vtkRayCastScene()
  : Internal(new Internals)
{
}

vtkRayCastScene::~vtkRayCastScene()
{
  // Scenes before the device that made them.
  this->Internal->Visible.reset();
  this->Internal->Casters.reset();
}

//------------------------------------------------------------------------------
void vtkRayCastScene::AddPolyData(vtkPolyData* data, const glm::dmat4& modelToWorld, bool opaque)
{
  if (!data || data->GetNumberOfPolys() + data->GetNumberOfStrips() == 0)
  {
    return;
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->SetInputData(data);
  triangles->Update();
  vtkPolyData* mesh = triangles->GetOutput();
  Surface surface;
  surface.Opaque = opaque;
  const vtkIdType n = mesh->GetNumberOfPoints();
  surface.Points.resize(static_cast<size_t>(n));
  std::vector<bool> finite(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    const glm::dvec4 world = modelToWorld * glm::dvec4(p[0], p[1], p[2], 1.0);
    surface.Points[i] = glm::vec3(world);
    finite[i] = Castable(world);
  }
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType count;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    if (count == 3 && finite[ids[0]] && finite[ids[1]] && finite[ids[2]])
    {
      for (int k = 0; k < 3; ++k)
      {
        surface.Triangles.push_back(static_cast<unsigned int>(ids[k]));
      }
    }
  }
  if (!surface.Triangles.empty())
  {
    this->Internal->Surfaces.push_back(std::move(surface));
  }
}

//------------------------------------------------------------------------------
void vtkRayCastScene::AddRenderer(vtkRenderer* renderer, double bounds[6])
{
  renderer->ComputeVisiblePropBounds(bounds);
  vtkShadowCasterRegistry casters;
  casters.Update(renderer);
  for (const vtkShadowCaster& caster : casters.GetCasters())
  {
    if (caster.Faces)
    {
      this->AddPolyData(caster.Data, caster.ModelToWorld, true);
    }
  }
  for (const vtkShadowCaster& caster : casters.GetTranslucent())
  {
    if (caster.Faces)
    {
      this->AddPolyData(caster.Data, caster.ModelToWorld, false);
    }
  }
}

//------------------------------------------------------------------------------
bool vtkRayCastScene::Castable(const glm::dvec3& v)
{
  const glm::vec3 single(v);
  return std::isfinite(single.x) && std::isfinite(single.y) && std::isfinite(single.z);
}

//------------------------------------------------------------------------------
bool vtkRayCastScene::Commit(std::string& error)
{
  Internals& in = *this->Internal;
  if (!in.Embree)
  {
    in.Embree.reset(rtcNewDevice(nullptr));
    if (!in.Embree)
    {
      error = "Embree could not create a device (error " +
        std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ").";
      return false;
    }
  }
  in.Visible = BuildScene(in.Embree.get(), in.Surfaces, false);
  in.Casters = BuildScene(in.Embree.get(), in.Surfaces, true);
  return true;
}

//------------------------------------------------------------------------------
bool vtkRayCastScene::Intersect(
  const glm::dvec3& origin, const glm::dvec3& direction, Hit& found) const
{
  if (!Castable(origin) || !Castable(direction))
  {
    return false;
  }
  RTCRayHit hit;
  hit.ray.org_x = static_cast<float>(origin.x);
  hit.ray.org_y = static_cast<float>(origin.y);
  hit.ray.org_z = static_cast<float>(origin.z);
  hit.ray.dir_x = static_cast<float>(direction.x);
  hit.ray.dir_y = static_cast<float>(direction.y);
  hit.ray.dir_z = static_cast<float>(direction.z);
  hit.ray.tnear = 0.0f;
  hit.ray.tfar = std::numeric_limits<float>::infinity();
  hit.ray.mask = 0xFFFFFFFFU;
  hit.ray.flags = 0;
  hit.ray.time = 0.0f;
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  Intersect1(this->Internal->Visible.get(), hit);
  if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
  {
    return false;
  }
  found.Surface = hit.hit.geomID;
  found.Position = origin + static_cast<double>(hit.ray.tfar) * direction;
  const glm::dvec3 n = glm::normalize(glm::dvec3(hit.hit.Ng_x, hit.hit.Ng_y, hit.hit.Ng_z));
  found.Normal = glm::dot(n, direction) > 0.0 ? -n : n; // the side the ray comes from
  return true;
}

//------------------------------------------------------------------------------
bool vtkRayCastScene::MakeLight(vtkLight* source, Light& light, std::string& error)
{
  const double* p = source->GetTransformedPosition();
  const double* f = source->GetTransformedFocalPoint();
  const double radius = vtkShadowLightSize::GetRadius(source);
  light = Light();
  light.Directional = !source->GetPositional();
  light.Position = glm::dvec3(p[0], p[1], p[2]);
  const glm::dvec3 beam = glm::dvec3(f[0], f[1], f[2]) - light.Position;
  if (!Castable(light.Position) || !Castable(beam) || !std::isfinite(radius))
  {
    error = "has a position, focal point or size that is not finite.";
    return false;
  }
  if (light.Directional)
  {
    if (!(glm::length(beam) > 0.0))
    {
      error = "is directional without a direction (position == focal point).";
      return false;
    }
    light.ToLight = -glm::normalize(beam);
    light.Radius = glm::radians(std::min(radius, 89.0));
  }
  else
  {
    light.Radius = radius;
    light.Spot = !vtkShadowLightSize::IsPointLight(source) && glm::length(beam) > 0.0;
    light.Axis = light.Spot ? glm::normalize(beam) : glm::dvec3(0.0);
    light.ConeAngle = glm::radians(source->GetConeAngle());
  }
  return true;
}

//------------------------------------------------------------------------------
vtkRayCastScene::Sight vtkRayCastScene::See(const Light& light, const glm::dvec3& at,
  const glm::dvec3& normal, int strata, const glm::dvec2& jitter, double offset,
  bool twoSided) const
{
  Sight sight;
  // Towards the light's centre: the cone of directions to sample.
  glm::dvec3 toLight = light.ToLight;
  double reach = std::numeric_limits<double>::infinity();
  double spread = light.Radius; // cone half-angle
  if (!light.Directional)
  {
    const glm::dvec3 offsetToLight = light.Position - at;
    const double distance = glm::length(offsetToLight);
    if (!(distance > light.Radius))
    {
      sight.Visible = 1.0; // inside the light
      sight.Facing = 1.0;
      return sight;
    }
    toLight = offsetToLight / distance;
    reach = distance;
    spread = std::asin(light.Radius / distance);
    sight.InCone = !light.Spot || glm::dot(-toLight, light.Axis) >= std::cos(0.9 * light.ConeAngle);
  }
  else
  {
    sight.InCone = true;
  }
  // The side that receives: the normal's, or with two sides the one
  // facing the light's centre.
  const glm::dvec3 n = twoSided && glm::dot(normal, toLight) < 0.0 ? -normal : normal;
  sight.Facing = glm::dot(n, toLight);

  const bool point = light.Radius <= 0.0;
  strata = point ? 1 : strata;
  const bool sided = n != glm::dvec3(0.0);
  glm::dvec3 u, v;
  vtkShadowMatrices::Basis(toLight, u, v);
  const glm::dvec3 start = at + offset * n;
  const double cosSpread = std::cos(spread);
  RTCScene casters = this->Internal->Casters.get();
  int lit = 0;
  for (int sy = 0; sy < strata; ++sy)
  {
    for (int sx = 0; sx < strata; ++sx)
    {
      glm::dvec3 ray = toLight;
      double length = reach;
      if (!point)
      {
        // Uniform over the cone's solid angle: cos(a) uniform in
        // [cos(spread), 1], azimuth uniform.
        const double s = std::fmod((sx + 0.5) / strata + jitter.x, 1.0);
        const double t = std::fmod((sy + 0.5) / strata + jitter.y, 1.0);
        const double cosA = 1.0 - s * (1.0 - cosSpread);
        const double sinA = std::sqrt(std::max(0.0, 1.0 - cosA * cosA));
        const double phi = 2.0 * glm::pi<double>() * t;
        ray = cosA * toLight + sinA * (std::cos(phi) * u + std::sin(phi) * v);
        if (!light.Directional)
        {
          // To the sphere's near side along this direction.
          const double along = reach * cosA;
          const double across = reach * reach - along * along;
          length = along - std::sqrt(std::max(0.0, light.Radius * light.Radius - across));
        }
      }
      if (sided && glm::dot(ray, n) <= 0.0)
      {
        continue; // below the surface: it shadows itself
      }
      if (!Castable(start) || !Castable(ray) || std::isnan(length))
      {
        continue; // no ray Embree can cast: none reaches the light
      }
      RTCRay shadow;
      shadow.org_x = static_cast<float>(start.x);
      shadow.org_y = static_cast<float>(start.y);
      shadow.org_z = static_cast<float>(start.z);
      shadow.dir_x = static_cast<float>(ray.x);
      shadow.dir_y = static_cast<float>(ray.y);
      shadow.dir_z = static_cast<float>(ray.z);
      shadow.tnear = 0.0f;
      shadow.tfar = static_cast<float>(length);
      shadow.mask = 0xFFFFFFFFU;
      shadow.flags = 0;
      shadow.time = 0.0f;
      Occluded1(casters, shadow);
      lit += shadow.tfar >= 0.0f ? 1 : 0; // -inf when occluded
    }
  }
  sight.Visible = static_cast<double>(lit) / static_cast<double>(strata * strata);
  return sight;
}

//------------------------------------------------------------------------------
glm::dvec2 vtkRayCastScene::Jitter(unsigned int index, unsigned int seed)
{
  auto mix = [](uint32_t x)
  {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
  };
  const uint32_t a = mix(index * 2U + seed * 0x9e3779b9U);
  const uint32_t b = mix(a ^ 0x68e31da4U);
  return glm::dvec2(a, b) / 4294967296.0;
}
