// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMShadowRenderViewProxy.h"

#include "vtkClientServerStream.h"
#include "vtkObjectFactory.h"
#include "vtkSMPropertyHelper.h"

vtkStandardNewMacro(vtkSMShadowRenderViewProxy);

//------------------------------------------------------------------------------
vtkSMShadowRenderViewProxy::vtkSMShadowRenderViewProxy() = default;

//------------------------------------------------------------------------------
vtkSMShadowRenderViewProxy::~vtkSMShadowRenderViewProxy() = default;

//------------------------------------------------------------------------------
vtkTypeUInt32 vtkSMShadowRenderViewProxy::PreRender(bool interactive)
{
  if (this->GetProperty("AdditionalLights"))
  {
    vtkSMPropertyHelper lights(this, "AdditionalLights");
    for (unsigned int i = 0; i < lights.GetNumberOfElements(); ++i)
    {
      vtkSMProxy* light = lights.GetAsProxy(i);
      if (!light || !light->GetProperty("Radius"))
      {
        continue;
      }
      const double radius = vtkSMPropertyHelper(light, "Radius").GetAsDouble();
      auto known = this->Radii.find(light->GetGlobalID());
      if (known != this->Radii.end() && known->second == radius)
      {
        continue;
      }
      this->Radii[light->GetGlobalID()] = radius;
      vtkClientServerStream stream;
      stream << vtkClientServerStream::Invoke << VTKOBJECT(this) << "SetLightRadius"
             << VTKOBJECT(light) << radius << vtkClientServerStream::End;
      this->ExecuteStream(stream);
    }
  }
  return this->Superclass::PreRender(interactive);
}

//------------------------------------------------------------------------------
void vtkSMShadowRenderViewProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Lights with a radius handed over: " << this->Radii.size() << "\n";
}
