// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVShadowRenderView.h"

#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkShadowTechniqueCatalog.h"
#include "vtkSoftShadowPass.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVShadowRenderView);

//------------------------------------------------------------------------------
vtkPVShadowRenderView::vtkPVShadowRenderView()
{
  this->Technique = vtkShadowTechniqueCatalog::FindTechnique(this->ShadowTechnique.c_str());
  this->MakePass();
}

//------------------------------------------------------------------------------
vtkPVShadowRenderView::~vtkPVShadowRenderView() = default;

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowTechnique(const char* spec)
{
  using Catalog = vtkShadowTechniqueCatalog;
  const std::string text = spec ? spec : "";
  if (text == this->ShadowTechnique)
  {
    return;
  }
  int ids[2];
  if (!Catalog::ParseSpec(text.c_str(), ids))
  {
    vtkErrorMacro(<< "ShadowTechnique: " << Catalog::GetSpecProblem(text.c_str())
                  << "; the view keeps '" << this->ShadowTechnique << "'.");
    return;
  }
  this->ShadowTechnique = text;
  this->Technique = ids[0];
  this->Variant = ids[1];
  this->MakePass();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowParameter(const char* name, double value)
{
  const double values[3] = { value, 0, 0 };
  this->ApplyShadowParameter(name, values, 1);
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowParameter(const char* name, double x, double y, double z)
{
  const double values[3] = { x, y, z };
  this->ApplyShadowParameter(name, values, 3);
}

//------------------------------------------------------------------------------
bool vtkPVShadowRenderView::ApplyShadowParameter(const char* name, const double values[3], int size)
{
  using Catalog = vtkShadowTechniqueCatalog;
  const std::string text = name ? name : "";
  const auto dot = text.find('.');
  const int technique = Catalog::FindTechnique(text.substr(0, dot).c_str());
  const int parameter =
    dot == std::string::npos ? -1 : Catalog::FindParameter(technique, text.substr(dot + 1).c_str());
  if (parameter < 0 || Catalog::GetParameterSize(technique, parameter) != size)
  {
    vtkErrorMacro(<< "'" << text << "' with " << size << (size == 1 ? " value" : " values")
                  << " is no technique.parameter of `softshadows techniques`.");
    return false;
  }
  if (!Catalog::IsAllowed(technique, parameter, values))
  {
    vtkErrorMacro(<< text << ": " << values[0] << (size == 3 ? " ..." : "")
                  << " is not allowed (from " << Catalog::GetParameterMinimum(technique, parameter)
                  << " to " << Catalog::GetParameterMaximum(technique, parameter)
                  << (Catalog::GetParameterType(technique, parameter) == Catalog::Number ||
                           Catalog::GetParameterType(technique, parameter) == Catalog::Vector3
                         ? ""
                         : ", whole")
                  << "); it stays as it was.");
    return false;
  }
  std::copy(values, values + 3, this->Parameters[text].begin());
  if (technique == this->Technique)
  {
    double before[3] = { 0, 0, 0 };
    Catalog::GetParameter(this->Pass, technique, parameter, before);
    Catalog::SetParameter(this->Pass, technique, parameter, values);
    if (!std::equal(values, values + size, before))
    {
      this->Modified();
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowMapSize(int size)
{
  if (size != this->ShadowMapSize)
  {
    this->ShadowMapSize = size;
    this->Pass->SetMapSize(size);
    this->ShadowMapSize = this->Pass->GetMapSize(); // clamped as the pass clamps it
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetLightRadius(vtkLight* light, double radius)
{
  if (light && radius != vtkSoftShadowPass::GetRadius(light))
  {
    vtkSoftShadowPass::SetRadius(radius, light);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::AboutToRenderOnLocalProcess(bool interactive)
{
  this->Superclass::AboutToRenderOnLocalProcess(interactive);
  // Each rank draws its own piece only when the synchronized renderers
  // composite and the data is not the same everywhere (tile displays, CAVEs).
  vtkPVSynchronizedRenderer* sync = this->SynchronizedRenderers;
  const bool pieces = sync->GetEnabled() && !sync->GetDataReplicatedOnAllProcesses();
  this->Pass->SetController(
    this->CombineShadowMaps && pieces ? vtkMultiProcessController::GetGlobalController() : nullptr);
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::MakePass()
{
  using Catalog = vtkShadowTechniqueCatalog;
  this->Pass = vtk::TakeSmartPointer(Catalog::NewPass(this->Technique, this->Variant));
  this->Pass->SetMapSize(this->ShadowMapSize);
  const std::string prefix = std::string(Catalog::GetTechniqueName(this->Technique)) + ".";
  for (const auto& kept : this->Parameters)
  {
    if (kept.first.compare(0, prefix.size(), prefix) == 0)
    {
      Catalog::SetParameter(this->Pass, this->Technique,
        Catalog::FindParameter(this->Technique, kept.first.substr(prefix.size()).c_str()),
        kept.second.data());
    }
  }
  // The previous pass, and its textures, go when the renderers drop it.
  this->SynchronizedRenderers->SetRenderPass(this->Pass);
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowTechnique: " << this->ShadowTechnique << " (technique " << this->Technique
     << ", variant " << this->Variant << ")\n";
  os << indent << "ShadowMapSize: " << this->ShadowMapSize << "\n";
  os << indent << "CombineShadowMaps: " << this->CombineShadowMaps << "\n";
  os << indent << "Pass: " << this->Pass->GetClassName() << "\n";
  for (const auto& kept : this->Parameters)
  {
    os << indent << kept.first << ": " << kept.second[0] << " " << kept.second[1] << " "
       << kept.second[2] << "\n";
  }
}
