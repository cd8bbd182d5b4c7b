// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Two point lights and a spot light together (Gerasimov, GPU Gems ch. 12):
// a post on the ground casts one shadow from each, each light's shadow-only
// output is dark exactly behind the post from that light and lit where only
// the other lights are hidden. Run with `hard` (default) or `omni`: the
// omnidirectional technique with lights of radius 0.1 and its Poisson filter.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkHardShadowPass.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkOmnidirectionalShadowPass.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include "ShadowTestScene.h"

#include <cmath>
#include <cstring>
#include <iostream>

int TestPointLightShadows(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  const double blue[3] = { 0.3, 0.45, 0.9 };
  ShadowTestScene::AddGround(renderer, 1);
  vtkNew<vtkCubeSource> post;
  post->SetCenter(0, 0.6, 0);
  post->SetXLength(0.4);
  post->SetYLength(1.2);
  post->SetZLength(0.4);
  ShadowTestScene::AddActor(renderer, post, blue);

  const bool omni = argc > 1 && std::strcmp(argv[1], "omni") == 0;
  const double radius = omni ? 0.1 : 0.0;
  const double origin[3] = { 0, 0, 0 };
  const double lights[3][3] = { { 2.0, 1.5, 0.0 }, { 0.0, 1.5, 2.0 }, { -3.0, 3.0, -3.0 } };
  ShadowTestScene::AddLight(renderer, lights[0], origin, 180, radius, 0.5); // point: towards -x
  ShadowTestScene::AddLight(renderer, lights[1], origin, 180, radius, 0.5); // point: towards -z
  ShadowTestScene::AddLight(renderer, lights[2], origin, 40, radius, 0.5);  // spot: towards +x +z

  const double eye[3] = { 3, 6, 4 };
  ShadowTestScene::SetCamera(renderer, eye, origin, 40);

  vtkSmartPointer<vtkSoftShadowPass> pass;
  if (omni)
  {
    pass = vtkSmartPointer<vtkOmnidirectionalShadowPass>::New();
  }
  else
  {
    pass = vtkSmartPointer<vtkHardShadowPass>::New();
  }
  pass->SetMapSize(512);
  renderer->SetPass(pass);
  vtkSmartPointer<vtkRenderWindow> window = ShadowTestScene::Show(renderer, 300, 240);
  if (pass->GetNumberOfShadowedLights() != 3)
  {
    std::cerr << "expected 3 shadowed lights, got " << pass->GetNumberOfShadowedLights() << "\n";
    return EXIT_FAILURE;
  }
  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);

  // Ground points where each light's shadow falls (through the post's centre).
  const double behind[3][3] = { { -4.0 / 3.0, 0, 0 }, { 0, 0, -4.0 / 3.0 }, { 0.75, 0, 0.75 } };
  bool ok = true;
  for (int light = 0; light < 3; ++light)
  {
    pass->SetShadowOnlyLight(light);
    window->Render();
    for (int point = 0; point < 3; ++point)
    {
      const double expected = point == light ? 0.0 : 1.0;
      const double v = ShadowTestScene::VisibilityAt(renderer, window, behind[point]);
      if (std::abs(v - expected) > 0.1)
      {
        std::cerr << "light " << light << " at (" << behind[point][0] << ", " << behind[point][2]
                  << "): visibility " << v << ", expected " << expected << "\n";
        ok = false;
      }
    }
  }
  return (result == vtkRegressionTester::FAILED || !ok) ? EXIT_FAILURE : EXIT_SUCCESS;
}
