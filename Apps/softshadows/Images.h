// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Reading a rendered window into images, writing PNGs, and the gallery.
 */

#ifndef softshadows_Images_h
#define softshadows_Images_h

#include <vtkSmartPointer.h>

#include <filesystem>
#include <string>
#include <vector>

class vtkImageData;
class vtkRenderWindow;

namespace softshadows
{
/// The window's last frame as 8-bit RGB (or RGBA), without rendering again.
vtkSmartPointer<vtkImageData> CaptureWindow(vtkRenderWindow* window, bool withAlpha);

/// Grey + alpha from an RGBA capture: its red (the visibility) and alpha.
vtkSmartPointer<vtkImageData> GreyAndAlpha(vtkImageData* rgba);

/// Writes a PNG; throws std::runtime_error when it cannot.
void WritePNG(vtkImageData* image, const std::filesystem::path& file);

/// Writes `text` on a dark box in the top-left corner of an RGB image.
void DrawLabel(vtkImageData* image, const std::string& text);

/**
 * Equally sized RGB images in a grid of `columns`, row by row from the top
 * left, with a thin border between them.
 */
vtkSmartPointer<vtkImageData> ComposeGrid(
  const std::vector<vtkSmartPointer<vtkImageData>>& images, int columns);
}

#endif
