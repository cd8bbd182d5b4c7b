// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "PlyFiles.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

namespace softshadows
{
namespace
{
// vtkPLY reads lines with getline(buffer, 4096) and writes a space at 4094.
constexpr std::size_t MaximumLineLength = 4093;
// vtkPLYReader keeps a face's ids in vtkIdType[256] and its count in a byte.
constexpr long long MaximumListLength = 255;

enum class Format
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

struct ScalarType
{
  const char* Name;
  int Size;
  bool Integer;
  bool Signed;
};

// vtkPLY's type names, in both spellings.
const ScalarType ScalarTypes[] = { { "char", 1, true, true }, { "int8", 1, true, true },
  { "uchar", 1, true, false }, { "uint8", 1, true, false }, { "short", 2, true, true },
  { "int16", 2, true, true }, { "ushort", 2, true, false }, { "uint16", 2, true, false },
  { "int", 4, true, true }, { "int32", 4, true, true }, { "uint", 4, true, false },
  { "uint32", 4, true, false }, { "float", 4, false, true }, { "float32", 4, false, true },
  { "double", 8, false, true }, { "float64", 8, false, true } };

const ScalarType* FindType(const std::string& name)
{
  for (const ScalarType& type : ScalarTypes)
  {
    if (name == type.Name)
    {
      return &type;
    }
  }
  return nullptr;
}

struct Property
{
  std::string Name;
  const ScalarType* Type = nullptr;
  const ScalarType* CountType = nullptr; // lists only
  bool IsList() const { return this->CountType != nullptr; }
};

struct Element
{
  std::string Name;
  long long Count = 0;
  std::vector<Property> Properties;

  const Property* Find(const std::string& name) const
  {
    for (const Property& property : this->Properties)
    {
      if (property.Name == name)
      {
        return &property; // the reader, too, takes the first of a name
      }
    }
    return nullptr;
  }
};

// What the reader reads by name, and how: scalars, except the two lists.
const char* const VertexScalars[] = { "x", "y", "z", "u", "v", "texture_u", "texture_v", "nx", "ny",
  "nz", "red", "green", "blue", "alpha", "diffuse_red", "diffuse_green", "diffuse_blue" };
const char* const FaceScalars[] = { "intensity", "red", "green", "blue", "alpha" };

[[noreturn]] void Fail(const std::string& problem)
{
  throw std::runtime_error(problem);
}

// Words as vtkPLY's get_words() splits a line: up to the first NUL, at spaces,
// tabs and carriage returns, with "vertex_index" renamed and the rest of the
// line dropped after it.
std::vector<std::string> SplitWords(std::string line)
{
  line = line.substr(0, line.find('\0'));
  const std::size_t renamed = line.find("vertex_index");
  if (renamed != std::string::npos)
  {
    line = line.substr(0, renamed) + "vertex_indices";
  }
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
    {
      ++i;
    }
    std::size_t end = i;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\r')
    {
      ++end;
    }
    if (end > i)
    {
      words.push_back(line.substr(i, end - i));
    }
    i = end;
  }
  return words;
}

// A non-negative decimal integer that fits an int, as atoi() must read it.
bool ParseCount(const std::string& word, long long& value)
{
  if (word.empty() || word.size() > 10 || word.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  value = std::stoll(word);
  return value <= std::numeric_limits<int>::max();
}

// A whole word that strtod() reads as a number.
bool ParseNumber(const std::string& word, double& value)
{
  char* end = nullptr;
  errno = 0;
  value = std::strtod(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size();
}

class Body
{
public:
  Body(const std::string& bytes, std::size_t start, int headerLines, Format format)
    : Bytes(bytes)
    , Position(start)
    , Kind(format)
    , Line(headerLines)
  {
  }

  /// Reads one instance of `element` (number `index`); point ids of
  /// "vertex_indices" must be below `numVertices`.
  void ReadInstance(const Element& element, long long index, long long numVertices)
  {
    if (this->Kind == Format::Ascii)
    {
      this->StartLine(element, index);
    }
    for (const Property& property : element.Properties)
    {
      const bool indices = property.Name == "vertex_indices";
      const bool stored = indices || property.Name == "texcoord";
      if (!property.IsList())
      {
        this->Read(*property.Type, element, index, property);
        continue;
      }
      const double count = this->Read(*property.CountType, element, index, property);
      if (count < 0 || count != std::floor(count) || (stored && count > MaximumListLength))
      {
        Fail(this->Describe(element, index) + ": the list '" + property.Name + "' has " +
          Number(count) + " items; VTK's PLY reader takes 0 to " +
          std::to_string(MaximumListLength));
      }
      for (long long k = 0; k < static_cast<long long>(count); ++k)
      {
        const double value = this->Read(*property.Type, element, index, property);
        if (indices && (value < 0 || value >= numVertices || value != std::floor(value)))
        {
          Fail(this->Describe(element, index) + " uses vertex " + Number(value) +
            ", but the file has " + std::to_string(numVertices) + " vertices");
        }
      }
    }
  }

private:
  static std::string Number(double value)
  {
    std::string text = std::to_string(value);
    return value == std::floor(value) && std::fabs(value) < 1e15
      ? std::to_string(static_cast<long long>(value))
      : text;
  }

  std::string Describe(const Element& element, long long index) const
  {
    std::string where = element.Name + " " + std::to_string(index);
    if (this->Kind == Format::Ascii)
    {
      where += " (line " + std::to_string(this->Line) + ")";
    }
    return where;
  }

  void StartLine(const Element& element, long long index)
  {
    const std::size_t end = this->Bytes.find('\n', this->Position);
    if (end == std::string::npos)
    {
      Fail("the file ends before " + element.Name + " " + std::to_string(index) + " of " +
        std::to_string(element.Count) + " (every line, the last too, must end with a newline)");
    }
    ++this->Line;
    if (end - this->Position > MaximumLineLength)
    {
      Fail("line " + std::to_string(this->Line) + " is longer than " +
        std::to_string(MaximumLineLength) + " characters");
    }
    this->Words = SplitWords(this->Bytes.substr(this->Position, end - this->Position));
    this->Word = 0;
    this->Position = end + 1;
  }

  double Read(
    const ScalarType& type, const Element& element, long long index, const Property& property)
  {
    if (this->Kind == Format::Ascii)
    {
      double value = 0.0;
      if (this->Word >= this->Words.size())
      {
        Fail(this->Describe(element, index) + " has too few numbers (ran out at '" + property.Name +
          "')");
      }
      const std::string& word = this->Words[this->Word++];
      // Integers are read with atoi() or strtoul(): digits only, in range.
      const bool integer = !word.empty() &&
        word.find_first_not_of("0123456789", word[0] == '-' || word[0] == '+' ? 1 : 0) ==
          std::string::npos &&
        word.size() > (word[0] == '-' || word[0] == '+' ? 1u : 0u);
      if (!ParseNumber(word, value) || (type.Integer && !integer))
      {
        Fail(this->Describe(element, index) + ": '" + property.Name + "' is not " +
          (type.Integer ? "an integer" : "a number"));
      }
      const double limit = type.Signed ? 2147483647.0 : 4294967295.0;
      if (type.Integer && (value > limit || value < (type.Signed ? -limit - 1 : 0.0)))
      {
        Fail(this->Describe(element, index) + ": '" + property.Name + "' is out of range");
      }
      return value;
    }
    if (this->Bytes.size() - this->Position < static_cast<std::size_t>(type.Size))
    {
      Fail("the file ends inside " + element.Name + " " + std::to_string(index) + " of " +
        std::to_string(element.Count));
    }
    unsigned char raw[8];
    std::memcpy(raw, this->Bytes.data() + this->Position, type.Size);
    this->Position += type.Size;
    const bool little = this->Kind == Format::BinaryLittleEndian;
    std::uint64_t bits = 0;
    for (int i = 0; i < type.Size; ++i)
    {
      bits |= std::uint64_t(raw[little ? i : type.Size - 1 - i]) << (8 * i);
    }
    if (!type.Integer)
    {
      if (type.Size == 4)
      {
        float value;
        const std::uint32_t narrow = static_cast<std::uint32_t>(bits);
        std::memcpy(&value, &narrow, 4);
        return value;
      }
      double value;
      std::memcpy(&value, &bits, 8);
      return value;
    }
    if (type.Signed && (bits >> (8 * type.Size - 1)) != 0)
    {
      return static_cast<double>(static_cast<std::int64_t>(bits)) - std::ldexp(1.0, 8 * type.Size);
    }
    return static_cast<double>(bits);
  }

  const std::string& Bytes;
  std::size_t Position;
  Format Kind;
  long long Line; // of the file; counted in ASCII bodies only
  std::vector<std::string> Words;
  std::size_t Word = 0;
};

std::string CheckPly(const std::string& bytes)
{
  // The header, line by line, as vtkPLY::ply_read() reads it.
  std::size_t position = 0;
  int lineNumber = 0;
  auto nextLine = [&]()
  {
    const std::size_t end = bytes.find('\n', position);
    ++lineNumber;
    if (end == std::string::npos)
    {
      Fail("the header does not end (no end_header line)");
    }
    if (end - position > MaximumLineLength)
    {
      Fail("header line " + std::to_string(lineNumber) + " is longer than " +
        std::to_string(MaximumLineLength) + " characters");
    }
    std::vector<std::string> words = SplitWords(bytes.substr(position, end - position));
    position = end + 1;
    return words;
  };

  std::vector<std::string> words = nextLine();
  if (words.empty() || words[0] != "ply")
  {
    Fail("it does not start with the line 'ply'");
  }
  bool haveFormat = false;
  Format format = Format::Ascii;
  std::vector<Element> elements;
  for (;;)
  {
    words = nextLine();
    const std::string where = "header line " + std::to_string(lineNumber);
    if (words.empty())
    {
      Fail(where + " is blank, before end_header");
    }
    const std::string& keyword = words[0];
    if (keyword == "end_header")
    {
      break;
    }
    if (keyword == "format")
    {
      if (words.size() != 3 ||
        (words[1] != "ascii" && words[1] != "binary_little_endian" &&
          words[1] != "binary_big_endian"))
      {
        Fail(where + ": expected 'format ascii|binary_little_endian|binary_big_endian VERSION'");
      }
      format = words[1] == "ascii"        ? Format::Ascii
        : words[1] == "binary_big_endian" ? Format::BinaryBigEndian
                                          : Format::BinaryLittleEndian;
      haveFormat = true;
    }
    else if (keyword == "element")
    {
      Element element;
      if (words.size() != 3 || !ParseCount(words[2], element.Count))
      {
        Fail(where + ": expected 'element NAME COUNT' with a COUNT from 0 to " +
          std::to_string(std::numeric_limits<int>::max()));
      }
      element.Name = words[1];
      elements.push_back(element);
    }
    else if (keyword == "property")
    {
      if (elements.empty())
      {
        Fail(where + ": a property before any element");
      }
      Property property;
      const bool list = words.size() >= 2 && words[1] == "list";
      if (list && words.size() == 5)
      {
        property.CountType = FindType(words[2]);
        property.Type = FindType(words[3]);
        property.Name = words[4];
        if (property.CountType && !property.CountType->Integer)
        {
          Fail(where + ": a list's count must have an integer type, not " + words[2]);
        }
      }
      else if (!list && words.size() == 3)
      {
        property.Type = FindType(words[1]);
        property.Name = words[2];
      }
      else
      {
        Fail(where + ": expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      }
      if (!property.Type || (list && !property.CountType))
      {
        Fail(where +
          ": unknown type (the types are char uchar short ushort int uint float "
          "double and int8 ... float64)");
      }
      elements.back().Properties.push_back(property);
    }
    // comment, obj_info and unknown keywords are skipped, as the reader does.
  }
  if (!haveFormat)
  {
    Fail("the header has no format line");
  }
  // The reader leaves an element's property list unset until its first
  // property, and frees it when it closes the file.
  for (const Element& element : elements)
  {
    if (element.Properties.empty())
    {
      Fail("the element '" + element.Name + "' has no properties");
    }
  }

  // The reader walks the elements in order and reads only "vertex" and
  // "face", without skipping others: nothing may come before them.
  if (elements.empty() || elements[0].Name != "vertex")
  {
    Fail("the first element must be 'vertex'");
  }
  const Element& vertex = elements[0];
  const Element* face = elements.size() > 1 && elements[1].Name == "face" ? &elements[1] : nullptr;
  for (std::size_t i = 1; i < elements.size(); ++i)
  {
    if ((elements[i].Name == "vertex" || elements[i].Name == "face") && &elements[i] != face)
    {
      Fail("element '" + elements[i].Name +
        "' must come once, 'vertex' first and 'face' right after it");
    }
  }
  for (const char* name : { "x", "y", "z" })
  {
    const Property* p = vertex.Find(name);
    if (!p)
    {
      Fail(std::string("the vertices have no '") + name + "' property");
    }
  }
  auto checkScalars = [](const Element& element, const auto& names)
  {
    for (const char* name : names)
    {
      const Property* p = element.Find(name);
      if (p && p->IsList())
      {
        Fail("the " + element.Name + " property '" + name + "' must not be a list");
      }
    }
  };
  checkScalars(vertex, VertexScalars);
  if (face)
  {
    checkScalars(*face, FaceScalars);
    const Property* indices = face->Find("vertex_indices");
    if (!indices || !indices->IsList() || !indices->Type->Integer)
    {
      Fail("the faces have no 'vertex_indices' list of integers");
    }
    const Property* texcoord = face->Find("texcoord");
    if (texcoord && !texcoord->IsList())
    {
      Fail("the face property 'texcoord' must be a list");
    }
  }

  // vtkPLY's ASCII element reader looks up the size of every list's item
  // type, including the lists nobody asked for, whose type it never set: in
  // ASCII files only the lists the reader reads may appear (the faces'
  // vertex_indices, and texcoord unless the vertices have their own).
  if (format == Format::Ascii)
  {
    const bool vertexTexture = (vertex.Find("u") && vertex.Find("v")) ||
      (vertex.Find("texture_u") && vertex.Find("texture_v"));
    for (const Element* element : { &vertex, face })
    {
      for (std::size_t p = 0; element && p < element->Properties.size(); ++p)
      {
        const Property& property = element->Properties[p];
        // (Of two properties of one name, the reader reads the first.)
        const bool read = element == face && element->Find(property.Name) == &property &&
          (property.Name == "vertex_indices" || (property.Name == "texcoord" && !vertexTexture));
        if (property.IsList() && !read)
        {
          Fail("the " + element->Name + " property '" + property.Name +
            "' is a list VTK's reader does not read, which in an ASCII file it cannot skip");
        }
      }
    }
  }

  Body body(bytes, position, lineNumber, format);
  for (long long i = 0; i < vertex.Count; ++i)
  {
    body.ReadInstance(vertex, i, 0);
  }
  for (long long i = 0; face && i < face->Count; ++i)
  {
    body.ReadInstance(*face, i, vertex.Count);
  }
  return std::string();
}
}

//------------------------------------------------------------------------------
std::string FindPlyProblem(const std::string& bytes)
{
  try
  {
    return CheckPly(bytes);
  }
  catch (const std::runtime_error& error)
  {
    return error.what();
  }
}
}
