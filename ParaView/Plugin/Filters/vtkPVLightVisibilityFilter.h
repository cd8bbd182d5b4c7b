// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkPVLightVisibilityFilter
 * @brief ParaView's "Light Visibility" filter: vtkLightVisibilityFilter with
 *        its lights given as parameters or taken from a view.
 *
 * The module's vtkLightVisibilityFilter, which ParaView's client-server
 * layer cannot call (the module is built without ParaView), run inside this
 * filter, which it can. What this class adds is where the lights come from
 * (LightsFrom):
 * - Parameters (0, the default): one light, of LightType point (0), spot (1)
 *   or directional (2), at LightPosition shining towards LightFocalPoint,
 *   of LightRadius (world units; degrees for a directional light),
 *   LightConeAngle (a spot light's) and LightIntensity;
 * - Lights (1): ParaView's light proxies given to AddLight() (in Python
 *   `Lights=list(view.AdditionalLights)`), each with its Radius, which
 *   vtkSMLightVisibilityProxy hands to SetLightRadius() as ParaView without
 *   ray tracing drops it;
 * - None (2): the sun only (SunHours).
 * Inputs may be composites of polygons (Extract Surface of multiblock data):
 * their blocks are merged into one surface, and one output.
 * The rest is vtkLightVisibilityFilter's, under the same names and with the
 * same defaults. Across MPI ranks (pvbatch, pvserver), each rank's piece is
 * shadowed by every rank's, through the global controller.
 */

#ifndef vtkPVLightVisibilityFilter_h
#define vtkPVLightVisibilityFilter_h

#include "vtkNew.h" // for vtkNew
#include "vtkPolyDataAlgorithm.h"
#include "vtkSoftShadowsParaViewFiltersModule.h" // for export macro

class vtkLight;
class vtkLightCollection;
class vtkLightVisibilityFilter;

class VTKSOFTSHADOWSPARAVIEWFILTERS_EXPORT vtkPVLightVisibilityFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkPVLightVisibilityFilter* New();
  vtkTypeMacro(vtkPVLightVisibilityFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum LightSources
  {
    PARAMETERS = 0,
    LIGHTS = 1,
    NONE = 2
  };
  enum LightTypes
  {
    POINT = 0,
    SPOT = 1,
    DIRECTIONAL = 2
  };

  /** Removes every caster connection (input 1). */
  void RemoveAllCasters();

  ///@{
  /** Where the lights come from (LightSources): default PARAMETERS. */
  void SetLightsFrom(int from);
  vtkGetMacro(LightsFrom, int);
  ///@}

  ///@{
  /**
   * The light given as parameters: type (LightTypes, default POINT),
   * position (default 0, 0, 1), focal point (default 0, 0, 0), radius
   * (default 0: a point, hard shadows), spot cone angle (default 30) and
   * intensity (default 1). A spot light's cone is under 90 degrees.
   */
  void SetLightType(int type);
  vtkGetMacro(LightType, int);
  void SetLightPosition(double x, double y, double z);
  void SetLightFocalPoint(double x, double y, double z);
  void SetLightRadius(double radius);
  void SetLightConeAngle(double degrees);
  void SetLightIntensity(double intensity);
  ///@}

  ///@{
  /**
   * ParaView's lights, for LightsFrom LIGHTS, and each one's size (its
   * proxy's Radius).
   */
  void AddLight(vtkLight* light);
  void RemoveAllLights();
  void SetLightRadius(vtkLight* light, double radius);
  ///@}

  ///@{
  /** vtkLightVisibilityFilter's, with its defaults. */
  void SetSamples(int samples);
  void SetPointVisibility(int on);
  void SetCellVisibility(int on);
  void SetReceiverCasts(int on);
  void SetTwoSided(int on);
  void SetSunHours(int on);
  void SetSunLatitude(double degrees);
  void SetSunDayOfYear(int day);
  void SetSunTimeStep(double hours);
  void SetSunUp(double x, double y, double z);
  void SetSunNorth(double x, double y, double z);
  void SetSunRadius(double degrees);
  ///@}

  /** Includes the inner filter's, its lights' included. */
  vtkMTimeType GetMTime() override;

protected:
  vtkPVLightVisibilityFilter();
  ~vtkPVLightVisibilityFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkPVLightVisibilityFilter(const vtkPVLightVisibilityFilter&) = delete;
  void operator=(const vtkPVLightVisibilityFilter&) = delete;

  // The inner filter's lights for LightsFrom.
  void UpdateLights();

  int LightsFrom = PARAMETERS;
  int LightType = POINT;
  double LightConeAngle = 30.0;
  vtkNew<vtkLightVisibilityFilter> Filter;
  vtkNew<vtkLight> ParameterLight;
  vtkNew<vtkLightCollection> ParaViewLights;
  vtkNew<vtkLightCollection> Lights; // what the inner filter reads
};

#endif
