#include "vtkPVShadowRenderView.h"

#include "vtkAliasFreeShadowPass.h"
#include "vtkContactHardeningShadowPass.h"
#include "vtkHardShadowPass.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOmnidirectionalShadowPass.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkReferenceShadowPass.h"
#include "vtkSilhouetteShadowPass.h"
#include "vtkSmoothieShadowPass.h"

vtkStandardNewMacro(vtkPVShadowRenderView);

//------------------------------------------------------------------------------
vtkPVShadowRenderView::vtkPVShadowRenderView()
{
  this->MakePass();
}

//------------------------------------------------------------------------------
vtkPVShadowRenderView::~vtkPVShadowRenderView() = default;

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::SetShadowTechnique(int technique)
{
  if (technique < 0 || technique >= NumberOfShadowTechniques)
  {
    vtkErrorMacro(<< "ShadowTechnique " << technique << " is not one of 0 to "
                  << NumberOfShadowTechniques - 1 << "; the view keeps " << this->ShadowTechnique
                  << ".");
    return;
  }
  if (technique != this->ShadowTechnique)
  {
    this->ShadowTechnique = technique;
    this->MakePass();
    this->Modified();
  }
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
  const int t = this->ShadowTechnique;
  if (t == Hard)
  {
    this->Pass = vtkSmartPointer<vtkHardShadowPass>::New();
  }
  else if (t == Reference)
  {
    this->Pass = vtkSmartPointer<vtkReferenceShadowPass>::New();
  }
  else if (t == Contact || t == ContactGaussian || t == ContactMultiPass)
  {
    auto contact = vtkSmartPointer<vtkContactHardeningShadowPass>::New();
    contact->SetVariant(t == Contact ? vtkContactHardeningShadowPass::PCF
        : t == ContactGaussian       ? vtkContactHardeningShadowPass::Gaussian
                                     : vtkContactHardeningShadowPass::MultiPass);
    this->Pass = contact;
  }
  else if (t == Omni || t == OmniPCF4)
  {
    auto omni = vtkSmartPointer<vtkOmnidirectionalShadowPass>::New();
    omni->SetFilter(
      t == Omni ? vtkOmnidirectionalShadowPass::Poisson : vtkOmnidirectionalShadowPass::PCF4);
    this->Pass = omni;
  }
  else if (t == Silhouette || t == SilhouetteHard)
  {
    auto silhouette = vtkSmartPointer<vtkSilhouetteShadowPass>::New();
    silhouette->SetVariant(
      t == Silhouette ? vtkSilhouetteShadowPass::Soft : vtkSilhouetteShadowPass::Hard);
    this->Pass = silhouette;
  }
  else if (t == Smoothies)
  {
    this->Pass = vtkSmartPointer<vtkSmoothieShadowPass>::New();
  }
  else
  {
    auto aliasFree = vtkSmartPointer<vtkAliasFreeShadowPass>::New();
    aliasFree->SetVariant(
      t == AliasFree ? vtkAliasFreeShadowPass::Soft : vtkAliasFreeShadowPass::Hard);
    this->Pass = aliasFree;
  }
  this->Pass->SetMapSize(this->ShadowMapSize);
  // The previous pass, and its textures, go when the renderers drop it.
  this->SynchronizedRenderers->SetRenderPass(this->Pass);
}

//------------------------------------------------------------------------------
void vtkPVShadowRenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowTechnique: " << this->ShadowTechnique << "\n";
  os << indent << "ShadowMapSize: " << this->ShadowMapSize << "\n";
  os << indent << "CombineShadowMaps: " << this->CombineShadowMaps << "\n";
  os << indent << "Pass: " << this->Pass->GetClassName() << "\n";
}
