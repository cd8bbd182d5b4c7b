// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "SceneBuilder.h"

#include "MeshFiles.h"
#include "Sources.h"

#include "vtkSoftShadowPass.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <thread>

namespace softshadows
{
namespace
{
vtkSmartPointer<vtkPolyData> ReadMesh(const SceneActor& actor)
{
  try
  {
    return ReadMeshFile(actor.File, actor.Format);
  }
  catch (const std::runtime_error& error)
  {
    throw InputError(
      FieldPath(actor.Path, "file"), "cannot read " + actor.File.string() + ": " + error.what());
  }
}

// Meshes without point normals would be drawn faceted; give them smooth
// normals, split at sharp edges, like the built-in sources have.
vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* mesh)
{
  if (mesh->GetPointData()->GetNormals())
  {
    return mesh;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->Update();
  return normals->GetOutput();
}

vtkSmartPointer<vtkActor> MakeActor(const SceneActor& description)
{
  vtkSmartPointer<vtkPolyData> mesh = description.Source.empty()
    ? ReadMesh(description)
    : FindSource(description.Source, description.Path).Create(description.Parameters);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(WithNormals(mesh));
  // Colours stored in mesh files would hide the scene's colour.
  mapper->ScalarVisibilityOff();

  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  const Vector3& p = description.Position;
  const Vector3& o = description.Orientation;
  const Vector3& s = description.Scale;
  const Vector3& c = description.Color;
  actor->SetPosition(p[0], p[1], p[2]);
  actor->SetOrientation(o[0], o[1], o[2]);
  actor->SetScale(s[0], s[1], s[2]);
  vtkProperty* property = actor->GetProperty();
  property->SetColor(c[0], c[1], c[2]);
  property->SetOpacity(description.Opacity);
  if (description.PBR)
  {
    property->SetInterpolationToPBR();
    property->SetMetallic(description.Metallic);
    property->SetRoughness(description.Roughness);
  }
  return actor;
}

/**
 * The X display, connected once for the whole run and given to every window.
 * VTK's own connection aborts the process when it fails. And Xvfb resets
 * whenever its last client leaves, refusing connections for a moment, which a
 * program started right after another one can meet: try for a while.
 */
Display* SharedDisplay()
{
  static std::unique_ptr<Display, int (*)(Display*)> display(nullptr, XCloseDisplay);
  const char* name = std::getenv("DISPLAY");
  if (!name || !*name)
  {
    throw std::runtime_error("no X display (DISPLAY is not set): run under xvfb-run -a");
  }
  for (int attempt = 0; attempt < 50 && !display; ++attempt)
  {
    display.reset(XOpenDisplay(nullptr));
    if (!display)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }
  if (!display)
  {
    throw std::runtime_error(std::string("cannot open the X display ") + name);
  }
  return display.get();
}

vtkSmartPointer<vtkLight> MakeLight(const SceneLight& description)
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->SetPosition(description.Position.data());
  light->SetFocalPoint(description.FocalPoint.data());
  light->SetColor(description.Color.data());
  light->SetIntensity(description.Intensity);
  light->SetShadowAttenuation(description.ShadowAttenuation);
  light->SetPositional(description.Type != SceneLight::Kind::Directional);
  light->SetConeAngle(description.ConeAngle);
  vtkSoftShadowPass::SetRadius(description.Radius, light);
  return light;
}
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkRenderer> BuildRenderer(const Scene& scene)
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(scene.Background.data());
  for (const SceneActor& actor : scene.Actors)
  {
    renderer->AddActor(MakeActor(actor));
  }
  if (!scene.Lights.empty())
  {
    renderer->AutomaticLightCreationOff();
  }
  for (const SceneLight& light : scene.Lights)
  {
    renderer->AddLight(MakeLight(light));
  }

  vtkCamera* camera = renderer->GetActiveCamera();
  if (scene.Camera.Given)
  {
    camera->SetPosition(scene.Camera.Position.data());
    camera->SetFocalPoint(scene.Camera.FocalPoint.data());
    camera->SetViewUp(scene.Camera.ViewUp.data());
    camera->SetViewAngle(scene.Camera.ViewAngle);
    camera->OrthogonalizeViewUp();
  }
  else
  {
    // Looking at a y-up scene from the front and a little above shows its
    // ground and the shadows on it; straight along -z would not.
    camera->SetPosition(0.0, 1.0, 2.5);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    renderer->ResetCamera();
  }
  renderer->ResetCameraClippingRange();
  return renderer;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkRenderWindow> MakeWindow(
  vtkRenderer* renderer, const std::array<int, 2>& size, bool withAlpha)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetDisplayId(SharedDisplay());
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetAlphaBitPlanes(withAlpha ? 1 : 0);
  window->SetSize(size[0], size[1]);
  window->AddRenderer(renderer);
  if (!window->SupportsOpenGL())
  {
    throw std::runtime_error("this display offers no OpenGL 3.2 context");
  }
  return window;
}
}
