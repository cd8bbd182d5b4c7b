// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "SceneFile.h"

#include "ModelFiles.h"
#include "Sources.h"
#include "Techniques.h"

#include <vtkMath.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace softshadows
{
namespace
{
bool IsZero(const Vector3& v)
{
  return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0;
}

void RejectField(const Json& object, const std::string& path, const char* key, const char* why)
{
  if (object.contains(key))
  {
    throw InputError(FieldPath(path, key), why);
  }
}

std::array<int, 2> ReadSize(const Json& value, const std::string& path)
{
  if (!value.is_array() || value.size() != 2)
  {
    throw InputError(path, "expected [width, height]");
  }
  const Range pixels = Range::Between(1, MaximumWindowSize);
  return { ReadInteger(value[0], IndexPath(path, 0), pixels),
    ReadInteger(value[1], IndexPath(path, 1), pixels) };
}

SceneCamera ReadCamera(const Json& value, const std::string& path)
{
  CheckObject(value, path, { "position", "focal_point", "view_up", "view_angle" });
  RequireField(value, path, "position");
  RequireField(value, path, "focal_point");
  SceneCamera camera;
  camera.Given = true;
  camera.Position = ReadVector3(value["position"], FieldPath(path, "position"));
  camera.FocalPoint = ReadVector3(value["focal_point"], FieldPath(path, "focal_point"));
  if (camera.Position == camera.FocalPoint)
  {
    throw InputError(FieldPath(path, "focal_point"), "must differ from position");
  }
  if (value.contains("view_up"))
  {
    camera.ViewUp = ReadVector3(value["view_up"], FieldPath(path, "view_up"));
  }
  Vector3 direction;
  vtkMath::Subtract(camera.FocalPoint.data(), camera.Position.data(), direction.data());
  Vector3 side;
  vtkMath::Cross(direction.data(), camera.ViewUp.data(), side.data());
  if (IsZero(side))
  {
    throw InputError(FieldPath(path, "view_up"), "must not be zero or along the view direction");
  }
  if (value.contains("view_angle"))
  {
    camera.ViewAngle =
      ReadNumber(value["view_angle"], FieldPath(path, "view_angle"), Range{ 0.0, 179.0, true });
  }
  return camera;
}

SceneLight ReadLight(const Json& value, const std::string& path)
{
  CheckObject(value, path,
    { "type", "position", "focal_point", "direction", "cone_angle", "color", "intensity", "radius",
      "shadow_attenuation" });
  RequireField(value, path, "type");
  SceneLight light;
  const std::string typePath = FieldPath(path, "type");
  const std::string type = ReadString(value["type"], typePath);
  if (type == "spot")
  {
    light.Type = SceneLight::Kind::Spot;
  }
  else if (type == "directional")
  {
    light.Type = SceneLight::Kind::Directional;
  }
  else if (type == "point")
  {
    light.Type = SceneLight::Kind::Point;
  }
  else
  {
    throw InputError(
      typePath, "unknown light type '" + type + "' (known: spot, directional, point)");
  }

  // Where the light is and where it points: a position with a focal point or
  // a direction, or (directional lights) only a direction.
  const bool directional = light.Type == SceneLight::Kind::Directional;
  if (light.Type == SceneLight::Kind::Point)
  {
    RejectField(value, path, "direction", "not used by point lights");
    RejectField(value, path, "cone_angle", "not used by point lights (they shine all around)");
  }
  if (directional)
  {
    RejectField(value, path, "cone_angle", "not used by directional lights");
  }
  if (value.contains("direction"))
  {
    const std::string directionPath = FieldPath(path, "direction");
    RejectField(value, path, "focal_point", "give either direction or focal_point, not both");
    if (directional)
    {
      RejectField(value, path, "position", "give either direction or position, not both");
    }
    else
    {
      RequireField(value, path, "position");
      light.Position = ReadVector3(value["position"], FieldPath(path, "position"));
    }
    const Vector3 direction = ReadVector3(value["direction"], directionPath);
    if (IsZero(direction))
    {
      throw InputError(directionPath, "must not be zero");
    }
    // VTK lights shine from Position towards FocalPoint, directional ones too.
    if (directional)
    {
      light.Position = { -direction[0], -direction[1], -direction[2] };
      light.FocalPoint = { 0.0, 0.0, 0.0 };
    }
    else
    {
      const Vector3& p = light.Position;
      light.FocalPoint = { p[0] + direction[0], p[1] + direction[1], p[2] + direction[2] };
    }
  }
  else
  {
    if (!value.contains("position"))
    {
      throw InputError(FieldPath(path, "position"),
        directional ? "missing required field (or give direction)" : "missing required field");
    }
    light.Position = ReadVector3(value["position"], FieldPath(path, "position"));
    if (value.contains("focal_point"))
    {
      light.FocalPoint = ReadVector3(value["focal_point"], FieldPath(path, "focal_point"));
    }
    if (light.Type != SceneLight::Kind::Point && light.Position == light.FocalPoint)
    {
      throw InputError(FieldPath(path, "focal_point"), "must differ from position");
    }
  }

  if (value.contains("cone_angle"))
  {
    light.ConeAngle =
      ReadNumber(value["cone_angle"], FieldPath(path, "cone_angle"), Range{ 0.0, 180.0, true });
  }
  if (light.Type == SceneLight::Kind::Point)
  {
    light.ConeAngle = 180.0;
  }
  if (value.contains("color"))
  {
    light.Color = ReadColor(value["color"], FieldPath(path, "color"));
  }
  if (value.contains("intensity"))
  {
    light.Intensity =
      ReadNumber(value["intensity"], FieldPath(path, "intensity"), Range::AtLeast(0));
  }
  if (value.contains("radius"))
  {
    light.Radius = ReadNumber(value["radius"], FieldPath(path, "radius"),
      directional ? Range::Between(0.0, 45.0) : Range::AtLeast(0.0));
  }
  if (value.contains("shadow_attenuation"))
  {
    light.ShadowAttenuation = ReadNumber(
      value["shadow_attenuation"], FieldPath(path, "shadow_attenuation"), Range::Between(0.0, 1.0));
  }
  return light;
}

void ReadMeshFile(const Json& value, const std::string& path,
  const std::filesystem::path& sceneFolder, SceneActor& actor)
{
  const std::string name = ReadString(value, path);
  std::string extension = std::filesystem::path(name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const std::map<std::string, MeshFormat> formats = { { ".vtp", MeshFormat::VTP },
    { ".obj", MeshFormat::OBJ }, { ".ply", MeshFormat::PLY }, { ".stl", MeshFormat::STL } };
  const auto format = formats.find(extension);
  if (format == formats.end())
  {
    throw InputError(
      path, "'" + name + "': unsupported mesh format (use .vtp, .obj, .ply or .stl)");
  }
  actor.Format = format->second;
  actor.File = sceneFolder / name;
  std::error_code error;
  if (!std::filesystem::is_regular_file(actor.File, error))
  {
    throw InputError(path, "'" + name + "': no such file (looked for " + actor.File.string() + ")");
  }
}

void ReadModelFile(const Json& value, const std::string& path,
  const std::filesystem::path& sceneFolder, SceneActor& actor)
{
  const std::string name = ReadString(value, path);
  if (!IsModelFile(name))
  {
    throw InputError(path, "'" + name + "': not a model file (use .gltf, .glb or .obj)");
  }
  actor.Import = sceneFolder / name;
  std::error_code error;
  if (!std::filesystem::is_regular_file(actor.Import, error))
  {
    throw InputError(
      path, "'" + name + "': no such file (looked for " + actor.Import.string() + ")");
  }
}

// At most this many glyph instances an actor (a million: llvmpipe draws
// them in seconds, and the instances' mesh stays under a few GiB).
constexpr int MaximumGlyphs = 1000000;

// A positive number or [x, y, z] of them (`scale`, `spacing`).
Vector3 ReadPositive3(const Json& value, const std::string& path)
{
  CheckValue(value, ValueType::Size3, Range::Positive(), path);
  const auto components = Components(value, 3);
  return { components[0], components[1], components[2] };
}

SceneGlyphs ReadGlyphs(const Json& value, const std::string& path)
{
  CheckObject(value, path, { "count", "spacing", "turn", "sizes" });
  RequireField(value, path, "count");
  SceneGlyphs glyphs;
  const std::string countPath = FieldPath(path, "count");
  const Json& count = value["count"];
  if (!count.is_array() || count.size() != 3)
  {
    throw InputError(countPath, "expected [nx, ny, nz]");
  }
  double total = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    glyphs.Count[k] =
      ReadInteger(count[k], IndexPath(countPath, k), Range::Between(1, MaximumGlyphs));
    total *= glyphs.Count[k];
  }
  if (total > MaximumGlyphs)
  {
    throw InputError(countPath, "at most " + std::to_string(MaximumGlyphs) + " instances in all");
  }
  if (value.contains("spacing"))
  {
    glyphs.Spacing = ReadPositive3(value["spacing"], FieldPath(path, "spacing"));
  }
  if (value.contains("turn"))
  {
    glyphs.Turn = ReadBoolean(value["turn"], FieldPath(path, "turn"));
  }
  if (value.contains("sizes"))
  {
    const std::string sizesPath = FieldPath(path, "sizes");
    const Json& sizes = value["sizes"];
    if (!sizes.is_array() || sizes.size() != 2)
    {
      throw InputError(sizesPath, "expected [smallest, largest]");
    }
    glyphs.Sizes = { ReadNumber(sizes[0], IndexPath(sizesPath, 0), Range::Positive()),
      ReadNumber(sizes[1], IndexPath(sizesPath, 1), Range::Positive()) };
    if (glyphs.Sizes[1] < glyphs.Sizes[0])
    {
      throw InputError(sizesPath, "the largest is smaller than the smallest");
    }
  }
  return glyphs;
}

SceneActor ReadActor(
  const Json& value, const std::string& path, const std::filesystem::path& folder)
{
  CheckObject(value, path,
    { "source", "params", "file", "import", "position", "orientation", "scale", "color", "opacity",
      "pbr", "glyphs" });
  SceneActor actor;
  actor.Path = path;
  const int kinds = static_cast<int>(value.contains("source")) +
    static_cast<int>(value.contains("file")) + static_cast<int>(value.contains("import"));
  if (kinds != 1)
  {
    throw InputError(
      path, kinds == 0 ? "needs source, file or import" : "give one of source, file and import");
  }
  if (value.contains("import"))
  {
    for (const char* field : { "params", "color", "opacity", "pbr", "glyphs" })
    {
      RejectField(value, path, field, "an imported model's materials come from its file");
    }
    ReadModelFile(value["import"], FieldPath(path, "import"), folder, actor);
  }
  else if (value.contains("source"))
  {
    const std::string where = FieldPath(path, "source");
    actor.Source = ReadString(value["source"], where);
    // A named path: GCC 14 takes a reference returned next to a temporary
    // argument for one to the temporary (-Wdangling-reference).
    const Source& source = FindSource(actor.Source, where);
    actor.Parameters = CompleteParameters(source,
      value.contains("params") ? value["params"] : Json::object(), FieldPath(path, "params"));
  }
  else
  {
    RejectField(value, path, "params", "only for built-in sources");
    ReadMeshFile(value["file"], FieldPath(path, "file"), folder, actor);
  }

  if (value.contains("glyphs"))
  {
    actor.Glyphs = ReadGlyphs(value["glyphs"], FieldPath(path, "glyphs"));
  }
  if (value.contains("position"))
  {
    actor.Position = ReadVector3(value["position"], FieldPath(path, "position"));
  }
  if (value.contains("orientation"))
  {
    actor.Orientation = ReadVector3(value["orientation"], FieldPath(path, "orientation"));
  }
  if (value.contains("scale"))
  {
    actor.Scale = ReadPositive3(value["scale"], FieldPath(path, "scale"));
  }
  if (value.contains("color"))
  {
    actor.Color = ReadColor(value["color"], FieldPath(path, "color"));
  }
  if (value.contains("opacity"))
  {
    actor.Opacity = ReadNumber(value["opacity"], FieldPath(path, "opacity"), Range::Between(0, 1));
  }
  if (value.contains("pbr"))
  {
    const std::string pbrPath = FieldPath(path, "pbr");
    const Json& pbr = value["pbr"];
    if (pbr.is_object())
    {
      CheckObject(pbr, pbrPath, { "metallic", "roughness" });
      actor.PBR = true;
      if (pbr.contains("metallic"))
      {
        actor.Metallic =
          ReadNumber(pbr["metallic"], FieldPath(pbrPath, "metallic"), Range::Between(0, 1));
      }
      if (pbr.contains("roughness"))
      {
        actor.Roughness =
          ReadNumber(pbr["roughness"], FieldPath(pbrPath, "roughness"), Range::Between(0, 1));
      }
    }
    else if (pbr.is_boolean())
    {
      actor.PBR = pbr.get<bool>();
    }
    else
    {
      throw InputError(pbrPath, "expected true, false or {\"metallic\": m, \"roughness\": r}");
    }
  }
  return actor;
}

SceneShadows ReadShadows(const Json& value, const std::string& path)
{
  if (!value.is_object())
  {
    throw InputError(path, "expected an object");
  }
  SceneShadows shadows;
  for (const auto& item : value.items())
  {
    const std::string itemPath = FieldPath(path, item.key());
    if (item.key() == "technique")
    {
      shadows.Technique = ReadString(item.value(), itemPath);
      ParseTechniqueSpec(shadows.Technique, itemPath);
    }
    else if (item.key() == "map_size")
    {
      shadows.MapSize = ReadInteger(item.value(), itemPath, Range::Between(16, 16384));
    }
    else
    {
      // Anything else must be a technique's parameters.
      CheckTechniqueParameters(item.key(), item.value(), itemPath);
      shadows.Parameters[item.key()] = item.value();
    }
  }
  return shadows;
}

// The path of the value the parser stopped at (nlohmann's parse errors say
// where in the text, its out-of-range errors nothing), in the form the
// field checks use: `lights[0].position[1]`.
class FieldAtError : public nlohmann::json_sax<Json>
{
public:
  std::string Path() const
  {
    std::string path;
    for (const Level& level : this->Levels)
    {
      path = level.IsArray ? IndexPath(path, level.Index) : FieldPath(path, level.Key);
    }
    return path;
  }

  bool null() override { return this->Value(); }
  bool boolean(bool) override { return this->Value(); }
  bool number_integer(number_integer_t) override { return this->Value(); }
  bool number_unsigned(number_unsigned_t) override { return this->Value(); }
  bool number_float(number_float_t, const string_t&) override { return this->Value(); }
  bool string(string_t&) override { return this->Value(); }
  bool binary(binary_t&) override { return this->Value(); }
  bool start_object(std::size_t) override { return this->Start(false); }
  bool key(string_t& name) override
  {
    this->Levels.back().Key = name;
    return true;
  }
  bool end_object() override { return this->End(); }
  bool start_array(std::size_t) override { return this->Start(true); }
  bool end_array() override { return this->End(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override
  {
    // An array's failing element is the one after the last value.
    if (!this->Levels.empty() && this->Levels.back().IsArray && this->Levels.back().Started)
    {
      ++this->Levels.back().Index;
    }
    return false;
  }

private:
  struct Level
  {
    bool IsArray = false;
    bool Started = false; // an array has had an element
    std::size_t Index = 0;
    std::string Key;
  };

  // A value of the current array moves its index on, except the first.
  bool Value()
  {
    if (!this->Levels.empty() && this->Levels.back().IsArray)
    {
      Level& level = this->Levels.back();
      level.Index += level.Started ? 1 : 0;
      level.Started = true;
    }
    return true;
  }
  bool Start(bool isArray)
  {
    this->Value();
    Level level;
    level.IsArray = isArray;
    this->Levels.push_back(level);
    return true;
  }
  bool End()
  {
    this->Levels.pop_back();
    return true;
  }

  std::vector<Level> Levels;
};

std::string ReadFile(const std::filesystem::path& file)
{
  std::ifstream stream(file, std::ios::binary);
  if (!stream)
  {
    throw InputError("", std::string("cannot read the file: ") + std::strerror(errno));
  }
  std::ostringstream text;
  text << stream.rdbuf();
  return text.str();
}

Json ParseJson(const std::string& text)
{
  try
  {
    return Json::parse(text);
  }
  catch (const Json::parse_error& error)
  {
    // Drop nlohmann's "[json.exception.parse_error.101] " tag; keep its
    // "parse error at line L, column C: ...".
    const std::string message = error.what();
    const auto tagEnd = message.find("] ");
    throw InputError("", tagEnd == std::string::npos ? message : message.substr(tagEnd + 2));
  }
  catch (const Json::out_of_range&)
  {
    // A number past a double's range (1e400): a mistake in one field.
    FieldAtError finder;
    Json::sax_parse(text, &finder);
    throw InputError(finder.Path(), "the number is out of the range of a double");
  }
}
}

//------------------------------------------------------------------------------
Json SceneShadows::ParametersOf(const std::string& name) const
{
  auto found = this->Parameters.find(name);
  return found == this->Parameters.end() ? Json::object() : found->second;
}

//------------------------------------------------------------------------------
Scene LoadScene(const std::filesystem::path& file)
{
  if (IsModelFile(file))
  {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
    {
      throw InputError("", "no such file");
    }
    Scene scene;
    scene.File = file;
    scene.Name = file.stem().string();
    scene.Staged = true;
    // Its lights get a radius (BuildRenderer()): show them soft.
    scene.Shadows.Technique = "contact";
    SceneActor model;
    // Errors about it are the file's own, not a field's.
    model.Import = file;
    scene.Actors.push_back(model);
    return scene;
  }
  return ParseScene(ReadFile(file), file);
}

//------------------------------------------------------------------------------
Scene ParseScene(const std::string& text, const std::filesystem::path& file)
{
  const Json root = ParseJson(text);
  if (!root.is_object())
  {
    throw InputError("", "expected a JSON object at the top level");
  }
  CheckObject(root, "",
    { "name", "description", "size", "background", "camera", "lights", "actors", "shadows" });

  Scene scene;
  scene.File = file;
  scene.Name = file.stem().string();
  if (root.contains("name"))
  {
    scene.Name = ReadString(root["name"], "name");
    if (scene.Name.empty())
    {
      throw InputError("name", "must not be empty");
    }
  }
  if (root.contains("description"))
  {
    ReadString(root["description"], "description");
  }
  if (root.contains("size"))
  {
    scene.Size = ReadSize(root["size"], "size");
  }
  if (root.contains("background"))
  {
    scene.Background = ReadColor(root["background"], "background");
  }
  if (root.contains("camera"))
  {
    scene.Camera = ReadCamera(root["camera"], "camera");
  }
  if (root.contains("lights"))
  {
    const Json& lights = root["lights"];
    if (!lights.is_array())
    {
      throw InputError("lights", "expected an array");
    }
    for (std::size_t i = 0; i < lights.size(); ++i)
    {
      scene.Lights.push_back(ReadLight(lights[i], IndexPath("lights", i)));
    }
  }
  if (root.contains("actors"))
  {
    const Json& actors = root["actors"];
    if (!actors.is_array())
    {
      throw InputError("actors", "expected an array");
    }
    const std::filesystem::path folder = file.parent_path();
    for (std::size_t i = 0; i < actors.size(); ++i)
    {
      scene.Actors.push_back(ReadActor(actors[i], IndexPath("actors", i), folder));
    }
  }
  if (root.contains("shadows"))
  {
    scene.Shadows = ReadShadows(root["shadows"], "shadows");
  }
  return scene;
}
}
