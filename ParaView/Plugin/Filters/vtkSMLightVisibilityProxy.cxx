// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMLightVisibilityProxy.h"

#include "vtkClientServerStream.h"
#include "vtkObjectFactory.h"
#include "vtkSMPropertyHelper.h"

vtkStandardNewMacro(vtkSMLightVisibilityProxy);

//------------------------------------------------------------------------------
vtkSMLightVisibilityProxy::vtkSMLightVisibilityProxy() = default;

vtkSMLightVisibilityProxy::~vtkSMLightVisibilityProxy() = default;

//------------------------------------------------------------------------------
void vtkSMLightVisibilityProxy::HandOverRadius(vtkSMProxy* light)
{
  if (!light || !light->GetProperty("Radius") || !this->ObjectsCreated)
  {
    return;
  }
  vtkClientServerStream stream;
  stream << vtkClientServerStream::Invoke << VTKOBJECT(this) << "SetLightRadius" << VTKOBJECT(light)
         << vtkSMPropertyHelper(light, "Radius").GetAsDouble() << vtkClientServerStream::End;
  this->ExecuteStream(stream);
}

//------------------------------------------------------------------------------
void vtkSMLightVisibilityProxy::UpdateVTKObjects()
{
  this->Superclass::UpdateVTKObjects();
  if (this->GetProperty("Lights"))
  {
    vtkSMPropertyHelper lights(this, "Lights");
    for (unsigned int i = 0; i < lights.GetNumberOfElements(); ++i)
    {
      this->HandOverRadius(lights.GetAsProxy(i));
    }
  }
}

//------------------------------------------------------------------------------
void vtkSMLightVisibilityProxy::MarkDirtyFromProducer(
  vtkSMProxy* modifiedProxy, vtkSMProxy* producer, vtkSMProperty* property)
{
  if (property && property == this->GetProperty("Lights"))
  {
    this->HandOverRadius(producer);
  }
  this->Superclass::MarkDirtyFromProducer(modifiedProxy, producer, property);
}

//------------------------------------------------------------------------------
void vtkSMLightVisibilityProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
