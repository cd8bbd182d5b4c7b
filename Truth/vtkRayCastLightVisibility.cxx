// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkRayCastLightVisibility.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkShadowCasterRegistry.h"
#include "vtkShadowLightSize.h"
#include "vtkShadowMatrices.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

// Embree 3 (Debian 12) or 4 (Debian 13 on), as CMake found it.
#if SOFTSHADOWS_EMBREE_MAJOR >= 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

vtkStandardNewMacro(vtkRayCastLightVisibility);

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
void Intersect(RTCScene scene, RTCRayHit& hit)
{
#if SOFTSHADOWS_EMBREE_MAJOR >= 4
  rtcIntersect1(scene, &hit);
#else
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect1(scene, &context, &hit);
#endif
}

void Occluded(RTCScene scene, RTCRay& ray)
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

// The triangles of `data` placed by `modelToWorld`; triangles with a
// non-finite corner are dropped.
void AddPolyData(
  vtkPolyData* data, const glm::dmat4& modelToWorld, bool opaque, std::vector<Surface>& surfaces)
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
    finite[i] = std::isfinite(world.x) && std::isfinite(world.y) && std::isfinite(world.z);
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
    surfaces.push_back(std::move(surface));
  }
}

// The polygons of every caster the registry lists (each polydata block,
// assembly part and composite prop's part its own surface), inputs brought
// up to date by the renderer's bounds.
std::vector<Surface> CollectSurfaces(vtkRenderer* renderer, double bounds[6])
{
  renderer->ComputeVisiblePropBounds(bounds);
  vtkShadowCasterRegistry casters;
  casters.Update(renderer);
  std::vector<Surface> surfaces;
  for (const vtkShadowCaster& caster : casters.GetCasters())
  {
    if (caster.Faces)
    {
      AddPolyData(caster.Data, caster.ModelToWorld, true, surfaces);
    }
  }
  for (const vtkShadowCaster& caster : casters.GetTranslucent())
  {
    if (caster.Faces)
    {
      AddPolyData(caster.Data, caster.ModelToWorld, false, surfaces);
    }
  }
  return surfaces;
}

// A scene of the surfaces (all, or only the opaque ones); geometry ids are
// indices into `surfaces` for the full scene.
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

// A hash of a pixel and the seed, to [0, 1)^2: the pixel's jitter of the
// stratified pattern (a Cranley-Patterson rotation).
glm::dvec2 Jitter(unsigned int pixel, unsigned int seed)
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
  const uint32_t a = mix(pixel * 2U + seed * 0x9e3779b9U);
  const uint32_t b = mix(a ^ 0x68e31da4U);
  return glm::dvec2(a, b) / 4294967296.0;
}

// What the light is, as the shadow rays see it.
struct LightShape
{
  bool Directional = false;
  glm::dvec3 Position{ 0.0 }; // positional lights
  glm::dvec3 ToLight{ 0.0 };  // directional lights: unit vector towards the light
  double Radius = 0.0;        // positional: world units; directional: radians
  bool Spot = false;
  glm::dvec3 Axis{ 0.0 }; // spot: unit direction of the cone
  double ConeAngle = 0.0; // spot: half-angle, radians
};

}

//------------------------------------------------------------------------------
vtkRayCastLightVisibility::vtkRayCastLightVisibility()
{
  this->SetNumberOfInputPorts(0);
}

vtkRayCastLightVisibility::~vtkRayCastLightVisibility() = default;

//------------------------------------------------------------------------------
void vtkRayCastLightVisibility::SetRenderer(vtkRenderer* renderer)
{
  if (this->Renderer != renderer)
  {
    this->Renderer = renderer;
    this->Modified();
  }
}

vtkRenderer* vtkRayCastLightVisibility::GetRenderer() const
{
  return this->Renderer;
}

//------------------------------------------------------------------------------
vtkMTimeType vtkRayCastLightVisibility::GetMTime()
{
  // The scene changes without telling this object: cast again every time.
  vtkMTimeType time = this->Superclass::GetMTime();
  if (this->Renderer)
  {
    time = std::max(time, this->Renderer->GetMTime());
  }
  return time;
}

//------------------------------------------------------------------------------
int vtkRayCastLightVisibility::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Size[0] - 1, 0, this->Size[1] - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkRayCastLightVisibility::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (!this->Renderer)
  {
    vtkErrorMacro(<< "no renderer: SetRenderer() first.");
    return 0;
  }
  if (this->Size[0] < 1 || this->Size[1] < 1)
  {
    vtkErrorMacro(<< "size " << this->Size[0] << " x " << this->Size[1]
                  << " has no pixels: both must be at least 1.");
    return 0;
  }
  vtkLight* source =
    vtkLight::SafeDownCast(this->Renderer->GetLights()->GetItemAsObject(this->LightIndex));
  if (!source)
  {
    vtkErrorMacro(<< "light " << this->LightIndex << " does not exist: the renderer has "
                  << this->Renderer->GetLights()->GetNumberOfItems() << " light(s).");
    return 0;
  }

  LightShape light;
  const double* p = source->GetTransformedPosition();
  const double* f = source->GetTransformedFocalPoint();
  const double radius = vtkShadowLightSize::GetRadius(source);
  light.Directional = !source->GetPositional();
  light.Position = glm::dvec3(p[0], p[1], p[2]);
  const glm::dvec3 beam = glm::dvec3(f[0], f[1], f[2]) - light.Position;
  if (light.Directional)
  {
    if (!(glm::length(beam) > 0.0))
    {
      vtkErrorMacro(<< "light " << this->LightIndex
                    << " is directional without a direction (position == focal point).");
      return 0;
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

  double bounds[6];
  const std::vector<Surface> surfaces = CollectSurfaces(this->Renderer, bounds);
  double extent =
    glm::length(glm::dvec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]));
  extent = bounds[0] <= bounds[1] && std::isfinite(extent) ? extent : 1.0; // none, or NaN points
  // Shadow rays start this far off the surface: above float rounding of
  // the hit, far below any gap a scene means.
  const double offset = 1.0e-5 * extent;

  Device device(rtcNewDevice(nullptr));
  if (!device)
  {
    vtkErrorMacro(<< "Embree could not create a device (error " << rtcGetDeviceError(nullptr)
                  << ").");
    return 0;
  }
  Scene visible = BuildScene(device.get(), surfaces, false);
  Scene casters = BuildScene(device.get(), surfaces, true);

  const int width = this->Size[0];
  const int height = this->Size[1];
  vtkCamera* camera = this->Renderer->GetActiveCamera();
  vtkMatrix4x4* worldToClip = camera->GetCompositeProjectionTransformMatrix(
    static_cast<double>(width) / static_cast<double>(height), -1.0, 1.0);
  const glm::dmat4 clipToWorld = glm::inverse(vtkShadowMatrices::FromVTK(worldToClip));
  auto unproject = [&](double x, double y, double z)
  {
    const glm::dvec4 world = clipToWorld * glm::dvec4(x, y, z, 1.0);
    return glm::dvec3(world) / world.w;
  };

  const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
  std::vector<float> visibility(pixels, 0.0f);
  std::vector<unsigned int> surfaceOf(pixels, RTC_INVALID_GEOMETRY_ID);
  std::vector<glm::dvec3> position(pixels), normal(pixels);
  std::vector<float> facing(pixels, 0.0f), inCone(pixels, 0.0f);

  const bool point = light.Radius <= 0.0;
  const int strata =
    point ? 1 : std::max(1, static_cast<int>(std::lround(std::sqrt(this->Samples))));
  const unsigned int seed = this->Seed;

  // In bands of rows, so that progress is reported from this thread, as
  // VTK's observers expect; each band still runs on every core.
  const vtkIdType bands = std::min<vtkIdType>(height, 32);
  this->UpdateProgress(0.0);
  for (vtkIdType band = 0; band < bands; ++band)
  {
    vtkSMPTools::For(height * band / bands, height * (band + 1) / bands,
      [&](vtkIdType firstRow, vtkIdType lastRow)
      {
        for (vtkIdType y = firstRow; y < lastRow; ++y)
        {
          for (int x = 0; x < width; ++x)
          {
            const size_t index = static_cast<size_t>(y) * width + x;
            // The camera ray through the pixel's centre, from the near plane.
            const double nx = 2.0 * (x + 0.5) / width - 1.0;
            const double ny = 2.0 * (y + 0.5) / height - 1.0;
            const glm::dvec3 origin = unproject(nx, ny, -1.0);
            const glm::dvec3 direction = glm::normalize(unproject(nx, ny, 1.0) - origin);
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
            Intersect(visible.get(), hit);
            if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
            {
              continue;
            }
            const glm::dvec3 at = origin + static_cast<double>(hit.ray.tfar) * direction;
            glm::dvec3 n = glm::normalize(glm::dvec3(hit.hit.Ng_x, hit.hit.Ng_y, hit.hit.Ng_z));
            n = glm::dot(n, direction) > 0.0 ? -n : n; // the side the camera sees
            surfaceOf[index] = hit.hit.geomID;
            position[index] = at;
            normal[index] = n;

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
                visibility[index] = 1.0f; // inside the light
                facing[index] = 1.0f;
                continue;
              }
              toLight = offsetToLight / distance;
              reach = distance;
              spread = std::asin(light.Radius / distance);
              inCone[index] =
                !light.Spot || glm::dot(-toLight, light.Axis) >= std::cos(0.9 * light.ConeAngle)
                ? 1.0f
                : 0.0f;
            }
            else
            {
              inCone[index] = 1.0f;
            }
            facing[index] = static_cast<float>(glm::dot(n, toLight));

            glm::dvec3 u, v;
            vtkShadowMatrices::Basis(toLight, u, v);
            const glm::dvec3 start = at + offset * n;
            const glm::dvec2 jitter = Jitter(static_cast<unsigned int>(index), seed);
            const double cosSpread = std::cos(spread);
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
                if (glm::dot(ray, n) <= 0.0)
                {
                  continue; // below the surface: it shadows itself
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
                Occluded(casters.get(), shadow);
                lit += shadow.tfar >= 0.0f ? 1 : 0; // -inf when occluded
              }
            }
            visibility[index] = static_cast<float>(lit) / static_cast<float>(strata * strata);
          }
        }
      });
    this->UpdateProgress(static_cast<double>(band + 1) / static_cast<double>(bands));
  }

  // SPEC's pixels: front-lit, in the cone, and with four neighbours on the
  // same surface, each within a quarter of their distance of this pixel's
  // tangent plane (a step in depth is a silhouette).
  output->SetExtent(0, width - 1, 0, height - 1, 0, 0);
  vtkNew<vtkFloatArray> visibilityArray;
  visibilityArray->SetName("Visibility");
  visibilityArray->SetNumberOfValues(static_cast<vtkIdType>(pixels));
  vtkNew<vtkUnsignedCharArray> geometryArray;
  geometryArray->SetName("Geometry");
  geometryArray->SetNumberOfValues(static_cast<vtkIdType>(pixels));
  vtkNew<vtkUnsignedCharArray> maskArray;
  maskArray->SetName("QualityMask");
  maskArray->SetNumberOfValues(static_cast<vtkIdType>(pixels));
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const size_t index = static_cast<size_t>(y) * width + x;
      const bool seen = surfaceOf[index] != RTC_INVALID_GEOMETRY_ID;
      bool measured = seen && facing[index] >= 0.1f && inCone[index] > 0.0f && x > 0 && y > 0 &&
        x < width - 1 && y < height - 1;
      const int dx[4] = { 1, -1, 0, 0 };
      const int dy[4] = { 0, 0, 1, -1 };
      for (int k = 0; k < 4 && measured; ++k)
      {
        const size_t other = static_cast<size_t>(y + dy[k]) * width + (x + dx[k]);
        const glm::dvec3 step = position[other] - position[index];
        measured = surfaceOf[other] == surfaceOf[index] &&
          std::abs(glm::dot(step, normal[index])) <= 0.25 * glm::length(step);
      }
      visibilityArray->SetValue(static_cast<vtkIdType>(index), visibility[index]);
      geometryArray->SetValue(static_cast<vtkIdType>(index), seen ? 1 : 0);
      maskArray->SetValue(static_cast<vtkIdType>(index), measured ? 1 : 0);
    }
  }
  output->GetPointData()->SetScalars(visibilityArray);
  output->GetPointData()->AddArray(geometryArray);
  output->GetPointData()->AddArray(maskArray);
  return 1;
}

//------------------------------------------------------------------------------
void vtkRayCastLightVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Renderer.Get() << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "LightIndex: " << this->LightIndex << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
