// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// What VTK 9.1's vtkShadowMapPass gets wrong, in one picture: a spot light
// and a directional light shadowing together, a PBR actor with positional
// light, a translucent actor still drawn, in a non-square window. Then a
// numeric check of each light's shadow-only output: both shadows are where
// the lights put them.
#include "vtkActor.h"
#include "vtkHardShadowPass.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include "ShadowTestScene.h"

#include <cmath>
#include <iostream>

int TestSoftShadowPassLights(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  vtkLight* spot = ShadowTestScene::Build(renderer, 0.0);

  // The ball becomes a PBR actor; a translucent ball floats beside it.
  vtkActor* ball = vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(1));
  ball->GetProperty()->SetInterpolationToPBR();
  ball->GetProperty()->SetRoughness(0.4);
  vtkNew<vtkSphereSource> glass;
  glass->SetCenter(1.5, 0.6, 1.2);
  glass->SetRadius(0.4);
  glass->SetThetaResolution(32);
  glass->SetPhiResolution(24);
  const double green[3] = { 0.3, 0.9, 0.4 };
  ShadowTestScene::AddActor(renderer, glass, green)->GetProperty()->SetOpacity(0.5);

  // A dim directional light from the left: shadows to +x.
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPositional(false);
  sun->SetPosition(-4, 3, 0);
  sun->SetFocalPoint(0, 0, 0);
  sun->SetIntensity(0.4);
  renderer->AddLight(sun);

  vtkNew<vtkHardShadowPass> pass;
  pass->SetMapSize(512);
  renderer->SetPass(pass);

  vtkSmartPointer<vtkRenderWindow> window = ShadowTestScene::Show(renderer, 360, 200);
  if (pass->GetNumberOfShadowedLights() != 2)
  {
    std::cerr << "expected 2 shadowed lights, got " << pass->GetNumberOfShadowedLights() << "\n";
    return EXIT_FAILURE;
  }
  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);

  // Ground points on the ball's axis, pushed away from each light: each is
  // shadowed by its own light only. Ball centre (0, 1, 0), radius 0.5.
  const double* s = spot->GetPosition();
  const double underSpot[3] = { -s[0] / (s[1] - 1.0), 0.0, -s[2] / (s[1] - 1.0) };
  const double underSun[3] = { 4.0 / 3.0, 0.0, 0.0 };
  bool ok = true;
  const struct
  {
    int light;
    const double* point;
    double expected;
  } checks[] = { { 0, underSpot, 0.0 }, { 0, underSun, 1.0 }, { 1, underSun, 0.0 },
    { 1, underSpot, 1.0 } };
  for (const auto& c : checks)
  {
    pass->SetShadowOnlyLight(c.light);
    window->Render();
    const double v = ShadowTestScene::VisibilityAt(renderer, window, c.point);
    if (std::abs(v - c.expected) > 0.1)
    {
      std::cerr << "light " << c.light << " at (" << c.point[0] << ", " << c.point[2]
                << "): visibility " << v << ", expected " << c.expected << "\n";
      ok = false;
    }
  }
  return (result == vtkRegressionTester::FAILED || !ok) ? EXIT_FAILURE : EXIT_SUCCESS;
}
