// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Regression images of the `aliasfree` technique: run as
//   TestAliasFreeShadowPass <ball|fence> <soft|hard> -V baseline ...
// The ball and the fence over a plane under spot lights of radius 0.4 and
// 0.3; the maps small (256^2), which alias-free shadows do not show.
#include "vtkAliasFreeShadowPass.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "ShadowTestScene.h"

#include <cstring>
#include <iostream>

int TestAliasFreeShadowPass(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: TestAliasFreeShadowPass <ball|fence> <soft|hard> ...\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderer> renderer;
  if (std::strcmp(argv[1], "fence") == 0)
  {
    ShadowTestScene::BuildFence(renderer, 0.3);
  }
  else
  {
    ShadowTestScene::Build(renderer, 0.4);
  }

  vtkNew<vtkAliasFreeShadowPass> pass;
  pass->SetMapSize(256);
  if (std::strcmp(argv[2], "hard") == 0)
  {
    pass->SetVariantToHard();
  }
  renderer->SetPass(pass);

  vtkSmartPointer<vtkRenderWindow> window = ShadowTestScene::Show(renderer, 320, 240);

  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
