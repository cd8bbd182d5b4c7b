// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "Visibility.h"

#include "Quality.h"

#include <vtkAppendPolyData.h>
#include <vtkLightVisibilityFilter.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkShadowCasterRegistry.h>
#include <vtkShadowMatrices.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <stdexcept>
#include <vector>

namespace softshadows
{
//------------------------------------------------------------------------------
namespace
{
// The faces of `casters`, placed in the world, appended; null if none.
vtkSmartPointer<vtkPolyData> Placed(const std::vector<vtkShadowCaster>& casters)
{
  vtkNew<vtkAppendPolyData> surfaces;
  for (const vtkShadowCaster& caster : casters)
  {
    if (!caster.Faces || !caster.Data)
    {
      continue;
    }
    vtkNew<vtkMatrix4x4> matrix;
    vtkShadowMatrices::ToVTK(caster.ModelToWorld, matrix);
    vtkNew<vtkTransform> transform;
    transform->SetMatrix(matrix);
    vtkNew<vtkTransformPolyDataFilter> placed;
    placed->SetInputData(caster.Data);
    placed->SetTransform(transform);
    placed->Update();
    surfaces->AddInputData(placed->GetOutput());
  }
  if (surfaces->GetNumberOfInputConnections(0) == 0)
  {
    return nullptr;
  }
  surfaces->Update();
  return surfaces->GetOutput();
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> CastVisibility(
  vtkRenderer* renderer, int samples, bool cells, const SunDay& sun, Progress* progress)
{
  // Bringing the props' bounds up to date updates their inputs.
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  vtkShadowCasterRegistry registry;
  registry.Update(renderer);
  // As VTK's shadows and the truth: opaque faces cast and receive,
  // translucent ones only receive.
  vtkSmartPointer<vtkPolyData> opaque = Placed(registry.GetCasters());
  vtkSmartPointer<vtkPolyData> translucent = Placed(registry.GetTranslucent());
  if (!opaque && !translucent)
  {
    throw std::runtime_error("the scene draws no faces to put the light's visibility on");
  }

  vtkNew<vtkAppendPolyData> output;
  for (vtkPolyData* receiver : { opaque.Get(), translucent.Get() })
  {
    if (!receiver)
    {
      continue;
    }
    vtkNew<vtkLightVisibilityFilter> visibility;
    visibility->SetInputData(receiver);
    visibility->SetReceiverCasts(receiver == opaque);
    if (receiver == translucent && opaque)
    {
      visibility->AddCasterData(opaque);
    }
    visibility->SetLights(renderer->GetLights());
    visibility->SetSamples(samples);
    visibility->SetCellVisibility(cells);
    visibility->SetSunHours(sun.On);
    visibility->SetSunLatitude(sun.Latitude);
    visibility->SetSunDayOfYear(sun.Day);
    visibility->SetSunTimeStep(sun.Step);
    visibility->SetSunUp(sun.Up.data());
    visibility->SetSunNorth(sun.North.data());
    UpdateRayCasting(visibility, progress);
    output->AddInputData(visibility->GetOutput());
  }
  output->Update();
  auto surfaces = vtkSmartPointer<vtkPolyData>::New();
  surfaces->ShallowCopy(output->GetOutput());
  return surfaces;
}
}
