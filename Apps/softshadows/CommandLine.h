// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * The command line of `softshadows`: options of a subcommand and the values
 * they take. Mistakes throw InputError naming the option.
 */

#ifndef softshadows_CommandLine_h
#define softshadows_CommandLine_h

#include "Techniques.h"

#include <array>
#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace softshadows
{
class CommandLine
{
public:
  /**
   * Parses the arguments after the subcommand: one SCENE.json (when
   * `needsScene`), options from `valued` (`--size WxH` or `--size=WxH`) and
   * flags from `flags`.
   */
  CommandLine(const std::string& command, const std::vector<std::string>& arguments,
    bool needsScene, std::initializer_list<const char*> valued,
    std::initializer_list<const char*> flags);

  const std::string& Scene() const { return this->SceneFile; }
  bool Has(const std::string& option) const;
  /// The option's value; throws InputError when a required option is missing.
  const std::string& Value(const std::string& option) const;

  /// `--size WxH`, or {0, 0} when not given.
  std::array<int, 2> Size() const;
  /// An integer option in [minimum, maximum], or `fallback` when not given.
  int Integer(const std::string& option, int minimum, int maximum, int fallback) const;
  /// A number option in [minimum, maximum], or `fallback` when not given.
  double Number(const std::string& option, double minimum, double maximum, double fallback) const;
  /// `X,Y,Z`, three finite numbers, or `fallback` when not given.
  std::array<double, 3> Vector(
    const std::string& option, const std::array<double, 3>& fallback) const;
  /**
   * A comma-separated list of technique specs, each parsed, none twice.
   */
  std::vector<TechniqueSpec> TechniqueList(const std::string& option) const;

private:
  std::string Command;
  std::string SceneFile;
  std::map<std::string, std::string> Values;
  std::set<std::string> Flags;
};
}

#endif
