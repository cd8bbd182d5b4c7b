// A point light inside a closed room, one box towards each of the six walls
// (Gerasimov, GPU Gems ch. 12): the regression image shows a shadow on every
// wall the camera sees, drawn through a single-pass (layered) cube map; the
// Python test test_point_lights.py checks all six walls against ray casting.
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkHardShadowPass.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include "ShadowTestScene.h"

int TestPointLightRoom(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer;
  const double wall[3] = { 0.9, 0.9, 0.9 };
  vtkNew<vtkCubeSource> room;
  room->SetXLength(8);
  room->SetYLength(8);
  room->SetZLength(8);
  ShadowTestScene::AddActor(renderer, room, wall);

  const double boxes[6][3] = { { 1.6, 0, 0 }, { -1.6, 0, 0 }, { 0, 1.6, 0 }, { 0, -1.6, 0 },
    { 0, 0, 1.6 }, { 0, 0, -1.6 } };
  const double colors[6][3] = { { 0.9, 0.3, 0.3 }, { 0.3, 0.9, 0.9 }, { 0.3, 0.9, 0.3 },
    { 0.9, 0.3, 0.9 }, { 0.9, 0.9, 0.3 }, { 0.3, 0.3, 0.9 } };
  for (int i = 0; i < 6; ++i)
  {
    vtkNew<vtkCubeSource> box;
    box->SetCenter(boxes[i][0], boxes[i][1], boxes[i][2]);
    box->SetXLength(0.6);
    box->SetYLength(0.6);
    box->SetZLength(0.6);
    ShadowTestScene::AddActor(renderer, box, colors[i]);
  }

  const double center[3] = { 0, 0, 0 };
  const double down[3] = { 0, -1, 0 };
  ShadowTestScene::AddLight(renderer, center, down, 180, 0.0);

  const double corner[3] = { -3.5, -3.5, 3.5 };
  const double across[3] = { 1, 1, -1 };
  ShadowTestScene::SetCamera(renderer, corner, across, 100);

  vtkNew<vtkHardShadowPass> pass;
  pass->SetMapSize(256);
  renderer->SetPass(pass);
  vtkSmartPointer<vtkRenderWindow> window = ShadowTestScene::Show(renderer, 240, 180);

  int result = vtkRegressionTestImage(window);
  return result == vtkRegressionTester::FAILED ? EXIT_FAILURE : EXIT_SUCCESS;
}
