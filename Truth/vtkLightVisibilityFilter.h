// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightVisibilityFilter
 * @brief   Shadows as data: how much of each light every point (or cell) of
 *          a surface sees, by ray casting.
 *
 * Input 0 is the receiving surface; input 1, optional and repeatable
 * (AddCasterConnection()), the geometry that casts shadows on it. The
 * receiver casts onto itself too (unless ReceiverCasts is off). Both are in
 * world coordinates; only polygons and strips cast and receive. The lights
 * (SetLights()) are taken where they shine in the world (their transformed
 * position and focal point), each with the module's light size
 * (vtkShadowLightSize): spot and point lights are spheres of that radius,
 * directional lights cones of directions of that angular radius, sampled by
 * Samples stratified rays as the ground truth samples them
 * (vtkRayCastLightVisibility). Camera lights and headlights are taken where
 * their position says, as no camera is at hand.
 *
 * The output is the receiver with, on its points (PointVisibility, on by
 * default) and on its cells (CellVisibility, off by default; from each
 * cell's centre, for a strip its triangles' weighted by area, and its
 * polygon's normal):
 * - "LightVisibility", one component a light, in the collection's order:
 *   the visible fraction of the light, 0..1. A point reads 0 for a light
 *   behind its surface (the side its normal points away from), and 1 for a
 *   light whose sphere it lies in. Point normals are the receiver's own
 *   ("Normals", or its active normals) or, without them, computed as
 *   vtkPolyDataNormals does without splitting.
 * - "Irradiance": the direct irradiance the switched-on lights bring, the
 *   sum of visibility x cos(angle to the light's centre) x intensity, times
 *   a positional light's attenuation (VTK's constant, linear and quadratic
 *   terms) and a spot light's cone (its exponent inside, 0 outside), as
 *   VTK's lights shade.
 *
 * With SunHours on, the sun over a day as well, on the same points and
 * cells: a cone of SunRadius degrees (default 0.27) from directions a
 * SunTimeStep apart (hours of apparent solar time) on SunDayOfYear at
 * SunLatitude (vtkSolarPosition), in a world whose up and north are SunUp
 * and SunNorth (defaults +z and +y, as in GIS data; east is north x up), or
 * from the directions and weights in hours given by AddSunDirection():
 * - "SunHours": the hours of direct sun, each step's visible fraction
 *   times its hours, summed over the steps the sun is up;
 * - "SunFraction": that over the day's hours of daylight (0 without any).
 *
 * Surfaces receive on the side their normals point to. VTK's isosurfaces
 * of fields negative inside point theirs inwards (VTK's two-sided lighting
 * hides it): reverse them first (vtkReverseSense, or vtkPolyDataNormals'
 * FlipNormals or AutoOrientNormals on closed surfaces), or turn TwoSided
 * on.
 *
 * Split among processes (ParaView's pvbatch and pvserver ranks, each
 * holding its own pieces of the receiver and the casters; SetController()),
 * every process's opaque surfaces are gathered so that each casts on every
 * other's receiver (each process then holds every process's casting
 * surfaces), and a point's rays are drawn from its position, not its id:
 * each point reads what it would with all the data on one process, given
 * its normal. Where the receiver has no normals they are computed from each
 * piece's own cells, so that points on the seams between pieces may differ:
 * give the receiver its normals first (vtkPolyDataNormals on the whole, or
 * ParaView's Generate Surface Normals) where the seams matter. Every
 * process runs the same lights: a camera light, which each process moves
 * with its own camera, shadows alike only where every process renders.
 *
 * Errors (vtkErrorMacro, no output): no receiver, neither lights nor
 * SunHours, a receiver point that is not finite (or beyond float range:
 * rays are cast in floats), a light or sun setting that is not finite,
 * SunUp and SunNorth parallel. Where the sun never rises, SunHours and
 * SunFraction are 0. Reports progress (ProgressEvent) in 32 bands.
 */

#ifndef vtkLightVisibilityFilter_h
#define vtkLightVisibilityFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"           // for vtkSmartPointer
#include "vtkSoftShadowsTruthModule.h" // for export macro

#include <array>  // for std::array
#include <vector> // for std::vector

class vtkLightCollection;
class vtkMultiProcessController;
struct vtkLightVisibilitySunStep;

class VTKSOFTSHADOWSTRUTH_EXPORT vtkLightVisibilityFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLightVisibilityFilter* New();
  vtkTypeMacro(vtkLightVisibilityFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Geometry that casts shadows on the receiver (input 1), in addition to
   * the receiver itself.
   */
  void AddCasterConnection(vtkAlgorithmOutput* caster);
  void AddCasterData(vtkDataObject* caster);
  void RemoveAllCasters();
  ///@}

  ///@{
  /**
   * The lights. Default none, which is an error.
   */
  void SetLights(vtkLightCollection* lights);
  vtkLightCollection* GetLights() const;
  ///@}

  ///@{
  /**
   * Rays a light and a point, rounded to a square number (stratified).
   * Default 64.
   */
  vtkSetClampMacro(Samples, int, 1, 65536);
  vtkGetMacro(Samples, int);
  ///@}

  ///@{
  /**
   * The seed of each point's jitter of the stratified pattern. Default 1.
   */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  ///@{
  /**
   * Whether the arrays are computed on the points (default on) and on the
   * cells (default off).
   */
  vtkSetMacro(PointVisibility, bool);
  vtkGetMacro(PointVisibility, bool);
  vtkBooleanMacro(PointVisibility, bool);
  vtkSetMacro(CellVisibility, bool);
  vtkGetMacro(CellVisibility, bool);
  vtkBooleanMacro(CellVisibility, bool);
  ///@}

  ///@{
  /**
   * The sun over a day (see the class description). Defaults: off,
   * latitude 0 degrees, day 80 (about the March equinox), a step of 0.25
   * hours (a minute to an hour, rounded so that whole steps fill the day),
   * up +z, north +y, a radius of 0.27 degrees.
   */
  vtkSetMacro(SunHours, bool);
  vtkGetMacro(SunHours, bool);
  vtkBooleanMacro(SunHours, bool);
  vtkSetClampMacro(SunLatitude, double, -90.0, 90.0);
  vtkGetMacro(SunLatitude, double);
  vtkSetClampMacro(SunDayOfYear, int, 1, 366);
  vtkGetMacro(SunDayOfYear, int);
  vtkSetClampMacro(SunTimeStep, double, 1.0 / 60.0, 1.0);
  vtkGetMacro(SunTimeStep, double);
  vtkSetVector3Macro(SunUp, double);
  vtkGetVector3Macro(SunUp, double);
  vtkSetVector3Macro(SunNorth, double);
  vtkGetVector3Macro(SunNorth, double);
  vtkSetClampMacro(SunRadius, double, 0.0, 10.0);
  vtkGetMacro(SunRadius, double);
  ///@}

  ///@{
  /**
   * Directions towards the sun (world coordinates) and the hours each
   * stands for, instead of a day's at SunLatitude: each counts as daylight.
   */
  void AddSunDirection(double x, double y, double z, double hours);
  void RemoveAllSunDirections();
  ///@}

  ///@{
  /**
   * Whether each point receives on whichever side of its surface faces the
   * light's centre (as VTK's two-sided lighting shades), rather than only
   * on the side its normal points to. Default off. On, a closed surface is
   * right whichever way its normals point (an isosurface's point inwards)
   * but at its terminator, where part of a light above the tangent plane
   * goes unseen, and a sheet is lit from both sides.
   */
  vtkSetMacro(TwoSided, bool);
  vtkGetMacro(TwoSided, bool);
  vtkBooleanMacro(TwoSided, bool);
  ///@}

  ///@{
  /**
   * Whether the receiver casts shadows (on itself) as well as receiving
   * them. Default on; off for translucent surfaces, which VTK's shadows
   * and the ground truth let receive only.
   */
  vtkSetMacro(ReceiverCasts, bool);
  vtkGetMacro(ReceiverCasts, bool);
  vtkBooleanMacro(ReceiverCasts, bool);
  ///@}

  ///@{
  /**
   * The processes among which the receiver and casters are split, each
   * with its own pieces: every process's opaque surfaces cast on every
   * other's receiver. Default: the global controller. With one process (or
   * none) nothing is exchanged; with several, every process must run the
   * filter together.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController() const;
  ///@}

  /**
   * Includes the lights' modification times, their sizes' included: moving
   * or resizing a light casts again.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkLightVisibilityFilter();
  ~vtkLightVisibilityFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int Samples = 64;
  unsigned int Seed = 1;
  bool PointVisibility = true;
  bool CellVisibility = false;
  bool ReceiverCasts = true;
  bool TwoSided = false;
  bool SunHours = false;
  double SunLatitude = 0.0;
  int SunDayOfYear = 80;
  double SunTimeStep = 0.25;
  double SunUp[3] = { 0.0, 0.0, 1.0 };
  double SunNorth[3] = { 0.0, 1.0, 0.0 };
  double SunRadius = 0.27;

private:
  vtkLightVisibilityFilter(const vtkLightVisibilityFilter&) = delete;
  // The sun's directions and hours for SunHours; false, with an error, for
  // a world without a north or a direction without a length.
  bool SunSteps(std::vector<vtkLightVisibilitySunStep>& steps);
  void operator=(const vtkLightVisibilityFilter&) = delete;

  vtkSmartPointer<vtkLightCollection> Lights;
  vtkSmartPointer<vtkMultiProcessController> Controller;
  std::vector<std::array<double, 4>> SunDirections; // x, y, z, hours
};

#endif
