// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * The shadow techniques the program knows: their names, variants and
 * parameters, and how to make their passes.
 *
 * A technique is one entry of Techniques(); a technique SPEC on the command
 * line or in a scene is `name[:variant]` and is parsed only by
 * ParseTechniqueSpec(). Parameters come from the scene's `shadows` object,
 * keyed by technique name, in snake_case; the defaults shown by the listing
 * are read from freshly made passes, so they are the classes' own defaults.
 */

#ifndef softshadows_Techniques_h
#define softshadows_Techniques_h

#include "JsonValues.h"

#include <vtkRenderPass.h> // for vtkSmartPointer<vtkRenderPass>
#include <vtkSmartPointer.h>

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

class vtkShadowMapBakerPass;
class vtkSoftShadowPass;

namespace softshadows
{
/// `name[:variant]`; an empty Variant leaves the choice to the scene or default.
struct TechniqueSpec
{
  std::string Name;
  std::string Variant;

  /// As written: `name` or `name:variant`.
  std::string ToString() const;
};

/// One technique's passes, ready for vtkRenderer::SetPass().
struct TechniqueInstance
{
  std::string Spec; ///< as requested, e.g. `contact:multipass`
  std::string Name; ///< the technique's name, e.g. `contact`
  vtkSmartPointer<vtkRenderPass> Pass;
  vtkSoftShadowPass* Shadows = nullptr;   ///< this module's pass; null for `vtk`
  vtkShadowMapBakerPass* Baker = nullptr; ///< VTK's baker; only for `vtk`
};

/// A technique parameter: how the scene spells it and how it reaches the pass.
struct TechniqueParameter
{
  std::string Key;
  ValueType Type;
  Range Allowed;
  std::string Meaning;
  std::function<void(TechniqueInstance&, const Json&)> Apply;
  std::function<Json(TechniqueInstance&)> Current;
};

struct TechniqueVariant
{
  std::string Name;
  std::string Meaning;
};

struct Technique
{
  std::string Name;
  std::string Summary;
  std::vector<TechniqueVariant> Variants; ///< the first is the default; may be empty
  std::vector<TechniqueParameter> Parameters;
  /// Makes the passes with every parameter at its default.
  std::function<TechniqueInstance(const std::string& variant)> Create;
};

const std::vector<Technique>& Techniques();

/**
 * Parses `name[:variant]`. Throws InputError at `where` (a field path or
 * option name) for an unknown technique or variant.
 */
TechniqueSpec ParseTechniqueSpec(const std::string& text, const std::string& where);

/**
 * Checks a technique's object in the scene's `shadows`: throws InputError
 * for an unknown technique name, parameter or variant, or a bad value.
 */
void CheckTechniqueParameters(
  const std::string& name, const Json& parameters, const std::string& path);

/**
 * Makes the passes of `spec` with shadow maps of `mapSize` texels and the
 * scene's `parameters` for its technique (an object, maybe empty). The
 * variant is the spec's, else the parameters' `variant`, else the default.
 */
TechniqueInstance CreateTechnique(const TechniqueSpec& spec, int mapSize, const Json& parameters);

/**
 * Sets the parameter `key` of the instance's technique to `value` (checked
 * as scene files are: throws InputError for a bad value). False when the
 * technique has no such parameter.
 */
bool SetTechniqueParameter(TechniqueInstance& instance, const std::string& key, const Json& value);

/// The `techniques` listing: every technique, variant and parameter.
void PrintTechniques(std::ostream& os);

/// Every spec worth showing: each technique, and each of its other variants.
std::vector<std::string> AllTechniqueSpecs();
}

#endif
