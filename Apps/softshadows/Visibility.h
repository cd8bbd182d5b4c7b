// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Shadows as data for a scene file (`softshadows visibility`): every face
 * the scene draws, in world coordinates, with each light's visibility and
 * the sun's hours on it (vtkLightVisibilityFilter).
 */

#ifndef softshadows_Visibility_h
#define softshadows_Visibility_h

#include "Progress.h"

#include <vtkSmartPointer.h>

#include <array>

class vtkPolyData;
class vtkRenderer;

namespace softshadows
{
/// The sun over a day, when `On` (vtkLightVisibilityFilter's Sun settings).
struct SunDay
{
  bool On = false;
  double Latitude = 0.0;
  int Day = 80;
  double Step = 0.25;
  std::array<double, 3> Up{ 0.0, 1.0, 0.0 };
  std::array<double, 3> North{ 0.0, 0.0, -1.0 };
};

/// The faces of every actor `renderer` draws (opaque ones, then the
/// translucent ones, which receive but do not cast, as in VTK's shadows),
/// placed in the world and appended, with the renderer's lights'
/// LightVisibility and Irradiance on the points (and cells, when `cells`)
/// and, with `sun`, SunHours and SunFraction; `samples` rays a light and a
/// point. Throws std::runtime_error when the scene has no faces or the
/// filter fails.
vtkSmartPointer<vtkPolyData> CastVisibility(
  vtkRenderer* renderer, int samples, bool cells, const SunDay& sun, Progress* progress = nullptr);
}

#endif
