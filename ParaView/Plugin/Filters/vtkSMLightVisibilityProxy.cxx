// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMLightVisibilityProxy.h"

#include "vtkClientServerStream.h"
#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkSMPropertyHelper.h"

vtkStandardNewMacro(vtkSMLightVisibilityProxy);

//------------------------------------------------------------------------------
vtkSMLightVisibilityProxy::vtkSMLightVisibilityProxy() = default;

vtkSMLightVisibilityProxy::~vtkSMLightVisibilityProxy()
{
  this->StopWatching();
}

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
void vtkSMLightVisibilityProxy::StopWatching()
{
  for (const auto& watched : this->Watched)
  {
    if (vtkSMProxy* light = watched.first)
    {
      light->RemoveObserver(watched.second);
    }
  }
  this->Watched.clear();
}

void vtkSMLightVisibilityProxy::WatchLights()
{
  this->StopWatching();
  if (!this->GetProperty("Lights"))
  {
    return;
  }
  vtkSMPropertyHelper lights(this, "Lights");
  for (unsigned int i = 0; i < lights.GetNumberOfElements(); ++i)
  {
    if (vtkSMProxy* light = lights.GetAsProxy(i))
    {
      const unsigned long tag = light->AddObserver(
        vtkCommand::ModifiedEvent, this, &vtkSMLightVisibilityProxy::LightModified);
      this->Watched.emplace_back(light, tag);
      this->HandOverRadius(light);
    }
  }
}

void vtkSMLightVisibilityProxy::LightModified(vtkObject* light, unsigned long, void*)
{
  this->HandOverRadius(vtkSMProxy::SafeDownCast(light));
}

//------------------------------------------------------------------------------
void vtkSMLightVisibilityProxy::UpdateVTKObjects()
{
  this->Superclass::UpdateVTKObjects();
  this->WatchLights();
}

//------------------------------------------------------------------------------
void vtkSMLightVisibilityProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Lights watched: " << this->Watched.size() << "\n";
}
