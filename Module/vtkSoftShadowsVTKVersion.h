// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkSoftShadowsVTKVersion.h
 * @brief  What differs between VTK releases for the mesh filters (no
 *         OpenGL): the one place they check VTK's version. The rendering
 *         side's is vtkShadowVTKVersion.h.
 *
 * - Cell storage: vtkCellArray::Visit() reads cells stored as offsets and
 *   connectivity arrays. VTK 9.6 added fixed-size storage (contour and
 *   flying-edges filters write their triangles so), which Visit() skips
 *   with a warning; VisitableCells() gives such cells in the storage Visit()
 *   reads.
 */

#ifndef vtkSoftShadowsVTKVersion_h
#define vtkSoftShadowsVTKVersion_h

#include "vtkCellArray.h"
#include "vtkSmartPointer.h"
#include "vtkVersionMacros.h" // for VTK_VERSION_NUMBER

namespace vtkSoftShadowsVTKVersion
{
/// `cells`, or where VTK stores them in a way Visit() does not read, a copy
/// in the default storage.
inline vtkSmartPointer<vtkCellArray> VisitableCells(vtkCellArray* cells)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 6, 0)
  if (cells && (cells->IsStorageFixedSize() || cells->IsStorageGeneric()))
  {
    auto copy = vtkSmartPointer<vtkCellArray>::New();
    copy->DeepCopy(cells);
    copy->ConvertToDefaultStorage();
    return copy;
  }
#endif
  return cells;
}
}

#endif
