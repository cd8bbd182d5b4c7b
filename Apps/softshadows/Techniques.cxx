// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "Techniques.h"

#include "vtkShadowTechniqueCatalog.h"
#include "vtkSoftShadowPass.h"

#include <vtkCameraPass.h>
#include <vtkNew.h>
#include <vtkRenderPassCollection.h>
#include <vtkSequencePass.h>
#include <vtkShadowMapBakerPass.h>
#include <vtkShadowMapPass.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace softshadows
{
namespace
{
using Catalog = vtkShadowTechniqueCatalog;

ValueType TypeOf(int type)
{
  switch (type)
  {
    case Catalog::Boolean:
      return ValueType::Boolean;
    case Catalog::Integer:
      return ValueType::Integer;
    case Catalog::Vector3:
      return ValueType::Vector3;
    default:
      return ValueType::Number;
  }
}

Range RangeOf(int technique, int parameter)
{
  const double minimum = Catalog::GetParameterMinimum(technique, parameter);
  const double maximum = Catalog::GetParameterMaximum(technique, parameter);
  if (Catalog::GetParameterType(technique, parameter) == Catalog::Boolean ||
    (std::isinf(minimum) && std::isinf(maximum)))
  {
    return Range::Any();
  }
  return std::isinf(maximum) ? Range::AtLeast(minimum) : Range::Between(minimum, maximum);
}

// A catalog parameter, its values converted from and to JSON.
TechniqueParameter ParameterOf(int technique, int parameter)
{
  const ValueType type = TypeOf(Catalog::GetParameterType(technique, parameter));
  return { Catalog::GetParameterKey(technique, parameter), type, RangeOf(technique, parameter),
    Catalog::GetParameterMeaning(technique, parameter),
    [=](TechniqueInstance& instance, const Json& value)
    {
      double values[3] = { 0, 0, 0 };
      if (type == ValueType::Vector3)
      {
        const std::vector<double> numbers = Components(value, 3);
        std::copy(numbers.begin(), numbers.end(), values);
      }
      else
      {
        values[0] = type == ValueType::Boolean ? value.get<bool>() : value.get<double>();
      }
      Catalog::SetParameter(instance.Shadows, technique, parameter, values);
    },
    [=](TechniqueInstance& instance)
    {
      double values[3] = { 0, 0, 0 };
      Catalog::GetParameter(instance.Shadows, technique, parameter, values);
      switch (type)
      {
        case ValueType::Boolean:
          return Json(values[0] != 0);
        case ValueType::Integer:
          return Json(static_cast<long long>(values[0]));
        case ValueType::Vector3:
          return Json::array({ values[0], values[1], values[2] });
        default:
          return Json(values[0]);
      }
    } };
}

// A technique of the module's catalog.
Technique TechniqueOf(int technique)
{
  Technique made;
  made.Name = Catalog::GetTechniqueName(technique);
  made.Summary = Catalog::GetTechniqueSummary(technique);
  for (int v = 0; v < Catalog::GetNumberOfVariants(technique); ++v)
  {
    made.Variants.push_back(
      { Catalog::GetVariantName(technique, v), Catalog::GetVariantMeaning(technique, v) });
  }
  for (int p = 0; p < Catalog::GetNumberOfParameters(technique); ++p)
  {
    made.Parameters.push_back(ParameterOf(technique, p));
  }
  made.Create = [technique](const std::string& variant)
  {
    auto pass = vtk::TakeSmartPointer(
      Catalog::NewPass(technique, Catalog::FindVariant(technique, variant.c_str())));
    TechniqueInstance instance;
    instance.Pass = pass;
    instance.Shadows = pass;
    return instance;
  };
  return made;
}

// VTK 9.1's own shadows, put together as its TestShadowMapPass does: the baker
// draws the maps, then vtkShadowMapPass draws the opaque geometry with them.
TechniqueInstance MakeVtkShadowMapPass()
{
  vtkNew<vtkShadowMapPass> shadows;
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(shadows->GetShadowMapBakerPass());
  passes->AddItem(shadows);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  auto camera = vtkSmartPointer<vtkCameraPass>::New();
  camera->SetDelegatePass(sequence);

  TechniqueInstance instance;
  instance.Pass = camera;
  instance.Baker = shadows->GetShadowMapBakerPass();
  return instance;
}

// Prints `text` in lines of at most 100 columns, continuation lines indented
// by `indent`; the first line starts at column `column`.
void PrintWrapped(std::ostream& os, const std::string& text, int indent, int column = 0)
{
  const int width = 100;
  os << std::string(static_cast<std::size_t>(std::max(0, indent - column)), ' ');
  column = std::max(column, indent);
  std::istringstream words(text);
  std::string word;
  bool first = true;
  while (words >> word)
  {
    const int length = static_cast<int>(word.size());
    if (!first && column + 1 + length > width)
    {
      os << "\n" << std::string(static_cast<std::size_t>(indent), ' ');
      column = indent;
      first = true;
    }
    os << (first ? "" : " ") << word;
    column += length + (first ? 0 : 1);
    first = false;
  }
  os << "\n";
}

const Technique* FindTechnique(const std::string& name)
{
  const auto& all = Techniques();
  auto found = std::find_if(
    all.begin(), all.end(), [&](const Technique& technique) { return technique.Name == name; });
  return found == all.end() ? nullptr : &*found;
}

const Technique& RequireTechnique(const std::string& name, const std::string& where)
{
  if (const Technique* technique = FindTechnique(name))
  {
    return *technique;
  }
  throw InputError(where,
    "unknown technique '" + name + "' " +
      KnownNames(Techniques(), [](const Technique& technique) { return technique.Name; }));
}

void RequireVariant(
  const Technique& technique, const std::string& variant, const std::string& where)
{
  if (technique.Name == "vtk")
  {
    throw InputError(where, "unknown variant '" + variant + "': technique 'vtk' has none");
  }
  const std::string spec = technique.Name + ":" + variant;
  int ids[2];
  if (!Catalog::ParseSpec(spec.c_str(), ids))
  {
    throw InputError(where, Catalog::GetSpecProblem(spec.c_str()));
  }
}
}

//------------------------------------------------------------------------------
std::string TechniqueSpec::ToString() const
{
  return this->Variant.empty() ? this->Name : this->Name + ":" + this->Variant;
}

//------------------------------------------------------------------------------
const std::vector<Technique>& Techniques()
{
  static const std::vector<Technique> techniques = []()
  {
    std::vector<Technique> all;
    for (int t = 0; t < Catalog::GetNumberOfTechniques(); ++t)
    {
      all.push_back(TechniqueOf(t));
    }
    all.push_back({ "vtk",
      "VTK 9.1's vtkShadowMapPass and vtkShadowMapBakerPass, the baseline: hard shadows, "
      "opaque geometry only, light radius ignored",
      {}, {}, [](const std::string&) { return MakeVtkShadowMapPass(); } });
    return all;
  }();
  return techniques;
}

//------------------------------------------------------------------------------
TechniqueSpec ParseTechniqueSpec(const std::string& text, const std::string& where)
{
  if (text == "vtk")
  {
    return { "vtk", "" }; // VTK's own pass: the one technique outside the catalog
  }
  int ids[2] = { -1, -1 };
  if (!Catalog::ParseSpec(text.c_str(), ids) && ids[0] >= 0)
  {
    throw InputError(where, Catalog::GetSpecProblem(text.c_str())); // the variant
  }
  if (ids[0] < 0)
  {
    // The catalog's techniques and VTK's own pass.
    std::string known;
    for (int i = 0; i < Catalog::GetNumberOfTechniques(); ++i)
    {
      known += std::string(Catalog::GetTechniqueName(i)) + ", ";
    }
    throw InputError(where,
      "unknown technique '" + text.substr(0, text.find(':')) + "' (known: " + known + "vtk)");
  }
  return { Catalog::GetTechniqueName(ids[0]),
    ids[1] < 0 ? std::string() : Catalog::GetVariantName(ids[0], ids[1]) };
}

//------------------------------------------------------------------------------
void CheckTechniqueParameters(
  const std::string& name, const Json& parameters, const std::string& path)
{
  const Technique& technique = RequireTechnique(name, path);
  if (!parameters.is_object())
  {
    throw InputError(path, "expected an object");
  }
  Json own = parameters;
  if (own.contains("variant"))
  {
    const std::string variantPath = FieldPath(path, "variant");
    RequireVariant(technique, ReadString(own["variant"], variantPath), variantPath);
    own.erase("variant");
  }
  CheckParameters(technique.Parameters, own, path);
}

//------------------------------------------------------------------------------
TechniqueInstance CreateTechnique(const TechniqueSpec& spec, int mapSize, const Json& parameters)
{
  const std::string where = "technique"; // a temporary would warn, as in SceneFile.cxx
  const Technique& technique = RequireTechnique(spec.Name, where);
  std::string variant = spec.Variant;
  if (variant.empty() && parameters.contains("variant"))
  {
    variant = parameters["variant"].get<std::string>();
  }
  if (variant.empty() && !technique.Variants.empty())
  {
    variant = technique.Variants.front().Name;
  }

  TechniqueInstance instance = technique.Create(variant);
  instance.Spec = spec.ToString();
  instance.Name = spec.Name;
  if (instance.Shadows)
  {
    instance.Shadows->SetMapSize(mapSize);
  }
  if (instance.Baker)
  {
    instance.Baker->SetResolution(static_cast<unsigned int>(mapSize));
  }
  for (const TechniqueParameter& parameter : technique.Parameters)
  {
    if (parameters.contains(parameter.Key))
    {
      parameter.Apply(instance, parameters[parameter.Key]);
    }
  }
  return instance;
}

//------------------------------------------------------------------------------
bool SetTechniqueParameter(TechniqueInstance& instance, const std::string& key, const Json& value)
{
  const Technique& technique = RequireTechnique(instance.Name, "technique");
  for (const TechniqueParameter& parameter : technique.Parameters)
  {
    if (parameter.Key == key)
    {
      CheckValue(value, parameter.Type, parameter.Allowed, instance.Name + "." + key);
      parameter.Apply(instance, value);
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void PrintTechniques(std::ostream& os)
{
  os << "Techniques, as --technique SPEC with SPEC = name[:variant]. Parameters go in the\n"
        "scene's \"shadows\" object under the technique's name, e.g.\n"
        "  \"shadows\": {\"technique\": \"hard\", \"map_size\": 2048, "
        "\"hard\": {\"pcf_radius\": 2}}\n"
        "and \"shadows.map_size\" (default 1024) sets every technique's shadow map size\n"
        "(a technique's own map_size overrides it).\n";
  // Columns as wide as their widest entry over every technique.
  std::vector<std::vector<std::string>> defaults;
  std::size_t keyWidth = 10;
  std::size_t defaultWidth = 8;
  for (const Technique& technique : Techniques())
  {
    TechniqueInstance fresh = technique.Create(
      technique.Variants.empty() ? std::string() : technique.Variants.front().Name);
    defaults.emplace_back();
    for (const TechniqueParameter& parameter : technique.Parameters)
    {
      defaults.back().push_back(parameter.Current(fresh).dump());
      keyWidth = std::max(keyWidth, parameter.Key.size() + 1);
      defaultWidth = std::max(defaultWidth, defaults.back().back().size() + 1);
    }
  }
  const int meaningColumn = static_cast<int>(2 + keyWidth + 10 + defaultWidth);
  for (std::size_t t = 0; t < Techniques().size(); ++t)
  {
    const Technique& technique = Techniques()[t];
    os << "\n" << technique.Name << "\n";
    PrintWrapped(os, technique.Summary, 2);
    for (std::size_t i = 0; i < technique.Variants.size(); ++i)
    {
      const TechniqueVariant& variant = technique.Variants[i];
      os << "  variant " << std::left << std::setw(12) << variant.Name;
      PrintWrapped(os, variant.Meaning + (i == 0 ? " (default)" : ""), 22, 22);
    }
    if (technique.Parameters.empty())
    {
      os << "  (no parameters)\n";
      continue;
    }
    os << "  " << std::left << std::setw(static_cast<int>(keyWidth)) << "parameter" << std::setw(10)
       << "type" << std::setw(static_cast<int>(defaultWidth)) << "default"
       << "meaning\n";
    for (std::size_t p = 0; p < technique.Parameters.size(); ++p)
    {
      const TechniqueParameter& parameter = technique.Parameters[p];
      const std::string range = parameter.Allowed.Describe();
      os << "  " << std::left << std::setw(static_cast<int>(keyWidth)) << parameter.Key
         << std::setw(10) << TypeName(parameter.Type) << std::setw(static_cast<int>(defaultWidth))
         << defaults[t][p];
      PrintWrapped(
        os, parameter.Meaning + (range.empty() ? "" : "; " + range), meaningColumn, meaningColumn);
    }
  }
}

//------------------------------------------------------------------------------
std::vector<std::string> AllTechniqueSpecs()
{
  std::vector<std::string> specs;
  for (const Technique& technique : Techniques())
  {
    specs.push_back(technique.Name);
    for (std::size_t i = 1; i < technique.Variants.size(); ++i)
    {
      specs.push_back(technique.Name + ":" + technique.Variants[i].Name);
    }
  }
  return specs;
}
}
