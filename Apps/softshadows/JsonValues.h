// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Reading typed values out of nlohmann::json with errors that name the field.
 *
 * Every check throws InputError with the path of the offending field
 * (`lights[0].cone_angle`), so main() can print one message in the form
 * `scene.json: lights[0].cone_angle: expected a number` and exit with 2.
 */

#ifndef softshadows_JsonValues_h
#define softshadows_JsonValues_h

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

namespace softshadows
{
using Json = nlohmann::json;
using Vector3 = std::array<double, 3>;

/**
 * `text` made fit for one line of a message: control characters and bytes
 * that are not UTF-8 written as \xNN, and anything past `limit` characters
 * cut, saying how much was left out.
 */
std::string Printable(const std::string& text, std::size_t limit = 200);

/**
 * A mistake in what the user gave: a scene field, an option or its value.
 * Where() is the field path or option name, what() the problem; both
 * Printable().
 */
class InputError : public std::runtime_error
{
public:
  InputError(std::string where, const std::string& problem);
  const std::string& Where() const { return this->Location; }

  /// The file the field belongs to; empty for command-line options.
  const std::string& File() const { return this->FileName; }
  InputError InFile(const std::string& file) const;

private:
  std::string Location;
  std::string FileName;
};

/// `parent.key`, or `key` at the top level.
std::string FieldPath(const std::string& parent, const std::string& key);
/// `parent[index]`.
std::string IndexPath(const std::string& parent, std::size_t index);

/**
 * Throws unless `value` is a JSON object whose keys are all in `known`.
 */
void CheckObject(
  const Json& value, const std::string& path, std::initializer_list<const char*> known);

/// Throws when `value` is an object without `key`.
void RequireField(const Json& value, const std::string& path, const char* key);

/// The numbers a field accepts.
struct Range
{
  double Minimum;
  double Maximum;
  bool ExclusiveMinimum;

  static Range Any();
  static Range AtLeast(double minimum);
  static Range Positive();
  static Range Between(double minimum, double maximum);

  bool Contains(double number) const;
  /// "must be > 0", "must be in [0, 1]"; empty for Any().
  std::string Describe() const;
};

/// What a technique or source parameter holds.
enum class ValueType
{
  Boolean,
  Integer,
  Number,
  Vector3,
  Size2, ///< a number, or an array of 2 numbers
  Size3  ///< a number, or an array of 3 numbers
};

/// How the techniques listing and error messages spell a type.
const char* TypeName(ValueType type);

/**
 * Throws unless `value` has `type` and each of its numbers lies in `range`.
 */
void CheckValue(const Json& value, ValueType type, const Range& range, const std::string& path);

/// A checked Size2, Size3 or Vector3 value as `count` numbers.
std::vector<double> Components(const Json& value, std::size_t count);

///@{
/**
 * Read a value, throwing when it has another type or lies outside `range`.
 */
double ReadNumber(const Json& value, const std::string& path, const Range& range = Range::Any());
int ReadInteger(const Json& value, const std::string& path, const Range& range = Range::Any());
bool ReadBoolean(const Json& value, const std::string& path);
std::string ReadString(const Json& value, const std::string& path);
Vector3 ReadVector3(const Json& value, const std::string& path);
Vector3 ReadColor(const Json& value, const std::string& path);
///@}

/**
 * "(known: a, b, c)", the names of `items` (`name` gives an item's name) for
 * a message about a name that is none of them.
 */
template <typename Items, typename Name>
std::string KnownNames(const Items& items, Name name)
{
  std::string list;
  for (const auto& item : items)
  {
    list += (list.empty() ? "" : ", ") + std::string(name(item));
  }
  return "(known: " + (list.empty() ? std::string("none") : list) + ")";
}

/**
 * Throws unless `value` is an object whose every field names an entry of
 * `table` (anything with Key, Type and Allowed members) and holds a valid
 * value for it.
 */
template <typename Parameter>
void CheckParameters(
  const std::vector<Parameter>& table, const Json& value, const std::string& path)
{
  if (!value.is_object())
  {
    throw InputError(path, "expected an object");
  }
  for (const auto& item : value.items())
  {
    const auto match = std::find_if(table.begin(), table.end(),
      [&](const Parameter& parameter) { return parameter.Key == item.key(); });
    if (match == table.end())
    {
      throw InputError(FieldPath(path, item.key()),
        "unknown parameter " +
          KnownNames(table, [](const Parameter& parameter) { return parameter.Key; }));
    }
    CheckValue(item.value(), match->Type, match->Allowed, FieldPath(path, item.key()));
  }
}

/// `number` as messages print it: 6 significant digits, "inf" for infinity.
std::string FormatNumber(double number);
}

#endif
