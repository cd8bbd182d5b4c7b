// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "GltfFiles.h"

#include "JsonValues.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace softshadows
{
namespace
{
/// A problem found: its message is the sentence FindGltfProblem() returns.
struct Problem : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

std::string At(const std::string& collection, std::size_t index)
{
  return collection + "[" + std::to_string(index) + "]";
}

/// `root[name]`: an array of objects (empty when absent); its size.
std::size_t Collection(const Json& root, const char* name)
{
  if (!root.contains(name))
  {
    return 0;
  }
  const Json& items = root[name];
  if (!items.is_array())
  {
    throw Problem(std::string(name) + " is not an array");
  }
  for (std::size_t i = 0; i < items.size(); ++i)
  {
    if (!items[i].is_object())
    {
      throw Problem(At(name, i) + " is not an object");
    }
  }
  return items.size();
}

/// An optional index field of `object` into a collection of `size` items.
void Index(const Json& object, const char* key, std::size_t size, const std::string& where)
{
  if (!object.contains(key))
  {
    return;
  }
  const Json& value = object[key];
  if (!value.is_number_integer() || value.get<std::int64_t>() < 0 ||
    value.get<std::uint64_t>() >= size)
  {
    throw Problem(
      (where.empty() ? "" : where + ".") + key + " is not an index below " + std::to_string(size));
  }
}

/// An optional non-negative integer field; `fallback` when absent.
std::uint64_t Count(
  const Json& object, const char* key, const std::string& where, std::uint64_t fallback = 0)
{
  if (!object.contains(key))
  {
    return fallback;
  }
  const Json& value = object[key];
  if (!value.is_number_integer() || value.get<std::int64_t>() < 0)
  {
    throw Problem(where + "." + key + " is not a non-negative integer");
  }
  return value.get<std::uint64_t>();
}

/// An optional array of indices into a collection of `size`.
void Indices(const Json& object, const char* key, std::size_t size, const std::string& where)
{
  if (!object.contains(key))
  {
    return;
  }
  const Json& values = object[key];
  if (!values.is_array())
  {
    throw Problem(where + "." + key + " is not an array");
  }
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    Json holder = Json::object();
    holder["i"] = values[i];
    Index(holder, "i", size, where + "." + key + "[" + std::to_string(i) + "]");
  }
}

/// An optional array of `count` numbers.
void Numbers(const Json& object, const char* key, std::size_t count, const std::string& where)
{
  if (!object.contains(key))
  {
    return;
  }
  const Json& values = object[key];
  if (!values.is_array() || values.size() != count ||
    !std::all_of(values.begin(), values.end(), [](const Json& v) { return v.is_number(); }))
  {
    throw Problem(where + "." + key + " is not " + std::to_string(count) + " numbers");
  }
}

/// An optional object field.
const Json* Object(const Json& object, const char* key, const std::string& where)
{
  if (!object.contains(key))
  {
    return nullptr;
  }
  if (!object[key].is_object())
  {
    throw Problem(where + "." + key + " is not an object");
  }
  return &object[key];
}

std::uint64_t ComponentBytes(std::int64_t type)
{
  switch (type)
  {
    case 5120: // BYTE
    case 5121: // UNSIGNED_BYTE
      return 1;
    case 5122: // SHORT
    case 5123: // UNSIGNED_SHORT
      return 2;
    case 5125: // UNSIGNED_INT
    case 5126: // FLOAT
      return 4;
    default:
      return 0;
  }
}

std::uint64_t Components(const std::string& type)
{
  const std::vector<std::pair<const char*, std::uint64_t>> types = { { "SCALAR", 1 }, { "VEC2", 2 },
    { "VEC3", 3 }, { "VEC4", 4 }, { "MAT2", 4 }, { "MAT3", 9 }, { "MAT4", 16 } };
  for (const auto& entry : types)
  {
    if (type == entry.first)
    {
      return entry.second;
    }
  }
  return 0;
}

/// Nodes form trees: no node has two parents or is its own ancestor.
void CheckNodeTree(const Json& nodes)
{
  std::vector<int> parents(nodes.size(), 0);
  for (const Json& node : nodes)
  {
    if (node.contains("children"))
    {
      for (const Json& child : node["children"])
      {
        if (++parents[child.get<std::size_t>()] > 1)
        {
          throw Problem(At("nodes", child.get<std::size_t>()) + " has more than one parent");
        }
      }
    }
  }
  // Every node with a parent hangs from a root: otherwise it is on a cycle.
  std::vector<bool> reached(nodes.size(), false);
  std::vector<std::size_t> stack;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (parents[i] == 0)
    {
      stack.push_back(i);
    }
  }
  while (!stack.empty())
  {
    const std::size_t node = stack.back();
    stack.pop_back();
    reached[node] = true;
    if (nodes[node].contains("children"))
    {
      for (const Json& child : nodes[node]["children"])
      {
        stack.push_back(child.get<std::size_t>());
      }
    }
  }
  const auto cycle = std::find(reached.begin(), reached.end(), false);
  if (cycle != reached.end())
  {
    throw Problem(
      At("nodes", static_cast<std::size_t>(cycle - reached.begin())) + " is its own ancestor");
  }
}

/// A .glb's JSON chunk and the size of its binary chunk.
std::string ReadGlb(const std::string& bytes, std::uint64_t& binarySize)
{
  const auto word = [&](std::size_t at)
  {
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4); // little-endian, as the format and the host
    return value;
  };
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || word(4) != 2)
  {
    throw Problem("not a binary glTF 2.0 file (no glTF header of version 2)");
  }
  const std::uint64_t jsonLength = word(12);
  if (word(16) != 0x4E4F534A || 20 + jsonLength > bytes.size())
  {
    throw Problem("the JSON chunk is missing or runs past the end of the file");
  }
  binarySize = 0;
  const std::uint64_t next = 20 + jsonLength;
  if (next + 8 <= bytes.size() && word(next + 4) == 0x004E4942)
  {
    binarySize = word(next);
    if (next + 8 + binarySize > bytes.size())
    {
      throw Problem("the binary chunk runs past the end of the file");
    }
  }
  return bytes.substr(20, jsonLength);
}

void CheckDocument(
  const Json& root, const std::filesystem::path& folder, bool binary, std::uint64_t binarySize)
{
  if (!root.is_object())
  {
    throw Problem("the document is not a JSON object");
  }
  if (root.contains("extensionsRequired") && root["extensionsRequired"].is_array())
  {
    for (const Json& extension : root["extensionsRequired"])
    {
      if (extension == "KHR_draco_mesh_compression")
      {
        throw Problem("its meshes are Draco compressed, which VTK 9.1's importer does not read");
      }
    }
  }
  const std::size_t scenes = Collection(root, "scenes");
  const std::size_t nodes = Collection(root, "nodes");
  const std::size_t meshes = Collection(root, "meshes");
  const std::size_t accessors = Collection(root, "accessors");
  const std::size_t views = Collection(root, "bufferViews");
  const std::size_t buffers = Collection(root, "buffers");
  const std::size_t materials = Collection(root, "materials");
  const std::size_t textures = Collection(root, "textures");
  const std::size_t images = Collection(root, "images");
  const std::size_t samplers = Collection(root, "samplers");
  const std::size_t cameras = Collection(root, "cameras");
  const std::size_t skins = Collection(root, "skins");
  Collection(root, "animations");
  if (scenes == 0)
  {
    throw Problem("the document has no scene");
  }
  Index(root, "scene", scenes, "");
  for (std::size_t i = 0; i < scenes; ++i)
  {
    Indices(root["scenes"][i], "nodes", nodes, At("scenes", i));
  }
  for (std::size_t i = 0; i < nodes; ++i)
  {
    const Json& node = root["nodes"][i];
    const std::string where = At("nodes", i);
    Indices(node, "children", nodes, where);
    Index(node, "mesh", meshes, where);
    Index(node, "camera", cameras, where);
    Index(node, "skin", skins, where);
    Numbers(node, "matrix", 16, where);
    Numbers(node, "translation", 3, where);
    Numbers(node, "rotation", 4, where);
    Numbers(node, "scale", 3, where);
  }
  if (nodes > 0)
  {
    CheckNodeTree(root["nodes"]);
  }

  std::vector<std::uint64_t> bufferBytes(buffers);
  for (std::size_t i = 0; i < buffers; ++i)
  {
    const Json& buffer = root["buffers"][i];
    const std::string where = At("buffers", i);
    bufferBytes[i] = Count(buffer, "byteLength", where);
    if (!buffer.contains("uri"))
    {
      if (!binary || i != 0 || bufferBytes[i] > binarySize)
      {
        throw Problem(where + " has no uri and no binary chunk of its length");
      }
      continue;
    }
    if (!buffer["uri"].is_string())
    {
      throw Problem(where + ".uri is not a string");
    }
    const std::string uri = buffer["uri"].get<std::string>();
    if (uri.compare(0, 5, "data:") == 0)
    {
      continue;
    }
    const std::filesystem::path file = folder / uri;
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error) ||
      std::filesystem::file_size(file, error) < bufferBytes[i])
    {
      throw Problem(where + "'s file " + file.string() + " is missing or shorter than " +
        std::to_string(bufferBytes[i]) + " bytes");
    }
  }
  std::vector<std::uint64_t> viewBytes(views);
  std::vector<std::uint64_t> viewStride(views);
  for (std::size_t i = 0; i < views; ++i)
  {
    const Json& view = root["bufferViews"][i];
    const std::string where = At("bufferViews", i);
    if (!view.contains("buffer"))
    {
      throw Problem(where + " names no buffer");
    }
    Index(view, "buffer", buffers, where);
    viewBytes[i] = Count(view, "byteLength", where);
    viewStride[i] = Count(view, "byteStride", where);
    const std::uint64_t offset = Count(view, "byteOffset", where);
    if (offset + viewBytes[i] > bufferBytes[view["buffer"].get<std::size_t>()])
    {
      throw Problem(where + " runs past the end of its buffer");
    }
  }
  for (std::size_t i = 0; i < accessors; ++i)
  {
    const Json& accessor = root["accessors"][i];
    const std::string where = At("accessors", i);
    Index(accessor, "bufferView", views, where);
    const std::uint64_t component =
      accessor.contains("componentType") && accessor["componentType"].is_number_integer()
      ? ComponentBytes(accessor["componentType"].get<std::int64_t>())
      : 0;
    const std::uint64_t components = accessor.contains("type") && accessor["type"].is_string()
      ? Components(accessor["type"].get<std::string>())
      : 0;
    if (component == 0 || components == 0)
    {
      throw Problem(where + " has no valid componentType and type");
    }
    const std::uint64_t count = Count(accessor, "count", where);
    if (accessor.contains("sparse"))
    {
      throw Problem(where + " is sparse, which is not checked here and not taken");
    }
    if (!accessor.contains("bufferView") || count == 0)
    {
      continue;
    }
    const std::size_t view = accessor["bufferView"].get<std::size_t>();
    const std::uint64_t element = component * components;
    const std::uint64_t stride = std::max(viewStride[view], element);
    const std::uint64_t offset = Count(accessor, "byteOffset", where);
    // Bounded first, so the product cannot overflow.
    if (count > viewBytes[view] || offset + (count - 1) * stride + element > viewBytes[view])
    {
      throw Problem(where + " runs past the end of its buffer view");
    }
  }
  for (std::size_t i = 0; i < meshes; ++i)
  {
    const Json& mesh = root["meshes"][i];
    const std::string where = At("meshes", i);
    if (!mesh.contains("primitives") || !mesh["primitives"].is_array())
    {
      throw Problem(where + ".primitives is not an array");
    }
    const Json& primitives = mesh["primitives"];
    for (std::size_t p = 0; p < primitives.size(); ++p)
    {
      const Json& primitive = primitives[p];
      const std::string at = where + "." + At("primitives", p);
      if (!primitive.is_object())
      {
        throw Problem(at + " is not an object");
      }
      const Json* attributes = Object(primitive, "attributes", at);
      if (!attributes || !attributes->contains("POSITION"))
      {
        throw Problem(at + " has no POSITION attribute");
      }
      for (auto attribute = attributes->begin(); attribute != attributes->end(); ++attribute)
      {
        Index(*attributes, attribute.key().c_str(), accessors, at + ".attributes");
      }
      Index(primitive, "indices", accessors, at);
      Index(primitive, "material", materials, at);
      Count(primitive, "mode", at);
      if (primitive.contains("targets"))
      {
        if (!primitive["targets"].is_array())
        {
          throw Problem(at + ".targets is not an array");
        }
        for (const Json& target : primitive["targets"])
        {
          if (!target.is_object())
          {
            throw Problem(at + ".targets holds something not an object");
          }
          for (auto attribute = target.begin(); attribute != target.end(); ++attribute)
          {
            Index(target, attribute.key().c_str(), accessors, at + ".targets");
          }
        }
      }
    }
  }
  for (std::size_t i = 0; i < materials; ++i)
  {
    const Json& material = root["materials"][i];
    const std::string where = At("materials", i);
    const auto texture = [&](const Json& holder, const char* key, const std::string& at)
    {
      if (const Json* info = Object(holder, key, at))
      {
        Index(*info, "index", textures, at + "." + key);
      }
    };
    if (const Json* pbr = Object(material, "pbrMetallicRoughness", where))
    {
      const std::string at = where + ".pbrMetallicRoughness";
      texture(*pbr, "baseColorTexture", at);
      texture(*pbr, "metallicRoughnessTexture", at);
      Numbers(*pbr, "baseColorFactor", 4, at);
    }
    for (const char* key : { "normalTexture", "occlusionTexture", "emissiveTexture" })
    {
      texture(material, key, where);
    }
    Numbers(material, "emissiveFactor", 3, where);
  }
  for (std::size_t i = 0; i < textures; ++i)
  {
    Index(root["textures"][i], "source", images, At("textures", i));
    Index(root["textures"][i], "sampler", samplers, At("textures", i));
  }
  for (std::size_t i = 0; i < images; ++i)
  {
    Index(root["images"][i], "bufferView", views, At("images", i));
  }
  for (std::size_t i = 0; i < skins; ++i)
  {
    Indices(root["skins"][i], "joints", nodes, At("skins", i));
    Index(root["skins"][i], "inverseBindMatrices", accessors, At("skins", i));
  }
  if (root.contains("animations"))
  {
    for (std::size_t i = 0; i < root["animations"].size(); ++i)
    {
      const Json& animation = root["animations"][i];
      const std::string where = At("animations", i);
      const std::size_t animationSamplers = Collection(animation, "samplers");
      Collection(animation, "channels");
      for (std::size_t s = 0; s < animationSamplers; ++s)
      {
        Index(animation["samplers"][s], "input", accessors, where + "." + At("samplers", s));
        Index(animation["samplers"][s], "output", accessors, where + "." + At("samplers", s));
      }
      for (std::size_t c = 0; animation.contains("channels") && c < animation["channels"].size();
           ++c)
      {
        const Json& channel = animation["channels"][c];
        const std::string at = where + "." + At("channels", c);
        Index(channel, "sampler", animationSamplers, at);
        if (const Json* target = Object(channel, "target", at))
        {
          Index(*target, "node", nodes, at + ".target");
        }
      }
    }
  }
  for (std::size_t i = 0; i < cameras; ++i)
  {
    const Json& camera = root["cameras"][i];
    const std::string where = At("cameras", i);
    if (!camera.contains("type") || !camera["type"].is_string())
    {
      throw Problem(where + " has no type");
    }
    const std::string type = camera["type"].get<std::string>();
    if (type != "perspective" && type != "orthographic")
    {
      throw Problem(where + ".type is neither perspective nor orthographic");
    }
    if (!Object(camera, type.c_str(), where))
    {
      throw Problem(where + " has no " + type + " object");
    }
  }
}
}

//------------------------------------------------------------------------------
std::string FindGltfProblem(const std::filesystem::path& file)
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
  {
    return "cannot read the file";
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  try
  {
    const bool binary = bytes.compare(0, 4, "glTF") == 0;
    std::uint64_t binarySize = 0;
    const std::string text = binary ? ReadGlb(bytes, binarySize) : bytes;
    const Json root = Json::parse(text, nullptr, false);
    if (root.is_discarded())
    {
      return "its JSON does not parse";
    }
    CheckDocument(root, file.parent_path(), binary, binarySize);
  }
  catch (const Problem& problem)
  {
    return problem.what();
  }
  return {};
}
}
