// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "ObjFiles.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace softshadows
{
namespace
{
// vtkOBJReader reads lines with fgets(rawLine, 256 KiB) and material names
// with sscanf("%s") into char[100].
constexpr std::size_t LineBuffer = 1024 * 256;
constexpr std::size_t MaximumMaterialName = 99;

bool IsSpace(char c)
{
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// The file as fgets() hands it to the reader: pieces up to and including a
// newline, of at most LineBuffer - 1 bytes.
std::vector<std::string> Lines(const std::string& bytes)
{
  std::vector<std::string> lines;
  for (std::size_t start = 0; start < bytes.size();)
  {
    const std::size_t newline = bytes.find('\n', start);
    const std::size_t end = newline == std::string::npos ? bytes.size() : newline + 1;
    const std::size_t size = std::min(end - start, LineBuffer - 1);
    lines.push_back(bytes.substr(start, size));
    start += size;
  }
  return lines;
}

// A line's command and where its arguments start, as the reader splits it:
// the first word, and the rest after the one character that ends it.
struct Command
{
  std::string Name;
  const char* Arguments;
  const char* End;
};

Command Split(const std::string& line)
{
  const char* p = line.c_str();
  const char* end = p + line.size();
  while (p < end && IsSpace(*p))
  {
    ++p;
  }
  const char* name = p;
  while (p < end && !IsSpace(*p))
  {
    ++p;
  }
  Command command{ std::string(name, p), p < end ? p + 1 : p, end };
  return command;
}

// The word sscanf("%s") reads.
std::string FirstWord(const char* p, const char* end)
{
  while (p < end && IsSpace(*p))
  {
    ++p;
  }
  const char* word = p;
  while (p < end && !IsSpace(*p))
  {
    ++p;
  }
  return std::string(word, p);
}

std::string At(std::size_t line)
{
  return "line " + std::to_string(line + 1) + ": ";
}

struct Face
{
  std::size_t Line;
  std::vector<int> Vertices; // 0-based, as the reader resolves them
  std::vector<int> Normals;
  int TextureCoordinates = 0;
};
}

//------------------------------------------------------------------------------
std::string FindObjProblem(const std::string& bytes)
{
  // fgets() and strlen() would disagree on a line holding one.
  const std::size_t nul = bytes.find('\0');
  if (nul != std::string::npos)
  {
    return "byte " + std::to_string(nul) + " is a NUL, and an OBJ file is text";
  }
  const std::vector<std::string> lines = Lines(bytes);

  // The reader's first pass: material names, and the texture coordinates
  // every face's are looked up in. A line too long ends it (and the read).
  int textureCoordinates = 0, allPoints = 0;
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    const Command command = Split(lines[i]);
    if (command.Name == "usemtl")
    {
      const std::string name = FirstWord(command.Arguments, command.End);
      if (name.size() > MaximumMaterialName)
      {
        return At(i) + "a material name of " + std::to_string(name.size()) +
          " characters; VTK's OBJ reader takes at most " + std::to_string(MaximumMaterialName);
      }
      if (name.empty())
      {
        return std::string(); // the reader refuses it, saying so
      }
    }
    else if (command.Name == "vt")
    {
      ++textureCoordinates;
    }
    else if (command.Name == "v")
    {
      ++allPoints;
    }
    const bool last = i + 1 == lines.size();
    if (lines[i].back() != '\n' && !(last && lines[i].size() < LineBuffer - 1))
    {
      return std::string(); // "Line longer than": the reader stops
    }
  }

  // The second pass: elements, with indices counted back from the line when
  // negative; continuation lines belong to the element before.
  int points = 0, normals = 0, textureSoFar = 0;
  bool hasTextureCoordinates = false, hasNormals = false;
  bool textureAsVertices = true, normalsAsVertices = true;
  std::vector<Face> faces;
  for (std::size_t i = 0; i < lines.size(); ++i)
  {
    const Command command = Split(lines[i]);
    const std::string& name = command.Name;
    if (name == "v")
    {
      ++points;
    }
    else if (name == "vt")
    {
      ++textureSoFar;
    }
    else if (name == "vn")
    {
      ++normals;
      hasNormals = true;
    }
    else if (name == "p" || name == "l" || name == "f")
    {
      const bool isFace = name == "f";
      Face face{ i, {}, {} };
      int count = 0;
      const char* p = command.Arguments;
      const char* end = command.End;
      while (p < end)
      {
        while (p < end && IsSpace(*p))
        {
          ++p;
        }
        if (p >= end)
        {
          break;
        }
        int vertex = 0, texture = 0, normal = 0;
        bool hasTexture = false, hasNormal = false;
        if (isFace && std::sscanf(p, "%d/%d/%d", &vertex, &texture, &normal) == 3)
        {
          hasTexture = hasNormal = true;
        }
        else if (isFace && std::sscanf(p, "%d//%d", &vertex, &normal) == 2)
        {
          hasNormal = true;
        }
        else if (isFace && std::sscanf(p, "%d/%d", &vertex, &texture) == 2)
        {
          hasTexture = true;
        }
        else if (name == "l" && std::sscanf(p, "%d/%d", &vertex, &texture) == 2)
        {
          // a line's texture coordinates are ignored
        }
        else if (std::sscanf(p, "%d", &vertex) == 1)
        {
        }
        else if (std::strcmp(p, "\\\n") == 0)
        {
          if (++i == lines.size())
          {
            return std::string(); // the reader refuses a continuation at the end
          }
          p = lines[i].c_str();
          end = p + lines[i].size();
          continue;
        }
        else
        {
          return std::string(); // "Error reading 'f' at line ..."
        }
        ++count;
        // Every release refuses these, but not alike (VTK 9.4's reader
        // itself, earlier ones through the mesh check after it).
        const char* what = isFace ? "a face" : (name == "l" ? "a line" : "a point");
        if (vertex == 0)
        {
          return At(i) + what + " uses vertex 0, and OBJ counts vertices from 1";
        }
        if (vertex < 0 && points + vertex < 0)
        {
          return At(i) + what + " uses vertex " + std::to_string(vertex) + ", but " +
            std::to_string(points) + " come before it";
        }
        if (vertex > allPoints)
        {
          return At(i) + what + " uses vertex " + std::to_string(vertex) +
            " (counted from 1), but the file has " + std::to_string(allPoints);
        }
        if (isFace)
        {
          face.Vertices.push_back(vertex < 0 ? points + vertex : vertex - 1);
        }
        if (hasTexture)
        {
          // Looked up as the face is read, among all the file's.
          const int index = texture < 0 ? textureSoFar + texture : texture - 1;
          if (index < 0 || index >= textureCoordinates)
          {
            return At(face.Line) + "a face uses texture coordinate " + std::to_string(texture) +
              ", but the file has " + std::to_string(textureCoordinates);
          }
          ++face.TextureCoordinates;
          textureAsVertices = textureAsVertices && texture == vertex;
        }
        if (hasNormal)
        {
          face.Normals.push_back(normal < 0 ? normals + normal : normal - 1);
          normalsAsVertices = normalsAsVertices && normal == vertex;
        }
        while (p < end && !IsSpace(*p))
        {
          ++p;
        }
      }
      const int corners = static_cast<int>(face.Vertices.size());
      if ((name == "p" && count < 1) || (name == "l" && count < 2) ||
        (isFace &&
          (corners < 3 || (face.TextureCoordinates > 0 && face.TextureCoordinates != corners) ||
            (!face.Normals.empty() && static_cast<int>(face.Normals.size()) != corners))))
      {
        return std::string(); // "Error reading file near line ..."
      }
      if (isFace)
      {
        hasTextureCoordinates = hasTextureCoordinates || face.TextureCoordinates > 0;
        hasNormals = hasNormals || !face.Normals.empty();
        faces.push_back(std::move(face));
      }
    }
    else if (name == "usemtl" && FirstWord(command.Arguments, command.End).empty())
    {
      return std::string();
    }
  }

  // Faces numbering texture coordinates or normals apart from their vertices
  // make the reader copy every face's corners by index (it skips a face
  // without normals when others have them). Otherwise the vertex ids are
  // the output's, checked with every mesh.
  if ((hasTextureCoordinates && !textureAsVertices) || (hasNormals && !normalsAsVertices))
  {
    for (const Face& face : faces)
    {
      const auto corners = face.Vertices.size();
      if (hasNormals && face.Normals.size() != corners)
      {
        continue;
      }
      for (std::size_t c = 0; c < corners; ++c)
      {
        if (face.Vertices[c] < 0 || face.Vertices[c] >= points)
        {
          return At(face.Line) + "a face uses vertex " + std::to_string(face.Vertices[c] + 1) +
            " (counted from 1), but the file has " + std::to_string(points);
        }
        if (!face.Normals.empty() && (face.Normals[c] < 0 || face.Normals[c] >= normals))
        {
          return At(face.Line) + "a face uses normal " + std::to_string(face.Normals[c] + 1) +
            " (counted from 1), but the file has " + std::to_string(normals);
        }
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string AbsoluteObjIndices(const std::string& bytes)
{
  // Vertices, texture coordinates and normals read so far: what a relative
  // index counts back from.
  long counts[3] = { 0, 0, 0 };
  std::string out;
  out.reserve(bytes.size());
  bool continued = false; // the line continues an element's
  for (std::size_t start = 0; start < bytes.size();)
  {
    const std::size_t newline = bytes.find('\n', start);
    const std::size_t end = newline == std::string::npos ? bytes.size() : newline + 1;
    const std::string line = bytes.substr(start, end - start);
    start = end;
    std::size_t first = 0; // where the element's words start
    if (!continued)
    {
      const Command command = Split(line);
      const std::string& name = command.Name;
      if (name == "v" || name == "vt" || name == "vn")
      {
        ++counts[name == "v" ? 0 : (name == "vt" ? 1 : 2)];
      }
      if (name != "f" && name != "l" && name != "p")
      {
        out += line;
        continue;
      }
      first = static_cast<std::size_t>(command.Arguments - line.c_str());
    }
    out += line.substr(0, first);
    // Each word is v, v/t, v//n or v/t/n: its k-th number indexes counts[k].
    // Only a number that starts its slot is one: the reader refuses "--2"
    // or "1-2", and rewriting the "-2" in them would hand it a negative
    // index it reads (and indexes arrays with: found by fuzzing).
    int slot = 0;
    for (std::size_t i = first; i < line.size();)
    {
      const char c = line[i];
      const bool starts = i == first || IsSpace(line[i - 1]) || line[i - 1] == '/';
      if (c == '-' && starts && slot < 3 && i + 1 < line.size() &&
        std::isdigit(static_cast<unsigned char>(line[i + 1])))
      {
        char* after = nullptr;
        const long index = std::strtol(line.c_str() + i, &after, 10);
        out += std::to_string(counts[slot] + index + 1);
        i = static_cast<std::size_t>(after - line.c_str());
        continue;
      }
      slot = IsSpace(c) ? 0 : (c == '/' ? slot + 1 : slot);
      out += c;
      ++i;
    }
    // A backslash before the newline continues the element on the next line.
    const std::size_t last = line.find_last_not_of("\r\n");
    continued = last != std::string::npos && line[last] == '\\';
  }
  return out;
}

//------------------------------------------------------------------------------
TemporaryFile::TemporaryFile(const std::string& text, const std::string& suffix)
{
  static int count = 0;
  this->File = std::filesystem::temp_directory_path() /
    ("softshadows-" + std::to_string(::getpid()) + "-" + std::to_string(count++) + suffix);
  std::ofstream out(this->File, std::ios::binary);
  out << text;
  if (!out)
  {
    throw std::runtime_error("cannot write " + this->File.string() + " for VTK's reader");
  }
}

TemporaryFile::~TemporaryFile()
{
  std::error_code error;
  std::filesystem::remove(this->File, error);
}
}
