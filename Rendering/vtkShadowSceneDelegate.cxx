// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowSceneDelegate.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkObjectFactory.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkTranslucentPass.h"
#include "vtkVolumetricPass.h"

namespace
{
// A function as a step of a render pass sequence.
class vtkShadowFunctionStep : public vtkRenderPass
{
public:
  static vtkShadowFunctionStep* New();
  vtkTypeMacro(vtkShadowFunctionStep, vtkRenderPass);
  std::function<void(const vtkRenderState*)> Function;
  void Render(const vtkRenderState* s) override { this->Function(s); }
};
vtkStandardNewMacro(vtkShadowFunctionStep);
}

//------------------------------------------------------------------------------
vtkShadowSceneDelegate::vtkShadowSceneDelegate()
  : DefaultSteps(vtkSmartPointer<vtkRenderStepsPass>::New())
{
  this->OrderIndependent->SetTranslucentPass(this->Translucent);
  this->DepthPeeling->SetTranslucentPass(this->Translucent);
  this->DefaultSteps->SetTranslucentPass(this->OrderIndependent);
}

vtkShadowSceneDelegate::~vtkShadowSceneDelegate() = default;

//------------------------------------------------------------------------------
vtkRenderStepsPass* vtkShadowSceneDelegate::GetDefaultSteps() const
{
  return this->DefaultSteps;
}

//------------------------------------------------------------------------------
int vtkShadowSceneDelegate::Render(const vtkRenderState* s, vtkRenderPass* delegate,
  const std::function<void(const vtkRenderState*)>& beforeOpaque)
{
  if (delegate == this->DefaultSteps)
  {
    this->ChooseTranslucency(s);
  }
  auto* steps = vtkRenderStepsPass::SafeDownCast(delegate);
  vtkSmartPointer<vtkRenderPass> opaque = steps ? steps->GetOpaquePass() : nullptr;
  const bool slotted = beforeOpaque && opaque;
  if (slotted)
  {
    vtkNew<vtkShadowFunctionStep> step;
    step->Function = beforeOpaque;
    vtkNew<vtkRenderPassCollection> passes;
    passes->AddItem(step);
    passes->AddItem(opaque);
    vtkNew<vtkSequencePass> sequence;
    sequence->SetPasses(passes);
    steps->SetOpaquePass(sequence);
  }
  delegate->Render(s);
  if (slotted)
  {
    steps->SetOpaquePass(opaque);
  }
  return delegate->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkShadowSceneDelegate::ChooseTranslucency(const vtkRenderState* s)
{
  // As vtkOpenGLRenderer::DeviceRenderTranslucentPolygonalGeometry() does.
  vtkRenderer* renderer = s->GetRenderer();
  vtkRenderStepsPass* steps = this->DefaultSteps;
  if (!renderer->GetUseDepthPeeling())
  {
    steps->SetTranslucentPass(this->OrderIndependent);
    steps->SetVolumetricPass(this->Volumetric);
    this->DepthPeeling->SetVolumetricPass(nullptr);
    return;
  }
  this->DepthPeeling->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
  this->DepthPeeling->SetOcclusionRatio(renderer->GetOcclusionRatio());
  // Volumes peeled with the translucent geometry, or drawn after it.
  const bool volumes = renderer->GetUseDepthPeelingForVolumes();
  this->DepthPeeling->SetVolumetricPass(volumes ? this->Volumetric.Get() : nullptr);
  steps->SetVolumetricPass(volumes ? nullptr : this->Volumetric.Get());
  steps->SetTranslucentPass(this->DepthPeeling);
}
