// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowTechniqueCatalog.h"
#include "vtkShadowTechniqueCatalogInternals.h"

#include "vtkObjectFactory.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowPass.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkShadowTechniqueCatalog);

namespace
{
using namespace vtkShadowCatalog;

/// The parameters every technique has: vtkSoftShadowPass's own.
std::vector<Parameter> SharedParameters()
{
  std::vector<Parameter> shared = {
    BindClamped<vtkSoftShadowPass, int>("map_size", Integer,
      "shadow maps' size in texels (each cube face's for point lights)",
      VTK_SHADOW_CLAMPED(vtkSoftShadowPass, MapSize)),
    Bind<vtkSoftShadowPass, double>("slope_scaled_bias", Number, Any(),
      "depth offset per unit of depth slope while drawing shadow maps (glPolygonOffset factor)",
      &vtkSoftShadowPass::SetSlopeScaledBias, &vtkSoftShadowPass::GetSlopeScaledBias),
    Bind<vtkSoftShadowPass, double>("constant_bias", Number, Any(),
      "constant depth offset while drawing shadow maps (glPolygonOffset units)",
      &vtkSoftShadowPass::SetConstantBias, &vtkSoftShadowPass::GetConstantBias),
    BindClamped<vtkSoftShadowPass, double>("normal_bias", Number,
      "how far in front of its surface a receiver point is looked up, along the light's ray, in "
      "shadow-map texels",
      VTK_SHADOW_CLAMPED(vtkSoftShadowPass, NormalBias)),
    BindClamped<vtkSoftShadowPass, double>("distance_bias", Number,
      "point lights: factor on squared distances before comparing with the cube map",
      VTK_SHADOW_CLAMPED(vtkSoftShadowPass, DistanceBias)),
    Bind<vtkSoftShadowPass, bool>("packed_cube_maps", Boolean, Any(),
      "point lights: RGBA8 cube maps packing squared distances, not float ones",
      &vtkSoftShadowPass::SetPackedCubeMaps, &vtkSoftShadowPass::GetPackedCubeMaps),
    Bind<vtkSoftShadowPass, bool>("depth_pre_pass", Boolean, Any(),
      "draw opaque depth first so that shading and shadow lookups run on visible fragments only",
      &vtkSoftShadowPass::SetDepthPrePass, &vtkSoftShadowPass::GetDepthPrePass),
  };
  for (Parameter& parameter : shared)
  {
    parameter.Shared = true;
  }
  return shared;
}

/// The table: each technique's entry with the shared parameters after its
/// own, and every clamped parameter's bounds read from a pass of it.
const std::vector<Technique>& Techniques()
{
  static const std::vector<Technique> techniques = []
  {
    std::vector<Technique> made = { Hard(), Reference(), Contact(), Omni(), Silhouette(),
      Smoothies(), AliasFree() };
    for (Technique& technique : made)
    {
      for (const Parameter& shared : SharedParameters())
      {
        technique.Parameters.push_back(shared);
      }
      vtkSmartPointer<vtkSoftShadowPass> pass =
        technique.Create(technique.Variants.empty() ? "" : technique.Variants[0].Name);
      for (Parameter& parameter : technique.Parameters)
      {
        if (parameter.Clamp)
        {
          parameter.Allowed = parameter.Clamp(pass);
        }
      }
    }
    return made;
  }();
  return techniques;
}

const Technique* At(int technique)
{
  const auto& all = Techniques();
  return technique >= 0 && technique < static_cast<int>(all.size()) ? &all[technique] : nullptr;
}

const Parameter* ParameterAt(int technique, int parameter)
{
  const Technique* t = At(technique);
  return t && parameter >= 0 && parameter < static_cast<int>(t->Parameters.size())
    ? &t->Parameters[parameter]
    : nullptr;
}

const Variant* VariantAt(int technique, int variant)
{
  const Technique* t = At(technique);
  return t && variant >= 0 && variant < static_cast<int>(t->Variants.size()) ? &t->Variants[variant]
                                                                             : nullptr;
}

template <typename Items>
int FindNamed(const Items& items, const char* name, const char* Items::value_type::*field)
{
  for (std::size_t i = 0; name && i < items.size(); ++i)
  {
    if (std::strcmp(items[i].*field, name) == 0)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetNumberOfTechniques()
{
  return static_cast<int>(Techniques().size());
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::FindTechnique(const char* name)
{
  return FindNamed(Techniques(), name, &Technique::Name);
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetTechniqueName(int technique)
{
  const Technique* t = At(technique);
  return t ? t->Name : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetTechniqueSummary(int technique)
{
  const Technique* t = At(technique);
  return t ? t->Summary : nullptr;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetNumberOfVariants(int technique)
{
  const Technique* t = At(technique);
  return t ? static_cast<int>(t->Variants.size()) : 0;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::FindVariant(int technique, const char* name)
{
  const Technique* t = At(technique);
  return t ? FindNamed(t->Variants, name, &Variant::Name) : -1;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetVariantName(int technique, int variant)
{
  const Variant* v = VariantAt(technique, variant);
  return v ? v->Name : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetVariantMeaning(int technique, int variant)
{
  const Variant* v = VariantAt(technique, variant);
  return v ? v->Meaning : nullptr;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetNumberOfParameters(int technique)
{
  const Technique* t = At(technique);
  return t ? static_cast<int>(t->Parameters.size()) : 0;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::FindParameter(int technique, const char* key)
{
  const Technique* t = At(technique);
  return t ? FindNamed(t->Parameters, key, &Parameter::Key) : -1;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetParameterKey(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Key : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkShadowTechniqueCatalog::GetParameterMeaning(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Meaning : nullptr;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetParameterType(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Type : -1;
}

//------------------------------------------------------------------------------
int vtkShadowTechniqueCatalog::GetParameterSize(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? (p->Type == Vector3 ? 3 : 1) : 0;
}

//------------------------------------------------------------------------------
double vtkShadowTechniqueCatalog::GetParameterMinimum(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Allowed.Minimum : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
double vtkShadowTechniqueCatalog::GetParameterMaximum(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p ? p->Allowed.Maximum : std::numeric_limits<double>::quiet_NaN();
}

//------------------------------------------------------------------------------
bool vtkShadowTechniqueCatalog::IsParameterShared(int technique, int parameter)
{
  const Parameter* p = ParameterAt(technique, parameter);
  return p && p->Shared;
}

//------------------------------------------------------------------------------
bool vtkShadowTechniqueCatalog::ParseSpec(const char* spec, int ids[2])
{
  const std::string text = spec ? spec : "";
  const std::size_t colon = text.find(':');
  ids[0] = FindTechnique(text.substr(0, colon).c_str());
  ids[1] = colon == std::string::npos ? -1 : FindVariant(ids[0], text.substr(colon + 1).c_str());
  return ids[0] >= 0 && (colon == std::string::npos || ids[1] >= 0);
}

//------------------------------------------------------------------------------
std::string vtkShadowTechniqueCatalog::GetSpecProblem(const char* spec)
{
  int ids[2];
  if (ParseSpec(spec, ids))
  {
    return {};
  }
  const std::string text = spec ? spec : "";
  const std::size_t colon = text.find(':');
  auto known = [](int count, const std::function<const char*(int)>& name)
  {
    std::string list;
    for (int i = 0; i < count; ++i)
    {
      list += (i ? ", " : "") + std::string(name(i));
    }
    return "(known: " + list + ")";
  };
  if (ids[0] < 0)
  {
    return "unknown technique '" + text.substr(0, colon) + "' " +
      known(GetNumberOfTechniques(), GetTechniqueName);
  }
  const std::string variant = text.substr(colon + 1);
  const int technique = ids[0];
  if (GetNumberOfVariants(technique) == 0)
  {
    return "unknown variant '" + variant + "': technique '" + GetTechniqueName(technique) +
      "' has none";
  }
  return "unknown variant '" + variant + "' of technique '" + GetTechniqueName(technique) + "' " +
    known(
      GetNumberOfVariants(technique), [technique](int v) { return GetVariantName(technique, v); });
}

//------------------------------------------------------------------------------
vtkSoftShadowPass* vtkShadowTechniqueCatalog::NewPass(const char* spec)
{
  int ids[2];
  if (!ParseSpec(spec, ids))
  {
    vtkOutputWindowDisplayErrorText(("vtkShadowTechniqueCatalog: " + GetSpecProblem(spec)).c_str());
    return nullptr;
  }
  return NewPass(ids[0], ids[1]);
}

//------------------------------------------------------------------------------
vtkSoftShadowPass* vtkShadowTechniqueCatalog::NewPass(int technique, int variant)
{
  const Technique* t = At(technique);
  const int variants = GetNumberOfVariants(technique);
  if (!t || variant < -1 || variant >= std::max(variants, 1))
  {
    std::ostringstream problem;
    problem << "vtkShadowTechniqueCatalog: no technique " << technique << " with variant "
            << variant << " (there are " << GetNumberOfTechniques() << " techniques)";
    vtkOutputWindowDisplayErrorText(problem.str().c_str());
    return nullptr;
  }
  const std::string name = variants ? t->Variants[std::max(variant, 0)].Name : "";
  vtkSmartPointer<vtkSoftShadowPass> pass = t->Create(name);
  pass->Register(nullptr);
  return pass;
}

//------------------------------------------------------------------------------
bool vtkShadowTechniqueCatalog::SetParameter(
  vtkSoftShadowPass* pass, int technique, int parameter, const double values[3])
{
  const Parameter* p = ParameterAt(technique, parameter);
  if (!pass)
  {
    vtkOutputWindowDisplayErrorText("vtkShadowTechniqueCatalog: SetParameter() without a pass");
    return false;
  }
  if (!p || !p->Accepts(pass))
  {
    vtkErrorWithObjectMacro(
      pass, << "no parameter " << parameter << " of technique " << technique << " for this pass");
    return false;
  }
  if (!IsAllowed(technique, parameter, values))
  {
    std::ostringstream shown;
    for (int i = 0; i < GetParameterSize(technique, parameter); ++i)
    {
      shown << (i ? " " : "") << values[i];
    }
    vtkErrorWithObjectMacro(pass, << Techniques()[technique].Name << "." << p->Key << ": "
                                  << shown.str() << " is not allowed ("
                                  << (p->Type == Boolean      ? "0 or 1"
                                         : p->Type == Integer ? "a whole number"
                                                              : "a finite number")
                                  << " from " << p->Allowed.Minimum << " to " << p->Allowed.Maximum
                                  << ")");
    return false;
  }
  p->Set(pass, values);
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowTechniqueCatalog::IsAllowed(int technique, int parameter, const double values[3])
{
  const Parameter* p = ParameterAt(technique, parameter);
  if (!p || !values)
  {
    return false;
  }
  for (int i = 0; i < GetParameterSize(technique, parameter); ++i)
  {
    const double v = values[i];
    if (!std::isfinite(v) || v < p->Allowed.Minimum || v > p->Allowed.Maximum ||
      (p->Type != Number && p->Type != Vector3 && v != std::floor(v)))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowTechniqueCatalog::GetParameter(
  vtkSoftShadowPass* pass, int technique, int parameter, double values[3])
{
  const Parameter* p = ParameterAt(technique, parameter);
  if (!p || !pass || !p->Accepts(pass))
  {
    return false;
  }
  p->Get(pass, values);
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowTechniqueCatalog::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  for (int t = 0; t < GetNumberOfTechniques(); ++t)
  {
    os << indent << GetTechniqueName(t) << ":";
    for (int v = 0; v < GetNumberOfVariants(t); ++v)
    {
      os << (v ? ", " : " variants ") << GetVariantName(t, v);
    }
    os << "\n";
    vtkSmartPointer<vtkSoftShadowPass> pass = vtk::TakeSmartPointer(NewPass(t, 0));
    for (int p = 0; p < GetNumberOfParameters(t); ++p)
    {
      double values[3] = { 0, 0, 0 };
      GetParameter(pass, t, p, values);
      os << indent.GetNextIndent() << GetParameterKey(t, p) << ": " << values[0];
      if (GetParameterSize(t, p) == 3)
      {
        os << " " << values[1] << " " << values[2];
      }
      os << "\n";
    }
  }
}
