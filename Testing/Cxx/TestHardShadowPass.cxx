// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Regression image of the `hard` technique on the ball-and-box scene, in a
// non-square window.
#include "vtkHardShadowPass.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "ShadowTestScene.h"

int TestHardShadowPass(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  ShadowTestScene::Build(renderer, 0.0);
  vtkNew<vtkHardShadowPass> pass;
  pass->SetMapSize(512);
  renderer->SetPass(pass);

  vtkSmartPointer<vtkRenderWindow> window = ShadowTestScene::Show(renderer, 320, 240);

  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
