// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Regression images of the `silhouette` technique: run as
//   TestSilhouetteShadowPass <ball|fence|room> <soft|hard> -V baseline ...
// Penumbrae come from the light's radius (the default), so no tuning per scene.
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSilhouetteShadowPass.h"

#include "ShadowTestScene.h"

#include <cstring>
#include <iostream>

int TestSilhouetteShadowPass(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: TestSilhouetteShadowPass <ball|fence|room> <soft|hard> ...\n";
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
    ShadowTestScene::BuildRoom(renderer, 0.25); // a point light: six cube faces
  }
  else
  {
    ShadowTestScene::Build(renderer, 0.4, 1.4);
  }

  vtkNew<vtkSilhouetteShadowPass> pass;
  pass->SetMapSize(room ? 512 : 1024);
  if (std::strcmp(argv[2], "hard") == 0)
  {
    pass->SetVariantToHard();
  }
  renderer->SetPass(pass);

  vtkSmartPointer<vtkRenderWindow> window =
    ShadowTestScene::Show(renderer, room ? 240 : 320, room ? 180 : 240);

  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
