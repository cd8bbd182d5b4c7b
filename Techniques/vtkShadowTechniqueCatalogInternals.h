// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * The catalog's table entries, for the files that describe one technique
 * each (catalog/<technique>.cxx) and for vtkShadowTechniqueCatalog, which
 * reads them. Not installed.
 *
 * A technique's entry names it, its variants and its own parameters, each
 * bound to the pass's Set/Get methods; bounds come from the class's clamp
 * (BindClamped()) wherever it has one. The parameters every technique shares
 * (vtkSoftShadowPass's) are added by the catalog.
 */

#ifndef vtkShadowTechniqueCatalogInternals_h
#define vtkShadowTechniqueCatalogInternals_h

#include "vtkShadowTechniqueCatalog.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowPass.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace vtkShadowCatalog
{
struct Bounds
{
  double Minimum = -std::numeric_limits<double>::infinity();
  double Maximum = std::numeric_limits<double>::infinity();
};

inline Bounds Any()
{
  return {};
}

inline Bounds Between(double minimum, double maximum)
{
  return { minimum, maximum };
}

inline Bounds AtLeast(double minimum)
{
  return { minimum, std::numeric_limits<double>::infinity() };
}

struct Parameter
{
  const char* Key;
  int Type;
  Bounds Allowed;
  const char* Meaning;
  /// Whether a pass has this parameter (is of the class that declares it).
  std::function<bool(vtkSoftShadowPass*)> Accepts;
  std::function<void(vtkSoftShadowPass*, const double*)> Set;
  std::function<void(vtkSoftShadowPass*, double*)> Get;
  /// The class's own clamp (vtkSetClampMacro's Get<Name>MinValue() and
  /// MaxValue()), read into Allowed when the table is made; unset when the
  /// entry gives Allowed.
  std::function<Bounds(vtkSoftShadowPass*)> Clamp;
  /// Every technique has it: one of vtkSoftShadowPass's own.
  bool Shared = false;
};

struct Variant
{
  const char* Name;
  const char* Meaning;
};

struct Technique
{
  const char* Name;
  const char* Summary;
  std::vector<Variant> Variants; ///< the first is the default; may be empty
  std::vector<Parameter> Parameters;
  std::function<vtkSmartPointer<vtkSoftShadowPass>(const std::string& variant)> Create;
};

constexpr int Boolean = vtkShadowTechniqueCatalog::Boolean;
constexpr int Integer = vtkShadowTechniqueCatalog::Integer;
constexpr int Number = vtkShadowTechniqueCatalog::Number;
constexpr int Vector3 = vtkShadowTechniqueCatalog::Vector3;

template <typename PassType>
bool IsPass(vtkSoftShadowPass* pass)
{
  return PassType::SafeDownCast(pass) != nullptr;
}

/// A parameter that reaches the pass through its Set/Get methods.
template <typename PassType, typename Value>
Parameter Bind(const char* key, int type, Bounds allowed, const char* meaning,
  void (PassType::*set)(Value), Value (PassType::*get)())
{
  return { key, type, type == Boolean ? Between(0, 1) : allowed, meaning, IsPass<PassType>,
    [set](vtkSoftShadowPass* pass, const double* v)
    { (PassType::SafeDownCast(pass)->*set)(static_cast<Value>(v[0])); },
    [get](vtkSoftShadowPass* pass, double* v)
    { v[0] = static_cast<double>((PassType::SafeDownCast(pass)->*get)()); },
    nullptr };
}

/// A parameter whose class clamps it (vtkSetClampMacro): its bounds are the
/// class's own. Getters by type: const or not, as each VTK release has them.
template <typename PassType, typename Value, typename MinGetter, typename MaxGetter>
Parameter BindClamped(const char* key, int type, const char* meaning, void (PassType::*set)(Value),
  Value (PassType::*get)(), MinGetter minimum, MaxGetter maximum)
{
  Parameter parameter = Bind<PassType, Value>(key, type, Any(), meaning, set, get);
  parameter.Clamp = [minimum, maximum](vtkSoftShadowPass* pass)
  {
    PassType* typed = PassType::SafeDownCast(pass);
    return Bounds{ static_cast<double>((typed->*minimum)()),
      static_cast<double>((typed->*maximum)()) };
  };
  return parameter;
}

/// The setter, getter and clamp of property Name of Class, for BindClamped().
#define VTK_SHADOW_CLAMPED(Class, Name)                                                            \
  &Class::Set##Name, &Class::Get##Name, &Class::Get##Name##MinValue, &Class::Get##Name##MaxValue

template <typename PassType>
Parameter BindVector3(const char* key, Bounds allowed, const char* meaning,
  void (PassType::*set)(double, double, double), double* (PassType::*get)())
{
  return { key, Vector3, allowed, meaning, IsPass<PassType>,
    [set](vtkSoftShadowPass* pass, const double* v)
    { (PassType::SafeDownCast(pass)->*set)(v[0], v[1], v[2]); },
    [get](vtkSoftShadowPass* pass, double* v)
    {
      const double* value = (PassType::SafeDownCast(pass)->*get)();
      std::copy(value, value + 3, v);
    },
    nullptr };
}

///@{
/// Each technique's entry, in its own file (catalog/<name>.cxx).
Technique Hard();
Technique Reference();
Technique Contact();
Technique Omni();
Technique Silhouette();
Technique Smoothies();
Technique AliasFree();
///@}
}

#endif
