// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "SceneBuilder.h"

#include "MeshFiles.h"
#include "ModelFiles.h"
#include "Sources.h"

#include "vtkSoftShadowPass.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkLight.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <X11/Xlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
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

/// A vtkGlyph3DMapper drawing `mesh` at every point of the grid `glyphs`
/// describes, centred on the origin; each instance turned (a direction) and
/// scaled (a size) by values that vary over the grid without repeating soon.
vtkSmartPointer<vtkMapper> GlyphMapper(vtkPolyData* mesh, const SceneGlyphs& glyphs)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> directions, sizes;
  directions->SetName("direction");
  directions->SetNumberOfComponents(3);
  sizes->SetName("size");
  const auto& n = glyphs.Count;
  const auto& d = glyphs.Spacing;
  vtkIdType k = 0;
  for (int z = 0; z < n[2]; ++z)
  {
    for (int y = 0; y < n[1]; ++y)
    {
      for (int x = 0; x < n[0]; ++x, ++k)
      {
        points->InsertNextPoint((x - 0.5 * (n[0] - 1)) * d[0], (y - 0.5 * (n[1] - 1)) * d[1],
          (z - 0.5 * (n[2] - 1)) * d[2]);
        // The golden angle and ratio: neighbours differ, nothing lines up.
        const double angle = 2.39996322972865332 * static_cast<double>(k);
        directions->InsertNextTuple3(std::cos(angle), 1.0, std::sin(angle));
        const double fraction = std::fmod(0.61803398874989485 * static_cast<double>(k), 1.0);
        sizes->InsertNextValue(
          static_cast<float>(glyphs.Sizes[0] + fraction * (glyphs.Sizes[1] - glyphs.Sizes[0])));
      }
    }
  }
  vtkNew<vtkPolyData> grid;
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(directions);
  grid->GetPointData()->AddArray(sizes);
  auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
  mapper->SetInputData(grid);
  mapper->SetSourceData(mesh);
  mapper->SetOrient(glyphs.Turn);
  mapper->SetOrientationArray("direction");
  mapper->SetOrientationModeToDirection();
  mapper->SetScaleArray("size");
  mapper->SetScaleModeToScaleByMagnitude();
  return mapper;
}

vtkSmartPointer<vtkActor> MakeActor(const SceneActor& description)
{
  vtkSmartPointer<vtkPolyData> mesh = description.Source.empty()
    ? ReadMesh(description)
    : FindSource(description.Source, description.Path).Create(description.Parameters);

  vtkSmartPointer<vtkMapper> mapper;
  if (description.Glyphs.Count[0] > 0)
  {
    mapper = GlyphMapper(WithNormals(mesh), description.Glyphs);
  }
  else
  {
    auto polydata = vtkSmartPointer<vtkPolyDataMapper>::New();
    polydata->SetInputData(WithNormals(mesh));
    mapper = polydata;
  }
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

/// The model `description` imports, placed by its position, orientation and
/// scale on top of the transforms the file gives its parts.
ImportedModel Import(const SceneActor& description)
{
  ImportedModel model;
  const std::string where = description.Path.empty() ? "" : FieldPath(description.Path, "import");
  try
  {
    model = ImportModel(description.Import);
  }
  catch (const std::runtime_error& error)
  {
    // A staged scene's errors are filed under the model file already.
    throw InputError(where,
      where.empty() ? std::string(error.what())
                    : "cannot import " + description.Import.string() + ": " + error.what());
  }
  if (!model.Warning.empty())
  {
    std::cerr << "softshadows: warning: " << description.Import.string() << ": " << model.Warning
              << "\n";
  }
  vtkNew<vtkActor> placement;
  const Vector3& p = description.Position;
  const Vector3& o = description.Orientation;
  const Vector3& s = description.Scale;
  placement->SetPosition(p[0], p[1], p[2]);
  placement->SetOrientation(o[0], o[1], o[2]);
  placement->SetScale(s[0], s[1], s[2]);
  vtkMatrix4x4* place = placement->GetMatrix();
  for (vtkActor* actor : model.Actors)
  {
    // The importer's matrices are shared between a node's parts: make new ones.
    vtkNew<vtkMatrix4x4> matrix;
    if (vtkMatrix4x4* own = actor->GetUserMatrix())
    {
      vtkMatrix4x4::Multiply4x4(place, own, matrix);
    }
    else
    {
      matrix->DeepCopy(place);
    }
    actor->SetUserMatrix(matrix);
  }
  const auto transform = [&](Vector3& point, double w)
  {
    double in[4] = { point[0], point[1], point[2], w }, out[4];
    place->MultiplyPoint(in, out);
    point = { out[0], out[1], out[2] };
  };
  for (SceneLight& light : model.Lights)
  {
    const bool directional = light.Type == SceneLight::Kind::Directional;
    transform(light.Position, directional ? 0.0 : 1.0);
    transform(light.FocalPoint, 1.0);
  }
  if (model.HasCamera)
  {
    transform(model.Camera.Position, 1.0);
    transform(model.Camera.FocalPoint, 1.0);
    transform(model.Camera.ViewUp, 0.0);
  }
  return model;
}

/// Sizes for lights that come without one, as parts of the scene's size:
/// soft shadows that show the technique, not a blur.
constexpr double ImportedLightRadius = 0.02; ///< of the bounds' diagonal
constexpr double ImportedSunRadius = 1.0;    ///< degrees
constexpr double StagedLightRadius = 0.03;   ///< of the bounds' diagonal

/// A staged model's floor (a square twice the bounds' diagonal, just under
/// their lowest y: glTF is y-up) and, when nothing lights it, a spot light
/// above and in front of it.
void Stage(vtkRenderer* renderer, Scene& scene)
{
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const double center[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double diagonal = std::max(1e-6,
    std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4])));
  // A gap of a thousandth keeps a flat bottom from fighting the floor.
  const double floorY = bounds[2] - 1e-3 * diagonal;
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(center[0] - diagonal, floorY, center[2] + diagonal);
  plane->SetPoint1(center[0] + diagonal, floorY, center[2] + diagonal);
  plane->SetPoint2(center[0] - diagonal, floorY, center[2] - diagonal);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> floor;
  floor->SetMapper(mapper);
  floor->GetProperty()->SetColor(0.8, 0.8, 0.8);
  renderer->AddActor(floor);
  if (scene.Lights.empty())
  {
    SceneLight light;
    light.Position = { center[0] + 0.35 * diagonal, center[1] + 1.1 * diagonal,
      center[2] + 0.55 * diagonal };
    light.FocalPoint = { center[0], floorY, center[2] };
    light.ConeAngle = 35.0;
    light.Radius = StagedLightRadius * diagonal;
    scene.Lights.push_back(light);
  }
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
vtkSmartPointer<vtkRenderer> BuildRenderer(Scene& scene)
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(scene.Background.data());
  std::vector<SceneLight> importedLights;
  for (const SceneActor& actor : scene.Actors)
  {
    if (actor.Import.empty())
    {
      renderer->AddActor(MakeActor(actor));
      continue;
    }
    ImportedModel model = Import(actor);
    for (vtkActor* part : model.Actors)
    {
      renderer->AddActor(part);
    }
    importedLights.insert(importedLights.end(), model.Lights.begin(), model.Lights.end());
    if (model.HasCamera && !scene.Camera.Given)
    {
      scene.Camera = model.Camera;
    }
  }
  // The scene's own lights, else the models' (sized to the scene).
  if (scene.Lights.empty() && !importedLights.empty())
  {
    double bounds[6];
    renderer->ComputeVisiblePropBounds(bounds);
    const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
    for (SceneLight& light : importedLights)
    {
      light.Radius = light.Type == SceneLight::Kind::Directional ? ImportedSunRadius
                                                                 : ImportedLightRadius * diagonal;
    }
    scene.Lights = importedLights;
  }
  // A staged model fills the view; its floor reaches past it.
  double modelBounds[6];
  renderer->ComputeVisiblePropBounds(modelBounds);
  if (scene.Staged)
  {
    Stage(renderer, scene);
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
    if (scene.Staged)
    {
      renderer->ResetCamera(modelBounds);
    }
    else
    {
      renderer->ResetCamera();
    }
  }
  renderer->ResetCameraClippingRange();
  return renderer;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkRenderWindow> MakeWindow(
  vtkRenderer* renderer, const std::array<int, 2>& size, bool withAlpha, bool onScreen)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetDisplayId(SharedDisplay());
  window->SetOffScreenRendering(onScreen ? 0 : 1);
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
