// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkShadowMatrices.h
 * @brief  VTK's row-major vtkMatrix4x4 to and from GLM's column-major
 *         matrices: the one transpose the framework needs.
 */

#ifndef vtkShadowMatrices_h
#define vtkShadowMatrices_h

#include "vtkMatrix4x4.h"

#include <glm/mat4x4.hpp>

namespace vtkShadowMatrices
{
inline glm::dmat4 FromVTK(vtkMatrix4x4* m)
{
  glm::dmat4 result;
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      result[col][row] = m->GetElement(row, col);
    }
  }
  return result;
}

inline void ToVTK(const glm::dmat4& m, vtkMatrix4x4* result)
{
  for (int row = 0; row < 4; ++row)
  {
    for (int col = 0; col < 4; ++col)
    {
      result->SetElement(row, col, m[col][row]);
    }
  }
}
}

#endif
