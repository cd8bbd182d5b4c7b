// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkRayCastLightVisibility.h"

#include "vtkCamera.h"
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
#include "vtkRayCastScene.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkShadowMatrices.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkRayCastLightVisibility);

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

  vtkRayCastScene::Light light;
  std::string error;
  if (!vtkRayCastScene::MakeLight(source, light, error))
  {
    vtkErrorMacro(<< "light " << this->LightIndex << " " << error);
    return 0;
  }

  vtkRayCastScene scene;
  double bounds[6];
  scene.AddRenderer(this->Renderer, bounds);
  double extent =
    glm::length(glm::dvec3(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]));
  extent = bounds[0] <= bounds[1] && std::isfinite(extent) ? extent : 1.0; // none, or NaN points
  // Shadow rays start this far off the surface: above float rounding of
  // the hit, far below any gap a scene means.
  const double offset = 1.0e-5 * extent;
  if (!scene.Commit(error))
  {
    vtkErrorMacro(<< error);
    return 0;
  }

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
  constexpr unsigned int none = std::numeric_limits<unsigned int>::max();
  std::vector<float> visibility(pixels, 0.0f);
  std::vector<unsigned int> surfaceOf(pixels, none);
  std::vector<glm::dvec3> position(pixels), normal(pixels);
  std::vector<float> facing(pixels, 0.0f), inCone(pixels, 0.0f);

  const int strata = std::max(1, static_cast<int>(std::lround(std::sqrt(this->Samples))));
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
            vtkRayCastScene::Hit hit;
            if (!scene.Intersect(origin, direction, hit))
            {
              continue;
            }
            surfaceOf[index] = hit.Surface;
            position[index] = hit.Position;
            normal[index] = hit.Normal;
            const vtkRayCastScene::Sight sight = scene.See(light, hit.Position, hit.Normal, strata,
              vtkRayCastScene::Jitter(static_cast<unsigned int>(index), seed), offset);
            visibility[index] = static_cast<float>(sight.Visible);
            facing[index] = static_cast<float>(sight.Facing);
            inCone[index] = sight.InCone ? 1.0f : 0.0f;
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
      const bool seen = surfaceOf[index] != none;
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
