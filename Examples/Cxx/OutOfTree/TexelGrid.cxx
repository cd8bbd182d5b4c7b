// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// A ball over a floor under a spot light, drawn with vtkShadowTexelGridPass,
// a technique built outside the module against its installed headers.
//
//   TexelGrid [OUTPUT.png]
//
// Writes the shadow-only view (light 0's visibility) and checks it: the lit
// floor shows the checkerboard's two levels, the ball's shadow the umbra.
// Exit status 0 when the checks pass.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include "vtkShadowTexelGridPass.h"

#include <cmath>
#include <cstdio>
#include <map>

int main(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 1.0); // blue: not a grey of the shadow-only view
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-2, 0, -2);
  floor->SetPoint1(2, 0, -2);
  floor->SetPoint2(-2, 0, 2);
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(0.0, 0.8, 0.0);
  ball->SetRadius(0.4);
  ball->SetThetaResolution(32);
  ball->SetPhiResolution(32);
  for (vtkAlgorithm* source : { static_cast<vtkAlgorithm*>(floor), static_cast<vtkAlgorithm*>(ball) })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
  }
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetPosition(0.5, 4.0, 0.5);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetConeAngle(35.0);
  renderer->AddLight(light);
  renderer->GetActiveCamera()->SetPosition(0.0, 4.0, 3.5);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();

  // A coarse map, so that its texels are several pixels wide.
  vtkNew<vtkShadowTexelGridPass> pass;
  pass->SetMapSize(64);
  pass->SetContrast(0.5);
  pass->SetShadowOnlyLight(0);
  renderer->SetPass(pass);

  vtkNew<vtkRenderWindow> window;
  window->SetSize(240, 200);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->Render();

  if (argc > 1)
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(argv[1]);
    writer->Write();
  }

  // Visibility levels over the geometry: 1 and 1 - contrast on the lit
  // floor's two kinds of texel, 0 in the ball's umbra.
  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(0, 0, 239, 199, 0, rgb);
  std::map<int, int> levels;
  int geometry = 0;
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
  {
    const int v = rgb->GetValue(3 * i);
    if (rgb->GetValue(3 * i + 2) != v)
    {
      continue; // background
    }
    ++geometry;
    for (int level : { 255, 128, 0 })
    {
      levels[level] += std::abs(v - level) <= 1 ? 1 : 0;
    }
  }
  const double lit = static_cast<double>(levels[255]) / geometry;
  const double odd = static_cast<double>(levels[128]) / geometry;
  const double umbra = static_cast<double>(levels[0]) / geometry;
  std::printf("texel grid: %.1f%% of the geometry at 1, %.1f%% at 0.5, %.1f%% at 0\n",
    100.0 * lit, 100.0 * odd, 100.0 * umbra);
  const bool ok = lit > 0.2 && odd > 0.2 && umbra > 0.01;
  std::printf("%s\n", ok ? "ok" : "FAILED: no checkerboard of the map's texels, or no shadow");
  return ok ? 0 : 1;
}
