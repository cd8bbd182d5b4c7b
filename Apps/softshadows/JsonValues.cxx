// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "JsonValues.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace softshadows
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

[[noreturn]] void Fail(const std::string& path, const std::string& problem)
{
  throw InputError(path, problem);
}

void CheckNumber(const Json& value, const Range& range, const std::string& path)
{
  if (!value.is_number())
  {
    Fail(path, "expected a number");
  }
  if (!range.Contains(value.get<double>()))
  {
    Fail(path, range.Describe() + ", got " + value.dump());
  }
}

void CheckInteger(const Json& value, const Range& range, const std::string& path)
{
  if (!value.is_number_integer())
  {
    Fail(path, "expected an integer");
  }
  // Integers past int's range are refused here, so callers can use get<int>().
  const Range limits =
    Range::Between(std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
  const double number = value.get<double>();
  if (!range.Contains(number) || !limits.Contains(number))
  {
    Fail(path, (range.Contains(number) ? limits : range).Describe() + ", got " + value.dump());
  }
}

void CheckNumbers(const Json& value, std::size_t count, const Range& range, const std::string& path)
{
  if (!value.is_array() || value.size() != count)
  {
    Fail(path, "expected an array of " + std::to_string(count) + " numbers");
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    CheckNumber(value[i], range, IndexPath(path, i));
  }
}
}

//------------------------------------------------------------------------------
std::string Printable(const std::string& text, std::size_t limit)
{
  std::string out;
  std::size_t shown = 0;
  std::size_t i = 0;
  for (; i < text.size() && shown < limit; ++shown)
  {
    const auto c = static_cast<unsigned char>(text[i]);
    // A whole UTF-8 sequence is one character; anything else a byte.
    std::size_t length = c < 0x80 ? 1
      : (c >> 5) == 0x6           ? 2
      : (c >> 4) == 0xE           ? 3
      : (c >> 3) == 0x1E          ? 4
                                  : 0;
    for (std::size_t k = 1; k < length; ++k)
    {
      if (i + k >= text.size() || (static_cast<unsigned char>(text[i + k]) >> 6) != 0x2)
      {
        length = 0;
      }
    }
    if (length == 0 || c < 0x20 || c == 0x7F)
    {
      static const char digits[] = "0123456789abcdef";
      out += "\\x";
      out += digits[c >> 4];
      out += digits[c & 0xF];
      ++i;
      continue;
    }
    out.append(text, i, length);
    i += length;
  }
  if (i < text.size())
  {
    out += "... (" + std::to_string(text.size() - i) + " more bytes)";
  }
  return out;
}

//------------------------------------------------------------------------------
InputError::InputError(std::string where, const std::string& problem)
  : std::runtime_error(Printable(problem))
  , Location(Printable(where))
{
}

//------------------------------------------------------------------------------
InputError InputError::InFile(const std::string& file) const
{
  InputError located(*this);
  located.FileName = file;
  return located;
}

//------------------------------------------------------------------------------
std::string FieldPath(const std::string& parent, const std::string& key)
{
  return parent.empty() ? key : parent + "." + key;
}

//------------------------------------------------------------------------------
std::string IndexPath(const std::string& parent, std::size_t index)
{
  return parent + "[" + std::to_string(index) + "]";
}

//------------------------------------------------------------------------------
void CheckObject(
  const Json& value, const std::string& path, std::initializer_list<const char*> known)
{
  if (!value.is_object())
  {
    Fail(path, "expected an object");
  }
  for (const auto& item : value.items())
  {
    const bool found =
      std::any_of(known.begin(), known.end(), [&](const char* key) { return item.key() == key; });
    if (!found)
    {
      Fail(FieldPath(path, item.key()),
        "unknown field " + KnownNames(known, [](const char* key) { return key; }));
    }
  }
}

//------------------------------------------------------------------------------
void RequireField(const Json& value, const std::string& path, const char* key)
{
  if (!value.contains(key))
  {
    Fail(FieldPath(path, key), "missing required field");
  }
}

//------------------------------------------------------------------------------
Range Range::Any()
{
  return { -Infinity, Infinity, false };
}

//------------------------------------------------------------------------------
Range Range::AtLeast(double minimum)
{
  return { minimum, Infinity, false };
}

//------------------------------------------------------------------------------
Range Range::Positive()
{
  return { 0.0, Infinity, true };
}

//------------------------------------------------------------------------------
Range Range::Between(double minimum, double maximum)
{
  return { minimum, maximum, false };
}

//------------------------------------------------------------------------------
bool Range::Contains(double number) const
{
  const bool aboveMinimum =
    this->ExclusiveMinimum ? number > this->Minimum : number >= this->Minimum;
  return aboveMinimum && number <= this->Maximum;
}

//------------------------------------------------------------------------------
std::string Range::Describe() const
{
  const std::string lower = (this->ExclusiveMinimum ? "> " : ">= ") + FormatNumber(this->Minimum);
  if (this->Maximum == Infinity)
  {
    return this->Minimum == -Infinity ? std::string() : "must be " + lower;
  }
  if (this->Minimum == -Infinity)
  {
    return "must be <= " + FormatNumber(this->Maximum);
  }
  if (this->ExclusiveMinimum)
  {
    return "must be " + lower + " and <= " + FormatNumber(this->Maximum);
  }
  return "must be in [" + FormatNumber(this->Minimum) + ", " + FormatNumber(this->Maximum) + "]";
}

//------------------------------------------------------------------------------
const char* TypeName(ValueType type)
{
  switch (type)
  {
    case ValueType::Boolean:
      return "boolean";
    case ValueType::Integer:
      return "integer";
    case ValueType::Number:
      return "number";
    case ValueType::Vector3:
      return "[x, y, z]";
    case ValueType::Size2:
      return "number or [a, b]";
    case ValueType::Size3:
      return "number or [a, b, c]";
  }
  return "";
}

//------------------------------------------------------------------------------
void CheckValue(const Json& value, ValueType type, const Range& range, const std::string& path)
{
  switch (type)
  {
    case ValueType::Boolean:
      ReadBoolean(value, path);
      return;
    case ValueType::Integer:
      CheckInteger(value, range, path);
      return;
    case ValueType::Number:
      CheckNumber(value, range, path);
      return;
    case ValueType::Vector3:
      CheckNumbers(value, 3, range, path);
      return;
    case ValueType::Size2:
    case ValueType::Size3:
      if (value.is_array())
      {
        CheckNumbers(value, type == ValueType::Size2 ? 2 : 3, range, path);
      }
      else if (value.is_number())
      {
        CheckNumber(value, range, path);
      }
      else
      {
        Fail(path, std::string("expected a ") + TypeName(type));
      }
      return;
  }
}

//------------------------------------------------------------------------------
std::vector<double> Components(const Json& value, std::size_t count)
{
  if (value.is_number())
  {
    return std::vector<double>(count, value.get<double>());
  }
  return value.get<std::vector<double>>();
}

//------------------------------------------------------------------------------
double ReadNumber(const Json& value, const std::string& path, const Range& range)
{
  CheckNumber(value, range, path);
  return value.get<double>();
}

//------------------------------------------------------------------------------
int ReadInteger(const Json& value, const std::string& path, const Range& range)
{
  CheckInteger(value, range, path);
  return value.get<int>();
}

//------------------------------------------------------------------------------
bool ReadBoolean(const Json& value, const std::string& path)
{
  if (!value.is_boolean())
  {
    Fail(path, "expected true or false");
  }
  return value.get<bool>();
}

//------------------------------------------------------------------------------
std::string ReadString(const Json& value, const std::string& path)
{
  if (!value.is_string())
  {
    Fail(path, "expected a string");
  }
  return value.get<std::string>();
}

//------------------------------------------------------------------------------
Vector3 ReadVector3(const Json& value, const std::string& path)
{
  CheckNumbers(value, 3, Range::Any(), path);
  return { value[0].get<double>(), value[1].get<double>(), value[2].get<double>() };
}

//------------------------------------------------------------------------------
Vector3 ReadColor(const Json& value, const std::string& path)
{
  CheckNumbers(value, 3, Range::Between(0.0, 1.0), path);
  return { value[0].get<double>(), value[1].get<double>(), value[2].get<double>() };
}

//------------------------------------------------------------------------------
std::string FormatNumber(double number)
{
  if (std::isinf(number))
  {
    return number > 0 ? "inf" : "-inf";
  }
  // Whole numbers in full (a seed's 4294967295), the rest as streams print.
  if (number == std::floor(number) && std::fabs(number) < 1e15)
  {
    return std::to_string(static_cast<long long>(number));
  }
  std::ostringstream text;
  text << number;
  return text.str();
}
}
