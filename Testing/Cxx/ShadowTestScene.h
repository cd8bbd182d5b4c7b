// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Small scene shared by the C++ tests: a ball above a ground plane, a box
// beside it, lit by a spot light from above at an angle. Windows stay small:
// the tests run on a software rasterizer.
#ifndef ShadowTestScene_h
#define ShadowTestScene_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkFenceSource.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowPass.h"
#include "vtkSphereSource.h"
#include "vtkUnsignedCharArray.h"

#include <cmath>

namespace ShadowTestScene
{
// The image comparison's threshold on every VTK release: 9.1's default,
// which 9.5 lowered to 0.05 along with a new comparison (the old one is
// chosen by VTK_TESTING_IMAGE_COMPARE_METHOD=LEGACY_VALID in the tests'
// environment, Testing/CMakeLists.txt).
constexpr double ImageThreshold = 0.15;

/// The red channel, in [0, 1], at the pixel where world point p lands: in
/// shadow-only mode, the visibility there.
inline double VisibilityAt(vtkRenderer* renderer, vtkRenderWindow* window, const double p[3])
{
  renderer->SetWorldPoint(p[0], p[1], p[2], 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  const int x = static_cast<int>(std::lround(d[0]));
  const int y = static_cast<int>(std::lround(d[1]));
  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(x, y, x, y, 0, rgb);
  return rgb->GetValue(0) / 255.0;
}

inline vtkSmartPointer<vtkActor> AddActor(
  vtkRenderer* renderer, vtkAlgorithm* source, const double color[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  renderer->AddActor(actor);
  return actor;
}

/// A positional scene light (a point light when `cone` >= 90) of radius
/// `radius`, aimed at `focal`.
inline vtkLight* AddLight(vtkRenderer* renderer, const double position[3], const double focal[3],
  double cone, double radius, double intensity = 1.0)
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetPosition(position[0], position[1], position[2]);
  light->SetFocalPoint(focal[0], focal[1], focal[2]);
  light->SetConeAngle(cone);
  light->SetIntensity(intensity);
  vtkSoftShadowPass::SetRadius(radius, light);
  renderer->AddLight(light);
  return light;
}

/// The camera at `position` looking at `focal`, y up, and the tests' background.
inline void SetCamera(
  vtkRenderer* renderer, const double position[3], const double focal[3], double viewAngle)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(position[0], position[1], position[2]);
  camera->SetFocalPoint(focal[0], focal[1], focal[2]);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(viewAngle);
  renderer->ResetCameraClippingRange();
  renderer->SetBackground(0.1, 0.1, 0.12);
}

/// The 6 x 6 ground on y = 0.
inline void AddGround(vtkRenderer* renderer, int resolution = 4)
{
  const double ground[3] = { 0.85, 0.85, 0.85 };
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-3, 0, -3);
  plane->SetPoint1(3, 0, -3);
  plane->SetPoint2(-3, 0, 3);
  plane->SetResolution(resolution, resolution);
  AddActor(renderer, plane, ground);
}

/// A `width` x `height` window showing `renderer`, rendered once.
inline vtkSmartPointer<vtkRenderWindow> Show(vtkRenderer* renderer, int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  window->Render();
  return window;
}

/// A point light of radius `lightRadius` inside a closed 8 x 8 x 8 room, one
/// box towards each of the six walls, seen from a corner; returns the light.
inline vtkLight* BuildRoom(vtkRenderer* renderer, double lightRadius)
{
  const double wall[3] = { 0.9, 0.9, 0.9 };
  vtkNew<vtkCubeSource> room;
  room->SetXLength(8);
  room->SetYLength(8);
  room->SetZLength(8);
  AddActor(renderer, room, wall);

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
    AddActor(renderer, box, colors[i]);
  }

  const double center[3] = { 0, 0, 0 };
  const double down[3] = { 0, -1, 0 };
  vtkLight* light = AddLight(renderer, center, down, 180, lightRadius);

  const double corner[3] = { -3.5, -3.5, 3.5 };
  const double across[3] = { 1, 1, -1 };
  SetCamera(renderer, corner, across, 100);
  return light;
}

/// Fills `renderer` and returns its spot light.
inline vtkLight* Build(vtkRenderer* renderer, double lightRadius, double ballHeight = 1.0)
{
  const double red[3] = { 0.9, 0.3, 0.25 };
  const double blue[3] = { 0.3, 0.45, 0.9 };
  AddGround(renderer);

  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(0, ballHeight, 0);
  ball->SetRadius(0.5);
  ball->SetThetaResolution(48);
  ball->SetPhiResolution(32);
  AddActor(renderer, ball, red);

  vtkNew<vtkCubeSource> box;
  box->SetCenter(-1.6, 0.5, -0.8);
  box->SetXLength(0.6);
  box->SetYLength(1.0);
  box->SetZLength(0.6);
  AddActor(renderer, box, blue);

  const double lightPosition[3] = { 1.5, 5.0, 1.0 };
  const double origin[3] = { 0, 0, 0 };
  vtkLight* light = AddLight(renderer, lightPosition, origin, 40, lightRadius);

  const double eye[3] = { 0, 5.5, 7.5 };
  const double focal[3] = { 0, 0.3, 0 };
  SetCamera(renderer, eye, focal, 35);
  return light;
}

/// A capped cylinder of `resolution` sides standing above the ground (the
/// report's figure 6), under a spot light; returns the light.
inline vtkLight* BuildCylinder(vtkRenderer* renderer, double lightRadius, int resolution = 32)
{
  const double green[3] = { 0.3, 0.75, 0.4 };
  AddGround(renderer);
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(0.4);
  cylinder->SetHeight(1.0);
  cylinder->SetCenter(0.0, 1.3, 0.0);
  cylinder->SetResolution(resolution);
  AddActor(renderer, cylinder, green);

  const double lightPosition[3] = { 1.5, 5.0, 1.0 };
  const double origin[3] = { 0, 0, 0 };
  vtkLight* light = AddLight(renderer, lightPosition, origin, 40, lightRadius);

  const double eye[3] = { 0, 5.5, 7.5 };
  const double focal[3] = { 0, 0.3, 0 };
  SetCamera(renderer, eye, focal, 35);
  return light;
}

/// A fence on the ground, lit from behind and above so that its shadow falls
/// towards the camera: contact-hardening shows at the fence's foot.
inline vtkLight* BuildFence(vtkRenderer* renderer, double lightRadius)
{
  const double wood[3] = { 0.72, 0.56, 0.38 };
  AddGround(renderer, 1);

  vtkNew<vtkFenceSource> fence;
  fence->SetNumberOfPickets(9);
  fence->SetHeight(1.2);
  AddActor(renderer, fence, wood)->SetPosition(0, 0, -1.0);

  const double lightPosition[3] = { 0.5, 4.0, -4.0 };
  const double lightFocal[3] = { 0, 0, 0.5 };
  vtkLight* light = AddLight(renderer, lightPosition, lightFocal, 40, lightRadius);

  const double eye[3] = { 0, 4.5, 5.0 };
  const double focal[3] = { 0, 0.3, 0.2 };
  SetCamera(renderer, eye, focal, 35);
  return light;
}
}

#endif
