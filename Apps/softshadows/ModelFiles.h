// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Whole models with their materials, cameras and lights, through VTK's
 * importers: glTF 2.0 (.gltf, .glb: vtkGLTFImporter, with KHR_lights_punctual
 * lights) and OBJ with its MTL materials and textures (vtkOBJImporter).
 *
 * OBJ geometry is read by ReadMeshFile() first, which refuses what VTK's
 * readers would trust; VTK 9.1's importer does not read the OBJ's `mtllib`
 * line, so it is found here.
 */

#ifndef softshadows_ModelFiles_h
#define softshadows_ModelFiles_h

#include "SceneFile.h"

#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>
#include <vector>

class vtkActor;

namespace softshadows
{
/// What a model file brings into a scene.
struct ImportedModel
{
  std::vector<vtkSmartPointer<vtkActor>> Actors; ///< as VTK's importer made them
  std::vector<SceneLight> Lights;                ///< in world space, radius 0
  bool HasCamera = false;
  SceneCamera Camera; ///< the file's first camera, when HasCamera
  /// The first thing VTK warned or complained about while importing what it
  /// could (a material or texture missing); empty when nothing.
  std::string Warning;
};

/// Whether `file`'s extension (any case) is one ImportModel() reads.
bool IsModelFile(const std::filesystem::path& file);

/**
 * Imports `file`. Throws std::runtime_error with one printable sentence when
 * the file cannot be read, holds no surface, or VTK's importer made a part
 * that cannot be drawn safely.
 */
ImportedModel ImportModel(const std::filesystem::path& file);
}

#endif
