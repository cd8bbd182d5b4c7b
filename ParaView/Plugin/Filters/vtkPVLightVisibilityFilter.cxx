// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVLightVisibilityFilter.h"

#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositeDataSetRange.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightVisibilityFilter.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkShadowLightSize.h"
#include "vtkSmartPointer.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVLightVisibilityFilter);

namespace
{
// `data` as one vtkPolyData: itself, or a composite's leaves appended (as
// Extract Surface makes of multiblock data), so that every block shadows
// every other and each rank runs the filter once; null for other data.
vtkSmartPointer<vtkPolyData> Surfaces(vtkDataObject* data)
{
  if (auto* polyData = vtkPolyData::SafeDownCast(data))
  {
    return polyData;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(data);
  if (!composite)
  {
    return nullptr;
  }
  vtkNew<vtkAppendPolyData> append;
  for (vtkDataObject* leaf : vtk::Range(composite))
  {
    auto* polyData = vtkPolyData::SafeDownCast(leaf);
    if (!polyData)
    {
      return nullptr;
    }
    append->AddInputData(polyData);
  }
  if (append->GetNumberOfInputConnections(0) == 0)
  {
    return vtkSmartPointer<vtkPolyData>::New();
  }
  append->Update();
  return append->GetOutput();
}
}

//------------------------------------------------------------------------------
vtkPVLightVisibilityFilter::vtkPVLightVisibilityFilter()
{
  this->SetNumberOfInputPorts(2);
  this->ParameterLight->SetPosition(0.0, 0.0, 1.0);
  this->ParameterLight->SetFocalPoint(0.0, 0.0, 0.0);
  this->SetLightType(POINT);
  this->Filter->SetLights(this->Lights);
  this->UpdateLights();
}

vtkPVLightVisibilityFilter::~vtkPVLightVisibilityFilter() = default;

//------------------------------------------------------------------------------
int vtkPVLightVisibilityFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkPVLightVisibilityFilter::RemoveAllCasters()
{
  this->SetInputConnection(1, nullptr);
}

//------------------------------------------------------------------------------
void vtkPVLightVisibilityFilter::SetLightsFrom(int from)
{
  from = std::min(std::max(from, static_cast<int>(PARAMETERS)), static_cast<int>(NONE));
  if (this->LightsFrom != from)
  {
    this->LightsFrom = from;
    this->UpdateLights();
    this->Modified();
  }
}

void vtkPVLightVisibilityFilter::UpdateLights()
{
  this->Lights->RemoveAllItems();
  if (this->LightsFrom == PARAMETERS)
  {
    this->Lights->AddItem(this->ParameterLight);
  }
  else if (this->LightsFrom == LIGHTS)
  {
    vtkCollectionSimpleIterator it;
    this->ParaViewLights->InitTraversal(it);
    while (vtkLight* light = this->ParaViewLights->GetNextLight(it))
    {
      this->Lights->AddItem(light);
    }
  }
}

//------------------------------------------------------------------------------
// A point light is VTK's positional light with a cone of 90 degrees or more.
void vtkPVLightVisibilityFilter::SetLightType(int type)
{
  this->LightType =
    std::min(std::max(type, static_cast<int>(POINT)), static_cast<int>(DIRECTIONAL));
  vtkLight* light = this->ParameterLight;
  light->SetPositional(this->LightType != DIRECTIONAL);
  light->SetConeAngle(this->LightType == SPOT ? this->LightConeAngle : 180.0);
}

void vtkPVLightVisibilityFilter::SetLightPosition(double x, double y, double z)
{
  this->ParameterLight->SetPosition(x, y, z);
}

void vtkPVLightVisibilityFilter::SetLightFocalPoint(double x, double y, double z)
{
  this->ParameterLight->SetFocalPoint(x, y, z);
}

void vtkPVLightVisibilityFilter::SetLightRadius(double radius)
{
  this->SetLightRadius(this->ParameterLight, radius);
}

void vtkPVLightVisibilityFilter::SetLightConeAngle(double degrees)
{
  this->LightConeAngle = degrees;
  this->SetLightType(this->LightType);
}

void vtkPVLightVisibilityFilter::SetLightIntensity(double intensity)
{
  this->ParameterLight->SetIntensity(intensity);
}

//------------------------------------------------------------------------------
void vtkPVLightVisibilityFilter::AddLight(vtkLight* light)
{
  if (light)
  {
    this->ParaViewLights->AddItem(light);
    this->UpdateLights();
    this->Modified();
  }
}

void vtkPVLightVisibilityFilter::RemoveAllLights()
{
  if (this->ParaViewLights->GetNumberOfItems() > 0)
  {
    this->ParaViewLights->RemoveAllItems();
    this->UpdateLights();
    this->Modified();
  }
}

void vtkPVLightVisibilityFilter::SetLightRadius(vtkLight* light, double radius)
{
  // (The light's information's time is the inner filter's.)
  if (light && radius != vtkShadowLightSize::GetRadius(light))
  {
    vtkShadowLightSize::SetRadius(radius, light);
  }
}

//------------------------------------------------------------------------------
void vtkPVLightVisibilityFilter::SetSamples(int samples)
{
  this->Filter->SetSamples(samples);
}

void vtkPVLightVisibilityFilter::SetPointVisibility(int on)
{
  this->Filter->SetPointVisibility(on != 0);
}

void vtkPVLightVisibilityFilter::SetCellVisibility(int on)
{
  this->Filter->SetCellVisibility(on != 0);
}

void vtkPVLightVisibilityFilter::SetReceiverCasts(int on)
{
  this->Filter->SetReceiverCasts(on != 0);
}

void vtkPVLightVisibilityFilter::SetTwoSided(int on)
{
  this->Filter->SetTwoSided(on != 0);
}

void vtkPVLightVisibilityFilter::SetSunHours(int on)
{
  this->Filter->SetSunHours(on != 0);
}

void vtkPVLightVisibilityFilter::SetSunLatitude(double degrees)
{
  this->Filter->SetSunLatitude(degrees);
}

void vtkPVLightVisibilityFilter::SetSunDayOfYear(int day)
{
  this->Filter->SetSunDayOfYear(day);
}

void vtkPVLightVisibilityFilter::SetSunTimeStep(double hours)
{
  this->Filter->SetSunTimeStep(hours);
}

void vtkPVLightVisibilityFilter::SetSunUp(double x, double y, double z)
{
  this->Filter->SetSunUp(x, y, z);
}

void vtkPVLightVisibilityFilter::SetSunNorth(double x, double y, double z)
{
  this->Filter->SetSunNorth(x, y, z);
}

void vtkPVLightVisibilityFilter::SetSunRadius(double degrees)
{
  this->Filter->SetSunRadius(degrees);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkPVLightVisibilityFilter::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Filter->GetMTime());
}

//------------------------------------------------------------------------------
int vtkPVLightVisibilityFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // (The same data type on every rank: all refuse together, before the
  // inner filter's exchange.)
  vtkLightVisibilityFilter* filter = this->Filter;
  vtkSmartPointer<vtkPolyData> receiver = Surfaces(vtkDataObject::GetData(inputVector[0]));
  if (!receiver)
  {
    vtkErrorMacro(<< "the input must be polygons: a vtkPolyData, or a composite of them.");
    return 0;
  }
  filter->SetInputData(receiver);
  filter->RemoveAllCasters();
  for (int c = 0; c < inputVector[1]->GetNumberOfInformationObjects(); ++c)
  {
    vtkSmartPointer<vtkPolyData> caster = Surfaces(vtkDataObject::GetData(inputVector[1], c));
    if (!caster)
    {
      vtkErrorMacro(<< "caster " << c
                    << " must be polygons: a vtkPolyData, or a composite of them.");
      filter->SetInputData(nullptr);
      filter->RemoveAllCasters();
      return 0;
    }
    filter->AddCasterData(caster);
  }
  // Its progress as this filter's.
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(this);
  progress->SetCallback(
    [](vtkObject* caller, unsigned long, void* self, void*)
    {
      static_cast<vtkAlgorithm*>(self)->UpdateProgress(
        static_cast<vtkAlgorithm*>(caller)->GetProgress());
    });
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  const bool done = filter->GetExecutive()->Update() != 0;
  filter->RemoveObserver(progress);
  vtkPolyData::GetData(outputVector)->ShallowCopy(filter->GetOutput());
  // Not to hold the inputs between runs.
  filter->SetInputData(nullptr);
  filter->RemoveAllCasters();
  return done ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkPVLightVisibilityFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightsFrom: " << this->LightsFrom << "\n";
  os << indent << "LightType: " << this->LightType << "\n";
  os << indent << "LightConeAngle: " << this->LightConeAngle << "\n";
  os << indent << "ParaView lights: " << this->ParaViewLights->GetNumberOfItems() << "\n";
  os << indent << "Filter:\n";
  this->Filter->PrintSelf(os, indent.GetNextIndent());
}
