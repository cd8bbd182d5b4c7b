// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkShadowLightSize.h"

#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkShadowLightSize);

vtkInformationKeyMacro(vtkShadowLightSize, RADIUS, Double);

//------------------------------------------------------------------------------
void vtkShadowLightSize::SetRadius(double radius, vtkLight* light)
{
  if (!light)
  {
    return;
  }
  if (!(radius >= 0.0)) // also rejects NaN
  {
    vtkGenericWarningMacro("SetRadius: a light's radius must be >= 0, got " << radius);
    return;
  }
  light->GetInformation()->Set(vtkShadowLightSize::RADIUS(), radius);
}

//------------------------------------------------------------------------------
double vtkShadowLightSize::GetRadius(vtkLight* light)
{
  if (!light || !light->GetInformation()->Has(vtkShadowLightSize::RADIUS()))
  {
    return 0.0;
  }
  return light->GetInformation()->Get(vtkShadowLightSize::RADIUS());
}

//------------------------------------------------------------------------------
bool vtkShadowLightSize::IsPointLight(vtkLight* light)
{
  return light && light->GetPositional() && light->GetConeAngle() >= 90.0;
}

//------------------------------------------------------------------------------
double vtkShadowLightSize::GetWidth(double radius, bool directional)
{
  return directional ? 2.0 * std::tan(vtkMath::RadiansFromDegrees(radius)) : 2.0 * radius;
}

//------------------------------------------------------------------------------
void vtkShadowLightSize::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
