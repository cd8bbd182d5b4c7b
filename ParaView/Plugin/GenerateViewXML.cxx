// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Writes the view's server-manager XML from a template and the module's
// technique catalog, so that the panel offers what the classes offer:
//   GenerateViewXML TEMPLATE OUTPUT
// In TEMPLATE, @SHADOW_TECHNIQUES@ becomes the Shadow Technique choices
// (`name[:variant]`, as `softshadows techniques` lists them) and
// @SHADOW_PARAMETERS@ one property per technique parameter (but map_size,
// the view's ShadowMapSize for every technique), defaults read
// from a fresh pass, and one panel group per technique shown only while it is
// chosen. A parameter's property is named and labelled `<Technique> <Key>`
// (contact.pass_limit: ContactPassLimit, "Contact Pass Limit"; Python names
// come from labels, which must differ) and reaches
// vtkPVShadowRenderView::SetShadowParameter("contact.pass_limit", value).

#include "vtkShadowTechniqueCatalog.h"
#include "vtkSmartPointer.h"
#include "vtkSoftShadowPass.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using Catalog = vtkShadowTechniqueCatalog;

std::string Escape(const std::string& text)
{
  std::string escaped;
  for (char c : text)
  {
    escaped += c == '&' ? "&amp;"
      : c == '<'        ? "&lt;"
      : c == '>'        ? "&gt;"
      : c == '"'        ? "&quot;"
                        : std::string(1, c);
  }
  return escaped;
}

// "pass_limit" -> "Pass Limit"
std::string Title(const std::string& key)
{
  std::string title;
  bool start = true;
  for (char c : key)
  {
    if (c == '_')
    {
      title += ' ';
      start = true;
      continue;
    }
    title += start ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    start = false;
  }
  return title;
}

std::string WithoutSpaces(std::string text)
{
  text.erase(std::remove(text.begin(), text.end(), ' '), text.end());
  return text;
}

std::string Number(double value)
{
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

std::vector<std::string> Specs(int technique)
{
  const std::string name = Catalog::GetTechniqueName(technique);
  std::vector<std::string> specs{ name };
  for (int v = 1; v < Catalog::GetNumberOfVariants(technique); ++v)
  {
    specs.push_back(name + ":" + Catalog::GetVariantName(technique, v));
  }
  return specs;
}

std::string TechniqueChoices()
{
  std::string xml;
  for (int t = 0; t < Catalog::GetNumberOfTechniques(); ++t)
  {
    for (const std::string& spec : Specs(t))
    {
      xml += "          <String value=\"" + spec + "\"/>\n";
    }
  }
  return xml;
}

std::string Property(int t, int p, vtkSoftShadowPass* defaults)
{
  const std::string technique = Catalog::GetTechniqueName(t);
  const std::string key = Catalog::GetParameterKey(t, p);
  const std::string label = Title(technique) + " " + Title(key);
  const int type = Catalog::GetParameterType(t, p);
  const int size = Catalog::GetParameterSize(t, p);
  double values[3] = { 0, 0, 0 };
  Catalog::GetParameter(defaults, t, p, values);
  const double minimum = Catalog::GetParameterMinimum(t, p);
  const double maximum = Catalog::GetParameterMaximum(t, p);

  const char* element = type == Catalog::Number || type == Catalog::Vector3 ? "DoubleVectorProperty"
                                                                            : "IntVectorProperty";
  std::string xml = "      <" + std::string(element) + " name=\"" + WithoutSpaces(label) +
    "\" label=\"" + label + "\"\n        command=\"SetShadowParameter\" initial_string=\"" +
    technique + "." + key + "\" number_of_elements=\"" + std::to_string(size) +
    "\" default_values=\"";
  for (int i = 0; i < size; ++i)
  {
    xml += (i ? " " : "") + Number(values[i]);
  }
  xml += "\"";
  // The parameters every technique shares: advanced in the panel.
  if (Catalog::IsParameterShared(t, p))
  {
    xml += "\n        panel_visibility=\"advanced\"";
  }
  xml += ">\n";
  if (type == Catalog::Boolean)
  {
    xml += "        <BooleanDomain name=\"bool\"/>\n";
  }
  else
  {
    const std::string domain = type == Catalog::Integer ? "IntRangeDomain" : "DoubleRangeDomain";
    xml += "        <" + domain + " name=\"range\"";
    // One bound per element: ParaView's range domains bound each element apart.
    auto bound = [size](double value)
    {
      std::string values;
      for (int i = 0; i < size; ++i)
      {
        values += (i ? " " : "") + Number(value);
      }
      return values;
    };
    if (std::isfinite(minimum))
    {
      xml += " min=\"" + bound(minimum) + "\"";
    }
    if (std::isfinite(maximum))
    {
      xml += " max=\"" + bound(maximum) + "\"";
    }
    xml += "/>\n";
  }
  xml += "        <Documentation>" + Escape(Catalog::GetParameterMeaning(t, p)) +
    " (softshadows: " + technique + "." + key + ")</Documentation>\n";
  xml += "      </" + std::string(element) + ">\n";
  return xml;
}

std::string Parameters()
{
  std::string properties;
  std::string groups;
  for (int t = 0; t < Catalog::GetNumberOfTechniques(); ++t)
  {
    auto defaults = vtk::TakeSmartPointer(Catalog::NewPass(t, 0));
    const std::string technique = Catalog::GetTechniqueName(t);
    std::string specs;
    for (const std::string& spec : Specs(t))
    {
      specs += (specs.empty() ? "" : " ") + spec;
    }
    groups += "      <PropertyGroup label=\"" + Title(technique) + "\">\n";
    for (int p = 0; p < Catalog::GetNumberOfParameters(t); ++p)
    {
      if (std::string(Catalog::GetParameterKey(t, p)) == "map_size")
      {
        continue; // the view's ShadowMapSize, for every technique
      }
      properties += Property(t, p, defaults);
      groups += "        <Property name=\"" +
        WithoutSpaces(Title(technique) + " " + Title(Catalog::GetParameterKey(t, p))) + "\"/>\n";
    }
    groups += "        <Hints>\n          <PropertyWidgetDecorator type=\"GenericDecorator\" "
              "mode=\"visibility\" property=\"ShadowTechnique\" values=\"" +
      specs + "\"/>\n        </Hints>\n      </PropertyGroup>\n";
  }
  return properties + groups;
}

void Replace(std::string& text, const std::string& tag, const std::string& with)
{
  const auto at = text.find(tag);
  if (at == std::string::npos)
  {
    throw std::runtime_error("the template has no " + tag);
  }
  text.replace(at, tag.size(), with);
}
}

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: " << argv[0] << " TEMPLATE OUTPUT\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof())
  {
    std::cerr << argv[0] << ": cannot read " << argv[1] << "\n";
    return 1;
  }
  try
  {
    Replace(xml, "@SHADOW_TECHNIQUES@\n", TechniqueChoices());
    Replace(xml, "@SHADOW_PARAMETERS@\n", Parameters());
  }
  catch (const std::exception& error)
  {
    std::cerr << argv[0] << ": " << argv[1] << ": " << error.what() << "\n";
    return 1;
  }
  std::ofstream out(argv[2]);
  out << xml;
  return out ? 0 : 1;
}
