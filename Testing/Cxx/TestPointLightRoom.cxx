// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// A point light inside a closed room, one box towards each of the six walls
// (Gerasimov, GPU Gems ch. 12): the regression image shows a shadow on every
// wall the camera sees, drawn through a single-pass (layered) cube map; the
// Python test test_point_lights.py checks all six walls against ray casting.
#include "vtkHardShadowPass.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "ShadowTestScene.h"

int TestPointLightRoom(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  ShadowTestScene::BuildRoom(renderer, 0.0);

  vtkNew<vtkHardShadowPass> pass;
  pass->SetMapSize(256);
  renderer->SetPass(pass);
  vtkSmartPointer<vtkRenderWindow> window = ShadowTestScene::Show(renderer, 240, 180);

  int result = vtkRegressionTestImageThreshold(window, ShadowTestScene::ImageThreshold);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
