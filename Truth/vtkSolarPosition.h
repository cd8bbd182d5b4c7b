// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSolarPosition
 * @brief   Where the sun stands in the sky, for a latitude, a day of the
 *          year and an hour of local apparent solar time.
 *
 * The sun's declination is Spencer's Fourier series in the fractional year
 * (J. W. Spencer, "Fourier series representation of the position of the
 * sun", Search 2(5), 1971; the form NOAA's Global Monitoring Laboratory
 * publishes as its "General Solar Position Calculations"): a mean year's.
 * Against the 2026 equinoxes and solstices (U.S. Naval Observatory) it errs
 * by 0.42-0.44 degrees at the equinoxes, where the declination moves 0.4
 * degrees a day and a given year's equinox falls up to a day from the
 * mean's, and by 0.015 degrees at the solstices (test_light_visibility.py).
 * Hours are apparent solar time, noon when the sun crosses the meridian, so
 * neither the equation of time nor the longitude enters: a whole day of
 * them is the day's sun, wherever on its latitude. Refraction is left out
 * (it raises the sun by about half a degree at the horizon, lengthening the
 * day by a few minutes).
 */

#ifndef vtkSolarPosition_h
#define vtkSolarPosition_h

#include "vtkObject.h"
#include "vtkSoftShadowsTruthModule.h" // for export macro

class VTKSOFTSHADOWSTRUTH_EXPORT vtkSolarPosition : public vtkObject
{
public:
  static vtkSolarPosition* New();
  vtkTypeMacro(vtkSolarPosition, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The sun's declination in degrees on `dayOfYear` (1 is 1 January) at
   * `solarHour` (0-24).
   */
  static double GetDeclination(double dayOfYear, double solarHour);

  /**
   * The unit vector towards the sun, in the local east, north, up frame, at
   * `latitude` degrees (north positive) on `dayOfYear` at `solarHour`. Its
   * third component is the sine of the sun's elevation: the sun is up where
   * it is positive.
   */
  static void GetDirection(
    double latitude, double dayOfYear, double solarHour, double eastNorthUp[3]);

protected:
  vtkSolarPosition() = default;
  ~vtkSolarPosition() override = default;

private:
  vtkSolarPosition(const vtkSolarPosition&) = delete;
  void operator=(const vtkSolarPosition&) = delete;
};

#endif
