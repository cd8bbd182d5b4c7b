// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "Images.h"

#include "MessageCapture.h"

#include <vtkImageData.h>
#include <vtkImageExtractComponents.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkStdString.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace softshadows
{
//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> CaptureWindow(vtkRenderWindow* window, bool withAlpha)
{
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  // Rendering again would redo the whole frame (for `reference` hundreds of
  // shadow maps); the frame just drawn is still in the back buffer.
  capture->ShouldRerenderOff();
  capture->ReadFrontBufferOff();
  if (withAlpha)
  {
    capture->SetInputBufferTypeToRGBA();
  }
  else
  {
    capture->SetInputBufferTypeToRGB();
  }
  capture->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(capture->GetOutput());
  return image;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> GreyAndAlpha(vtkImageData* rgba)
{
  vtkNew<vtkImageExtractComponents> extract;
  extract->SetInputData(rgba);
  extract->SetComponents(0, 3);
  extract->Update();
  return extract->GetOutput();
}

//------------------------------------------------------------------------------
void WritePNG(vtkImageData* image, const std::filesystem::path& file)
{
  const std::string name = file.string();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(name.c_str());
  writer->SetInputData(image);
  MessageCapture messages;
  writer->Write();
  if (messages.HasError() || writer->GetErrorCode() != 0)
  {
    const std::string problem = messages.FirstMessage();
    throw std::runtime_error("cannot write " + name + (problem.empty() ? "" : ": " + problem));
  }
}

//------------------------------------------------------------------------------
void DrawLabel(vtkImageData* image, const std::string& text)
{
  vtkTextRenderer* textRenderer = vtkTextRenderer::GetInstance();
  if (!textRenderer)
  {
    throw std::runtime_error("no text renderer (VTK::RenderingFreeType is missing)");
  }
  int dimensions[3];
  image->GetDimensions(dimensions);

  vtkNew<vtkTextProperty> property;
  property->SetFontSize(std::max(12, dimensions[1] / 22));
  property->SetColor(1.0, 1.0, 1.0);
  property->SetBackgroundColor(0.0, 0.0, 0.0);
  property->SetBackgroundOpacity(0.6);
  property->BoldOn();
  vtkNew<vtkImageData> label;
  int labelSize[2];
  if (!textRenderer->RenderString(property, text, label, labelSize, 72))
  {
    throw std::runtime_error("cannot draw the label '" + text + "'");
  }

  // Blend the RGBA label into the image, its top left a margin from the
  // image's top left (VTK images count rows from the bottom).
  const int margin = 6;
  const int left = margin;
  const int bottom = dimensions[1] - margin - labelSize[1];
  int labelExtent[6];
  label->GetExtent(labelExtent);
  for (int y = 0; y < labelSize[1]; ++y)
  {
    for (int x = 0; x < labelSize[0]; ++x)
    {
      const int tx = left + x;
      const int ty = bottom + y;
      if (tx < 0 || ty < 0 || tx >= dimensions[0] || ty >= dimensions[1])
      {
        continue;
      }
      auto* source = static_cast<unsigned char*>(
        label->GetScalarPointer(labelExtent[0] + x, labelExtent[2] + y, labelExtent[4]));
      auto* target = static_cast<unsigned char*>(image->GetScalarPointer(tx, ty, 0));
      const int alpha = source[3];
      for (int c = 0; c < 3; ++c)
      {
        target[c] =
          static_cast<unsigned char>((source[c] * alpha + target[c] * (255 - alpha)) / 255);
      }
    }
  }
  image->Modified();
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> ComposeGrid(
  const std::vector<vtkSmartPointer<vtkImageData>>& images, int columns)
{
  const int border = 4;
  const unsigned char borderGrey = 32;
  int tile[3];
  images.front()->GetDimensions(tile);
  const int count = static_cast<int>(images.size());
  columns = std::max(1, std::min(columns, count));
  const int rows = (count + columns - 1) / columns;
  const int width = columns * tile[0] + (columns + 1) * border;
  const int height = rows * tile[1] + (rows + 1) * border;

  auto grid = vtkSmartPointer<vtkImageData>::New();
  grid->SetDimensions(width, height, 1);
  grid->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(grid->GetScalarPointer());
  std::memset(pixels, borderGrey, static_cast<std::size_t>(width) * height * 3);

  for (int i = 0; i < count; ++i)
  {
    const int column = i % columns;
    const int row = i / columns;
    const int left = border + column * (tile[0] + border);
    // Row 0 is at the top; image rows count from the bottom.
    const int bottom = border + (rows - 1 - row) * (tile[1] + border);
    for (int y = 0; y < tile[1]; ++y)
    {
      std::memcpy(grid->GetScalarPointer(left, bottom + y, 0), images[i]->GetScalarPointer(0, y, 0),
        static_cast<std::size_t>(tile[0]) * 3);
    }
  }
  return grid;
}
}
