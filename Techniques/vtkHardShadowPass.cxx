// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHardShadowPass.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkHardShadowPass);

vtkHardShadowPass::vtkHardShadowPass() = default;
vtkHardShadowPass::~vtkHardShadowPass() = default;

//------------------------------------------------------------------------------
vtkSoftShadowPass::Traits vtkHardShadowPass::GetTraits() const
{
  Traits traits;
  traits.PointLights = true;
  return traits;
}

//------------------------------------------------------------------------------
bool vtkHardShadowPass::RenderShadowMaps(const vtkRenderState* s)
{
  return this->RenderLightDepthMaps(s, this->HardwareFiltering);
}

//------------------------------------------------------------------------------
void vtkHardShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PCFRadius: " << this->PCFRadius << "\n";
  os << indent << "HardwareFiltering: " << this->HardwareFiltering << "\n";
}
