// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Regression images of the `smoothies` technique: run as
//   TestSmoothieShadowPass <cylinder|fence|room> -V baseline ...
// A cylinder and the fence over a plane (the report's figures 6 and 7) under
// spot lights, and the room's point light; thicknesses from the lights'
// radii (the default).
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmoothieShadowPass.h"

#include "ShadowTestScene.h"

#include <cstring>
#include <iostream>

int TestSmoothieShadowPass(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::cerr << "usage: TestSmoothieShadowPass <cylinder|fence|room> ...\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderer> renderer;
  const bool room = std::strcmp(argv[1], "room") == 0;
  if (std::strcmp(argv[1], "fence") == 0)
  {
    ShadowTestScene::BuildFence(renderer, 0.3);
  }
  else if (room)
  {
    ShadowTestScene::BuildRoom(renderer, 0.25); // six cube faces
  }
  else
  {
    ShadowTestScene::BuildCylinder(renderer, 0.4);
  }

  vtkNew<vtkSmoothieShadowPass> pass;
  pass->SetMapSize(room ? 512 : 1024);
  renderer->SetPass(pass);

  vtkSmartPointer<vtkRenderWindow> window =
    ShadowTestScene::Show(renderer, room ? 240 : 320, room ? 180 : 240);

  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
