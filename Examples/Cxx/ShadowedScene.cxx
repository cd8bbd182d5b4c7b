// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// A ball above a floor, lit by a spot light of radius 0.3, drawn with
// shadows by setting a vtkHardShadowPass on the renderer. Writes a PNG.
//
//   xvfb-run -a ./ShadowedScene shadowed.png

#include "vtkHardShadowPass.h"
#include "vtkSoftShadowPass.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkWindowToImageFilter.h>

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "Usage: " << argv[0] << " OUTPUT.png\n";
    return 2;
  }

  // A 6 x 6 floor on y = 0, facing up.
  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-3.0, 0.0, -3.0);
  floor->SetPoint1(-3.0, 0.0, 3.0);
  floor->SetPoint2(3.0, 0.0, -3.0);
  vtkNew<vtkPolyDataMapper> floorMapper;
  floorMapper->SetInputConnection(floor->GetOutputPort());
  vtkNew<vtkActor> floorActor;
  floorActor->SetMapper(floorMapper);

  // A ball floating above it.
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(0.5);
  ball->SetThetaResolution(48);
  ball->SetPhiResolution(24);
  vtkNew<vtkPolyDataMapper> ballMapper;
  ballMapper->SetInputConnection(ball->GetOutputPort());
  vtkNew<vtkActor> ballActor;
  ballActor->SetMapper(ballMapper);
  ballActor->SetPosition(0.0, 1.0, 0.0);
  ballActor->GetProperty()->SetColor(0.9, 0.3, 0.25);

  // Shadows come from scene lights: a spot light (cone < 90 degrees) above
  // the ball. Its radius sets the penumbra width of the soft techniques.
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetPosition(1.0, 5.0, 0.5);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetConeAngle(40.0);
  vtkSoftShadowPass::SetRadius(0.3, light);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(floorActor);
  renderer->AddActor(ballActor);
  renderer->AutomaticLightCreationOff();
  renderer->AddLight(light);
  renderer->SetBackground(0.2, 0.2, 0.25);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 5.0, 7.0);
  camera->SetFocalPoint(0.0, 0.5, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCameraClippingRange();

  // The pass draws the shadow maps and the scene: every ordinary actor
  // casts and receives shadows. Other techniques (vtkReferenceShadowPass...)
  // are set the same way.
  vtkNew<vtkHardShadowPass> shadows;
  renderer->SetPass(shadows);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(480, 360);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(argv[1]);
  writer->SetInputConnection(capture->GetOutputPort());
  writer->Write();
  return writer->GetErrorCode() == 0 ? 0 : 1;
}
