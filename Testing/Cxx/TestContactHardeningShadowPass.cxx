// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Regression images of the `contact` technique: run as
//   TestContactHardeningShadowPass <ball|fence> <pcf|gaussian|multipass> -V baseline ...
// Kernels come from the light's radius (the default), so no tuning per scene.
#include "vtkContactHardeningShadowPass.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "ShadowTestScene.h"

#include <cstring>
#include <iostream>

int TestContactHardeningShadowPass(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: TestContactHardeningShadowPass <ball|fence> <variant> ...\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderer> renderer;
  if (std::strcmp(argv[1], "fence") == 0)
  {
    ShadowTestScene::BuildFence(renderer, 0.3);
  }
  else
  {
    ShadowTestScene::Build(renderer, 0.4, 1.4);
  }

  vtkNew<vtkContactHardeningShadowPass> pass;
  pass->SetMapSize(1024);
  if (std::strcmp(argv[2], "pcf") == 0)
  {
    pass->SetVariantToPCF();
  }
  else if (std::strcmp(argv[2], "gaussian") == 0)
  {
    pass->SetVariantToGaussian();
  }
  renderer->SetPass(pass);

  vtkSmartPointer<vtkRenderWindow> window = ShadowTestScene::Show(renderer, 320, 240);

  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
