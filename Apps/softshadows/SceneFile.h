// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * A scene file (JSON, docs/scene-format.md) read and checked into plain structs.
 *
 * LoadScene() checks everything that can be checked without OpenGL: types,
 * ranges, unknown fields, source and technique names and parameters, that
 * mesh files exist. Errors are InputError with the field's path.
 */

#ifndef softshadows_SceneFile_h
#define softshadows_SceneFile_h

#include "JsonValues.h"

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace softshadows
{
struct SceneCamera
{
  bool Given = false; ///< false: fit the camera to the scene
  Vector3 Position{ 0.0, 0.0, 1.0 };
  Vector3 FocalPoint{ 0.0, 0.0, 0.0 };
  Vector3 ViewUp{ 0.0, 1.0, 0.0 };
  double ViewAngle = 30.0; ///< vertical, degrees
};

struct SceneLight
{
  enum class Kind
  {
    Spot,
    Directional,
    Point
  };
  Kind Type = Kind::Spot;
  Vector3 Position{ 0.0, 0.0, 1.0 };
  Vector3 FocalPoint{ 0.0, 0.0, 0.0 };
  double ConeAngle = 30.0; ///< half angle, degrees
  Vector3 Color{ 1.0, 1.0, 1.0 };
  double Intensity = 1.0;
  double Radius = 0.0; ///< world units; degrees for directional lights
  double ShadowAttenuation = 1.0;
};

/// Mesh files an actor can read, told by the extension (any case).
enum class MeshFormat
{
  VTP,
  OBJ,
  PLY,
  STL
};

/// An actor's `glyphs`: its geometry drawn as instances on a grid, through
/// one vtkGlyph3DMapper.
struct SceneGlyphs
{
  std::array<int, 3> Count{ 0, 0, 0 }; ///< instances along x, y, z; 0: no glyphs
  Vector3 Spacing{ 1.0, 1.0, 1.0 };
  bool Turn = false;                       ///< each instance pointed its own way
  std::array<double, 2> Sizes{ 1.0, 1.0 }; ///< each instance scaled within
};

struct SceneActor
{
  std::string Path;   ///< `actors[i]`, for messages about it
  std::string Source; ///< a built-in source, or empty when File or Import is set
  Json Parameters;    ///< the source's parameters, defaults filled in
  std::filesystem::path File;
  /// A model file (glTF, OBJ + MTL) imported whole with its materials,
  /// cameras and lights (ModelFiles.h); Color, Opacity and PBR are unused.
  std::filesystem::path Import;
  MeshFormat Format = MeshFormat::VTP; ///< of File
  Vector3 Position{ 0.0, 0.0, 0.0 };
  Vector3 Orientation{ 0.0, 0.0, 0.0 }; ///< degrees, as vtkProp3D
  Vector3 Scale{ 1.0, 1.0, 1.0 };
  Vector3 Color{ 0.8, 0.8, 0.8 };
  double Opacity = 1.0;
  bool PBR = false;
  double Metallic = 0.0;
  double Roughness = 0.5;
  SceneGlyphs Glyphs;
};

struct SceneShadows
{
  std::string Technique = "hard"; ///< a checked SPEC
  int MapSize = 1024;
  std::map<std::string, Json> Parameters; ///< checked, keyed by technique name

  /// The scene's parameters for technique `name`: an object, maybe empty.
  Json ParametersOf(const std::string& name) const;
};

struct Scene
{
  std::filesystem::path File;
  std::string Name;
  std::array<int, 2> Size{ 640, 480 };
  Vector3 Background{ 0.2, 0.2, 0.2 };
  SceneCamera Camera;
  std::vector<SceneLight> Lights;
  std::vector<SceneActor> Actors;
  SceneShadows Shadows;
  /// A model file named instead of a scene file: BuildRenderer() sets it on
  /// a floor under the model, lit from above when the model has no lights.
  bool Staged = false;
};

/**
 * Reads and checks a scene file; a model file (.gltf, .glb, .obj) is the
 * staged scene of that one model. Throws InputError; its Where() is a field
 * path (empty for problems with the file as a whole).
 */
Scene LoadScene(const std::filesystem::path& file);

/**
 * Checks `text` as LoadScene() checks the contents of `file`, whose name
 * gives the default scene name and whose folder mesh paths are relative to.
 * The fuzz target's entry point: it reads nothing but mesh files' existence.
 */
Scene ParseScene(const std::string& text, const std::filesystem::path& file);

/// Largest width or height accepted for a window.
constexpr int MaximumWindowSize = 16384;
}

#endif
