// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSolarPosition.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <cmath>

vtkStandardNewMacro(vtkSolarPosition);

//------------------------------------------------------------------------------
double vtkSolarPosition::GetDeclination(double dayOfYear, double solarHour)
{
  // The fractional year, radians (NOAA's form of Spencer's series).
  const double g = 2.0 * vtkMath::Pi() / 365.0 * (dayOfYear - 1.0 + (solarHour - 12.0) / 24.0);
  const double declination = 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) -
    0.006758 * std::cos(2.0 * g) + 0.000907 * std::sin(2.0 * g) - 0.002697 * std::cos(3.0 * g) +
    0.00148 * std::sin(3.0 * g);
  return vtkMath::DegreesFromRadians(declination);
}

//------------------------------------------------------------------------------
void vtkSolarPosition::GetDirection(
  double latitude, double dayOfYear, double solarHour, double eastNorthUp[3])
{
  const double phi = vtkMath::RadiansFromDegrees(latitude);
  const double delta = vtkMath::RadiansFromDegrees(GetDeclination(dayOfYear, solarHour));
  // The hour angle: 15 degrees an hour, zero at solar noon, negative in the
  // morning (the sun east of the meridian).
  const double h = vtkMath::RadiansFromDegrees(15.0 * (solarHour - 12.0));
  // The sun's direction in the equatorial frame turned to the horizon's:
  // east, north (along the meridian) and up.
  eastNorthUp[0] = -std::cos(delta) * std::sin(h);
  eastNorthUp[1] = std::cos(phi) * std::sin(delta) - std::sin(phi) * std::cos(delta) * std::cos(h);
  eastNorthUp[2] = std::sin(phi) * std::sin(delta) + std::cos(phi) * std::cos(delta) * std::cos(h);
}

//------------------------------------------------------------------------------
void vtkSolarPosition::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
