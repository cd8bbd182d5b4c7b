// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Regression image of the `reference` technique: the same scene as
// TestHardShadowPass with a light of radius 0.4, so penumbrae appear.
#include "vtkNew.h"
#include "vtkReferenceShadowPass.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "ShadowTestScene.h"

int TestReferenceShadowPass(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  ShadowTestScene::Build(renderer, 0.4);
  vtkNew<vtkReferenceShadowPass> pass;
  pass->SetMapSize(512);
  pass->SetNumberOfSamples(64);
  renderer->SetPass(pass);

  vtkSmartPointer<vtkRenderWindow> window = ShadowTestScene::Show(renderer, 320, 240);

  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
