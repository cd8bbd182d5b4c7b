// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkFenceSource
 * @brief   Create a garden fence: vertical pickets on two horizontal rails.
 *
 * vtkFenceSource makes a test and demo occluder with many thin parallel gaps,
 * the kind of geometry where soft shadow techniques differ most. The fence
 * stands on the plane y = 0 (VTK's usual y-up), runs along x and is centred
 * on the origin in x and z.
 *
 * NumberOfPickets boxes of PicketWidth x Height x Thickness stand side by
 * side with Gap between neighbours, in front (z from 0 to Thickness). Two
 * rails, boxes as long as the fence, PicketWidth high and Thickness deep, are
 * centred at 0.25 and 0.75 of Height and run behind the pickets (z from
 * -Thickness to 0), so the whole fence is centred on z = 0 and light passes
 * between the pickets except where the rails are.
 *
 * The output is triangles only, four points per box face so that every face
 * has its own outward normal (point data "Normals").
 */

#ifndef vtkFenceSource_h
#define vtkFenceSource_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkSoftShadowsFiltersModule.h" // for export macro

class VTKSOFTSHADOWSFILTERS_EXPORT vtkFenceSource : public vtkPolyDataAlgorithm
{
public:
  static vtkFenceSource* New();
  vtkTypeMacro(vtkFenceSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Number of vertical pickets. Default 7.
   */
  vtkSetClampMacro(NumberOfPickets, int, 1, VTK_INT_MAX);
  vtkGetMacro(NumberOfPickets, int);
  ///@}

  ///@{
  /**
   * Width of a picket along x, also the height of a rail. Must be > 0.
   * Default 0.1.
   */
  vtkSetClampMacro(PicketWidth, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PicketWidth, double);
  ///@}

  ///@{
  /**
   * Free space between neighbouring pickets along x. Default 0.08.
   */
  vtkSetClampMacro(Gap, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Gap, double);
  ///@}

  ///@{
  /**
   * Height of the pickets along y; the rails are centred at 0.25 and 0.75 of
   * it. Must be > 0. Default 1.
   */
  vtkSetClampMacro(Height, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Height, double);
  ///@}

  ///@{
  /**
   * Depth along z of a picket, and of a rail. Must be > 0. Default 0.05.
   */
  vtkSetClampMacro(Thickness, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Thickness, double);
  ///@}

  /**
   * Length of the fence along x: the pickets and the gaps between them.
   */
  double GetLength() const;

protected:
  vtkFenceSource();
  ~vtkFenceSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfPickets = 7;
  double PicketWidth = 0.1;
  double Gap = 0.08;
  double Height = 1.0;
  double Thickness = 0.05;

private:
  vtkFenceSource(const vtkFenceSource&) = delete;
  void operator=(const vtkFenceSource&) = delete;
};

#endif
