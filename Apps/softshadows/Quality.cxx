// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "Quality.h"

#include "MessageCapture.h"

#include "vtkRayCastLightVisibility.h"

#include <vtkAlgorithm.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace softshadows
{
namespace
{
vtkSmartPointer<vtkImageData> Image8(vtkImageData* like, int components)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(like->GetExtent());
  image->AllocateScalars(VTK_UNSIGNED_CHAR, components);
  return image;
}
}

//------------------------------------------------------------------------------
void UpdateRayCasting(vtkAlgorithm* caster, Progress* progress)
{
  MessageCapture messages;
  Progress::Observation observation;
  if (progress)
  {
    observation = progress->Observe(
      caster, [progress](double fraction) { progress->Show("ray casting", fraction); });
  }
  caster->Update();
  if (progress)
  {
    progress->Clear();
  }
  if (messages.HasError())
  {
    throw std::runtime_error("ray casting failed: " + messages.FirstMessage());
  }
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> CastTruth(
  vtkRenderer* renderer, const std::array<int, 2>& size, int light, int samples, Progress* progress)
{
  vtkNew<vtkRayCastLightVisibility> caster;
  caster->SetRenderer(renderer);
  caster->SetSize(size[0], size[1]);
  caster->SetLightIndex(light);
  caster->SetSamples(samples);
  UpdateRayCasting(caster, progress);
  auto truth = vtkSmartPointer<vtkImageData>::New();
  truth->ShallowCopy(caster->GetOutput());
  return truth;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> TruthImage(vtkImageData* truth)
{
  vtkSmartPointer<vtkImageData> image = Image8(truth, 2);
  vtkDataArray* visibility = truth->GetPointData()->GetArray("Visibility");
  vtkDataArray* geometry = truth->GetPointData()->GetArray("Geometry");
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (vtkIdType i = 0; i < visibility->GetNumberOfTuples(); ++i)
  {
    const bool seen = geometry->GetTuple1(i) > 0.0;
    out[2 * i] =
      seen ? static_cast<unsigned char>(std::lround(255.0 * visibility->GetTuple1(i))) : 0;
    out[2 * i + 1] = seen ? 255 : 0;
  }
  return image;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> MaskImage(vtkImageData* truth)
{
  vtkSmartPointer<vtkImageData> image = Image8(truth, 1);
  vtkDataArray* mask = truth->GetPointData()->GetArray("QualityMask");
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  for (vtkIdType i = 0; i < mask->GetNumberOfTuples(); ++i)
  {
    out[i] = mask->GetTuple1(i) > 0.0 ? 255 : 0;
  }
  return image;
}

//------------------------------------------------------------------------------
QualityFigures CompareWithTruth(vtkImageData* shadowOnly, vtkImageData* truth)
{
  vtkDataArray* visibility = truth->GetPointData()->GetArray("Visibility");
  vtkDataArray* mask = truth->GetPointData()->GetArray("QualityMask");
  vtkDataArray* frame = shadowOnly->GetPointData()->GetScalars();
  if (frame->GetNumberOfTuples() != visibility->GetNumberOfTuples())
  {
    throw std::logic_error("the frame and the truth differ in size");
  }
  QualityFigures figures;
  double squares = 0.0, umbraSum = 0.0;
  long off = 0, umbra = 0, penumbra = 0, truthPenumbra = 0;
  auto inPenumbra = [](double v) { return v > UmbraLevel && v < 1.0 - UmbraLevel; };
  for (vtkIdType i = 0; i < visibility->GetNumberOfTuples(); ++i)
  {
    if (mask->GetTuple1(i) <= 0.0)
    {
      continue;
    }
    const double value = frame->GetComponent(i, 0) / 255.0;
    const double truthValue = visibility->GetTuple1(i);
    const double error = value - truthValue;
    squares += error * error;
    off += std::abs(error) > MismatchTolerance ? 1 : 0;
    ++figures.Pixels;
    if (truthValue <= UmbraLevel)
    {
      umbraSum += value;
      ++umbra;
    }
    penumbra += inPenumbra(value) ? 1 : 0;
    truthPenumbra += inPenumbra(truthValue) ? 1 : 0;
  }
  if (figures.Pixels > 0)
  {
    figures.RMSE = std::sqrt(squares / static_cast<double>(figures.Pixels));
    figures.Mismatch = static_cast<double>(off) / static_cast<double>(figures.Pixels);
  }
  figures.Umbra = umbra > 0 ? umbraSum / static_cast<double>(umbra) : 0.0;
  figures.PenumbraRatio =
    truthPenumbra > 0 ? static_cast<double>(penumbra) / static_cast<double>(truthPenumbra) : 0.0;
  return figures;
}
}
