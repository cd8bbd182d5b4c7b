// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "ModelFiles.h"

#include "GltfFiles.h"
#include "MeshFiles.h"
#include "MessageCapture.h"
#include "ObjFiles.h"
#include "vtkSoftShadowsMeshCheck.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkDataSet.h>
#include <vtkGLTFImporter.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkOBJImporter.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>


namespace softshadows
{
namespace
{
std::string LowerExtension(const std::filesystem::path& file)
{
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

/// The material library the OBJ names (`mtllib`), else <file>.mtl or
/// <stem>.mtl as VTK's importer would look for; empty when none exists
/// (every part VTK's default white).
std::filesystem::path MaterialLibrary(const std::filesystem::path& obj)
{
  std::ifstream in(obj);
  std::string line;
  while (std::getline(in, line))
  {
    if (line.compare(0, 7, "mtllib ") != 0)
    {
      continue;
    }
    std::string name = line.substr(7);
    // Names may hold spaces; only the ends are trimmed.
    const auto isSpace = [](unsigned char c) { return std::isspace(c) != 0; };
    name.erase(name.begin(), std::find_if_not(name.begin(), name.end(), isSpace));
    name.erase(std::find_if_not(name.rbegin(), name.rend(), isSpace).base(), name.end());
    const std::filesystem::path library = obj.parent_path() / name;
    std::error_code error;
    if (std::filesystem::is_regular_file(library, error))
    {
      return library;
    }
    break;
  }
  // Where VTK's importer looks when it is given none.
  for (std::filesystem::path library : { std::filesystem::path(obj.string() + ".mtl"),
         obj.parent_path() / (obj.stem().string() + ".mtl") })
  {
    std::error_code error;
    if (std::filesystem::is_regular_file(library, error))
    {
      return library;
    }
  }
  return {};
}

/**
 * A copy of the material library for VTK 9.1's importer, removed when this
 * goes. Its MTL parser reads past its tokens when the last line names a
 * texture (a crash; upstream checks the bound since), so the copy ends with
 * a comment line; and texture names written with Windows' separators
 * (`map_Kd .\\wood.jpg`) get '/' so that they are found.
 */
class MaterialCopy
{
public:
  explicit MaterialCopy(const std::filesystem::path& library)
  {
    std::ifstream in(library, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string fixed;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line))
    {
      if (line.compare(0, 4, "map_") == 0 || line.compare(0, 4, "bump") == 0)
      {
        std::replace(line.begin(), line.end(), '\\', '/');
      }
      fixed += line + "\n";
    }
    fixed += "\n# end\n";
    this->Copy = std::make_unique<TemporaryFile>(fixed, ".mtl");
  }
  const std::filesystem::path& File() const { return this->Copy->Path(); }

private:
  std::unique_ptr<TemporaryFile> Copy;
};

SceneLight FromVTK(vtkLight* light)
{
  SceneLight result;
  double position[3], focalPoint[3];
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focalPoint);
  result.Position = { position[0], position[1], position[2] };
  result.FocalPoint = { focalPoint[0], focalPoint[1], focalPoint[2] };
  if (!light->GetPositional())
  {
    // The scene's directional lights shine from Position towards the origin.
    result.Type = SceneLight::Kind::Directional;
    result.Position = { position[0] - focalPoint[0], position[1] - focalPoint[1],
      position[2] - focalPoint[2] };
    result.FocalPoint = { 0.0, 0.0, 0.0 };
  }
  else if (light->GetConeAngle() >= 90.0)
  {
    // vtkGLTFImporter gives point lights a cone of 90 degrees.
    result.Type = SceneLight::Kind::Point;
    result.ConeAngle = 180.0;
  }
  else
  {
    result.ConeAngle = light->GetConeAngle();
  }
  double color[3];
  light->GetDiffuseColor(color);
  result.Color = { color[0], color[1], color[2] };
  result.Intensity = light->GetIntensity();
  return result;
}

SceneCamera FromVTK(vtkCamera* camera)
{
  SceneCamera result;
  result.Given = true;
  const double* p = camera->GetPosition();
  const double* f = camera->GetFocalPoint();
  const double* u = camera->GetViewUp();
  result.Position = { p[0], p[1], p[2] };
  result.FocalPoint = { f[0], f[1], f[2] };
  result.ViewUp = { u[0], u[1], u[2] };
  result.ViewAngle = camera->GetViewAngle();
  return result;
}

/// Whether the part has cells to draw; throws when it has a problem that
/// would make VTK's mapper or the shadow passes read out of bounds.
bool HasSurface(vtkActor* actor, std::size_t index)
{
  vtkMapper* mapper = actor->GetMapper();
  if (!mapper)
  {
    return false;
  }
  mapper->Update();
  auto* mesh = vtkPolyData::SafeDownCast(mapper->GetInput());
  if (!mesh || mesh->GetNumberOfCells() == 0)
  {
    return false;
  }
  const std::string problem = vtkSoftShadowsMeshCheck::FindProblem(mesh);
  if (!problem.empty())
  {
    throw std::runtime_error("VTK's importer made part " + std::to_string(index) +
      " a mesh that cannot be drawn: " + problem);
  }
  return true;
}
}

//------------------------------------------------------------------------------
bool IsModelFile(const std::filesystem::path& file)
{
  const std::string extension = LowerExtension(file);
  return extension == ".gltf" || extension == ".glb" || extension == ".obj";
}

//------------------------------------------------------------------------------
ImportedModel ImportModel(const std::filesystem::path& file)
{
  const bool obj = LowerExtension(file) == ".obj";
  if (obj)
  {
    // Refuses broken geometry before VTK's importer, which trusts it, reads it.
    ReadMeshFile(file, MeshFormat::OBJ);
  }
  else
  {
    const std::string problem = FindGltfProblem(file);
    if (!problem.empty())
    {
      throw std::runtime_error(problem);
    }
  }

  MessageCapture capture;
  // Importers put what they read into their window's first renderer; this
  // window is never opened.
  vtkNew<vtkRenderWindow> holder;
  vtkNew<vtkRenderer> renderer;
  holder->AddRenderer(renderer);
  vtkSmartPointer<vtkImporter> importer;
  vtkGLTFImporter* gltf = nullptr;
  std::unique_ptr<MaterialCopy> materials;
  std::unique_ptr<TemporaryFile> absolute;
  if (obj)
  {
    vtkNew<vtkOBJImporter> objImporter;
    // Relative indices resolved as for the reader (ObjFiles.h).
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string resolved = AbsoluteObjIndices(bytes);
    if (resolved != bytes)
    {
      absolute = std::make_unique<TemporaryFile>(resolved, ".obj");
    }
    objImporter->SetFileName((absolute ? absolute->Path() : file).string().c_str());
    const std::filesystem::path library = MaterialLibrary(file);
    if (!library.empty())
    {
      materials = std::make_unique<MaterialCopy>(library);
      objImporter->SetFileNameMTL(materials->File().string().c_str());
    }
    // Texture names in the MTL are relative to the OBJ's folder.
    objImporter->SetTexturePath((file.parent_path().string() + "/").c_str());
    importer = objImporter;
  }
  else
  {
    vtkNew<vtkGLTFImporter> gltfImporter;
    gltfImporter->SetFileName(file.string().c_str());
    gltf = gltfImporter;
    importer = gltfImporter;
  }
  importer->SetRenderWindow(holder);
  importer->Update();

  ImportedModel model;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  std::size_t index = 0;
  while (vtkActor* actor = actors->GetNextActor())
  {
    if (HasSurface(actor, index++))
    {
      model.Actors.emplace_back(actor);
    }
  }
  if (model.Actors.empty())
  {
    throw std::runtime_error(capture.HasError()
        ? capture.FirstError()
        : std::string("the file holds nothing VTK's importer can draw"));
  }
  // What was drawn may still miss something (a material the MTL lacks, a
  // texture not found): the model is shown, and what VTK said with it.
  model.Warning = capture.FirstMessage();
  model.Warning.erase(0, model.Warning.find_first_not_of(' '));
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    model.Lights.push_back(FromVTK(light));
  }
  if (gltf)
  {
    // The first perspective camera; the scene format has no orthographic one.
    for (vtkIdType i = 0; i < gltf->GetNumberOfCameras(); ++i)
    {
      vtkSmartPointer<vtkCamera> camera = gltf->GetCamera(static_cast<unsigned int>(i));
      if (camera && !camera->GetParallelProjection())
      {
        model.HasCamera = true;
        model.Camera = FromVTK(camera);
        break;
      }
    }
  }
  return model;
}
}
