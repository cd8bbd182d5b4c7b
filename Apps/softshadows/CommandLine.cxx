// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "CommandLine.h"

#include "SceneFile.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <regex>

namespace softshadows
{
namespace
{
bool Contains(std::initializer_list<const char*> names, const std::string& name)
{
  return std::any_of(
    names.begin(), names.end(), [&](const char* candidate) { return name == candidate; });
}

std::string KnownOptions(
  std::initializer_list<const char*> valued, std::initializer_list<const char*> flags)
{
  std::vector<const char*> all(valued);
  all.insert(all.end(), flags.begin(), flags.end());
  return KnownNames(all, [](const char* name) { return name; });
}
}

//------------------------------------------------------------------------------
CommandLine::CommandLine(const std::string& command, const std::vector<std::string>& arguments,
  bool needsScene, std::initializer_list<const char*> valued,
  std::initializer_list<const char*> flags)
  : Command(command)
{
  for (std::size_t i = 0; i < arguments.size(); ++i)
  {
    const std::string& argument = arguments[i];
    if (argument.size() < 2 || argument.compare(0, 2, "--") != 0)
    {
      if (!needsScene || !this->SceneFile.empty())
      {
        throw InputError(command, "unexpected argument '" + argument + "'");
      }
      this->SceneFile = argument;
      continue;
    }
    const auto equals = argument.find('=');
    const std::string name = argument.substr(0, equals);
    if (this->Values.count(name) || this->Flags.count(name))
    {
      throw InputError(name, "given twice");
    }
    if (Contains(flags, name) && equals == std::string::npos)
    {
      this->Flags.insert(name);
    }
    else if (Contains(valued, name))
    {
      if (equals != std::string::npos)
      {
        this->Values[name] = argument.substr(equals + 1);
      }
      else if (i + 1 < arguments.size())
      {
        this->Values[name] = arguments[++i];
      }
      else
      {
        throw InputError(name, "needs a value");
      }
    }
    else
    {
      throw InputError(name,
        Contains(flags, name)
          ? "takes no value"
          : "unknown option for '" + command + "' " + KnownOptions(valued, flags));
    }
  }
  if (needsScene && this->SceneFile.empty())
  {
    throw InputError(command, "needs a scene file: softshadows " + command + " SCENE.json ...");
  }
}

//------------------------------------------------------------------------------
bool CommandLine::Has(const std::string& option) const
{
  return this->Values.count(option) || this->Flags.count(option);
}

//------------------------------------------------------------------------------
const std::string& CommandLine::Value(const std::string& option) const
{
  auto found = this->Values.find(option);
  if (found == this->Values.end())
  {
    throw InputError(option, "required by '" + this->Command + "'");
  }
  return found->second;
}

//------------------------------------------------------------------------------
std::array<int, 2> CommandLine::Size() const
{
  if (!this->Has("--size"))
  {
    return { 0, 0 };
  }
  const std::string& text = this->Value("--size");
  static const std::regex pattern("([0-9]{1,6})x([0-9]{1,6})");
  std::smatch match;
  if (!std::regex_match(text, match, pattern))
  {
    throw InputError("--size", "expected WxH, e.g. 640x480, got '" + text + "'");
  }
  const std::array<int, 2> size = { std::stoi(match[1]), std::stoi(match[2]) };
  for (int extent : size)
  {
    if (extent < 1 || extent > MaximumWindowSize)
    {
      throw InputError("--size",
        "width and height must be in [1, " + std::to_string(MaximumWindowSize) + "], got '" + text +
          "'");
    }
  }
  return size;
}

//------------------------------------------------------------------------------
int CommandLine::Integer(const std::string& option, int minimum, int maximum, int fallback) const
{
  if (!this->Has(option))
  {
    return fallback;
  }
  const std::string& text = this->Value(option);
  static const std::regex pattern("[0-9]{1,9}");
  const bool valid =
    std::regex_match(text, pattern) && std::stoi(text) >= minimum && std::stoi(text) <= maximum;
  if (!valid)
  {
    const std::string range = maximum == std::numeric_limits<int>::max()
      ? ">= " + std::to_string(minimum)
      : "in [" + std::to_string(minimum) + ", " + std::to_string(maximum) + "]";
    throw InputError(option, "expected an integer " + range + ", got '" + text + "'");
  }
  return std::stoi(text);
}

//------------------------------------------------------------------------------
namespace
{
// A number the option's pattern matched; infinite past a double's range
// (std::stod would throw), which no range admits.
double ParsedNumber(const std::string& text)
{
  return std::strtod(text.c_str(), nullptr);
}
}

//------------------------------------------------------------------------------
double CommandLine::Number(
  const std::string& option, double minimum, double maximum, double fallback) const
{
  if (!this->Has(option))
  {
    return fallback;
  }
  const std::string& text = this->Value(option);
  static const std::regex pattern("[-+]?[0-9]*\\.?[0-9]+([eE][-+]?[0-9]+)?");
  const bool valid = std::regex_match(text, pattern) && ParsedNumber(text) >= minimum &&
    ParsedNumber(text) <= maximum;
  if (!valid)
  {
    throw InputError(option,
      "expected a number in [" + FormatNumber(minimum) + ", " + FormatNumber(maximum) + "], got '" +
        text + "'");
  }
  return ParsedNumber(text);
}

//------------------------------------------------------------------------------
std::array<double, 3> CommandLine::Vector(
  const std::string& option, const std::array<double, 3>& fallback) const
{
  if (!this->Has(option))
  {
    return fallback;
  }
  const std::string& text = this->Value(option);
  static const std::regex number("[-+]?[0-9]*\\.?[0-9]+([eE][-+]?[0-9]+)?");
  std::array<double, 3> vector{};
  std::size_t start = 0;
  for (int k = 0; k < 3; ++k)
  {
    const std::size_t comma = k < 2 ? text.find(',', start) : text.size();
    const std::string item =
      comma == std::string::npos ? std::string() : text.substr(start, comma - start);
    if (!std::regex_match(item, number) || !std::isfinite(ParsedNumber(item)))
    {
      throw InputError(option, "expected X,Y,Z (three numbers), got '" + text + "'");
    }
    vector[k] = ParsedNumber(item);
    start = comma + 1;
  }
  return vector;
}

//------------------------------------------------------------------------------
std::vector<TechniqueSpec> CommandLine::TechniqueList(const std::string& option) const
{
  const std::string& text = this->Value(option);
  std::vector<TechniqueSpec> specs;
  std::size_t start = 0;
  while (start <= text.size())
  {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, comma - start);
    if (item.empty())
    {
      throw InputError(option, "empty technique in '" + text + "'");
    }
    TechniqueSpec spec = ParseTechniqueSpec(item, option);
    for (const TechniqueSpec& earlier : specs)
    {
      if (earlier.ToString() == spec.ToString())
      {
        throw InputError(option, "'" + item + "' is listed twice");
      }
    }
    specs.push_back(spec);
    start = comma + 1;
  }
  return specs;
}
}
