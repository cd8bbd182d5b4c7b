// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSoftShadowsMeshCheck
 * @brief   Finds what in a vtkPolyData would make filters read out of bounds.
 *
 * VTK's filters trust their input: a cell that names a point the mesh does
 * not have, offsets that run past the connectivity, or attribute arrays
 * shorter than the points they describe make them read past the end of an
 * array (vtkPolyDataNormals crashes in vtkCellLinks::BuildLinks). Meshes
 * reach this module from files and from users' pipelines, so the module's
 * filters, its render passes and the softshadows program check each mesh
 * once, where it enters, with FindProblem(), and refuse it with the message.
 *
 * Checked: a mesh with cells has points; every point is finite; each of the
 * four cell arrays has offsets that start at 0, never decrease and end at
 * the connectivity's size; every point id is in [0, number of points); point
 * data arrays have a tuple for every point and cell data arrays one for every
 * cell. Optionally, cells have as many points as VTK's cell map (vtkPolyData::
 * BuildCells()) requires, at least 1, 2, 3 and 3 for vertices, lines,
 * polygons and strips: filters that build links (vtkPolyDataNormals) crash on
 * a mesh it refuses. The module's filters and render passes do not ask for
 * it: they drop such cells as degenerate faces. Faces that repeat a point id
 * are valid VTK and left to the filters. The work is linear in the mesh's
 * size and runs in parallel (vtkSMPTools).
 */

#ifndef vtkSoftShadowsMeshCheck_h
#define vtkSoftShadowsMeshCheck_h

#include "vtkObject.h"
#include "vtkSoftShadowsFiltersModule.h" // for export macro

#include <string> // for std::string

class vtkPolyData;

class VTKSOFTSHADOWSFILTERS_EXPORT vtkSoftShadowsMeshCheck : public vtkObject
{
public:
  static vtkSoftShadowsMeshCheck* New();
  vtkTypeMacro(vtkSoftShadowsMeshCheck, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The first problem found in `mesh`, as one sentence naming the cell or
   * point and the numbers involved; empty when the mesh is safe to filter
   * and draw. A null mesh is a problem. With `cellSizes`, cells with fewer
   * points than VTK's cell map takes are problems too.
   */
  static std::string FindProblem(vtkPolyData* mesh, bool cellSizes = false);

protected:
  vtkSoftShadowsMeshCheck() = default;
  ~vtkSoftShadowsMeshCheck() override = default;

private:
  vtkSoftShadowsMeshCheck(const vtkSoftShadowsMeshCheck&) = delete;
  void operator=(const vtkSoftShadowsMeshCheck&) = delete;
};

#endif
