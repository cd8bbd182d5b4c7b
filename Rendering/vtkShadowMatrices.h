// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkShadowMatrices.h
 * @brief  VTK's row-major vtkMatrix4x4 to and from GLM's column-major
 *         matrices: the one transpose the framework needs; and the one
 *         frame across an axis that sampling a light uses.
 */

#ifndef vtkShadowMatrices_h
#define vtkShadowMatrices_h

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <cmath>

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

/// The camera's world to view matrix (its model-view).
inline glm::dmat4 WorldToView(vtkCamera* camera)
{
  return FromVTK(camera->GetModelViewTransformMatrix());
}

/// The camera's view to world matrix.
inline glm::dmat4 ViewToWorld(vtkCamera* camera)
{
  return glm::inverse(WorldToView(camera));
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

/**
 * Unit `u`, `v` across the unit axis `w`, with (u, v, w) right-handed: u is
 * the world's x made perpendicular to w (y when w is nearly along x), v = w
 * x u. Every light sample, on the truth's cones and on the techniques'
 * discs and balls, is laid out in this frame, and aliasfree's LightScale
 * scales along it.
 */
inline void Basis(const glm::dvec3& w, glm::dvec3& u, glm::dvec3& v)
{
  const glm::dvec3 x = std::abs(w.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  u = glm::normalize(x - glm::dot(x, w) * w);
  v = glm::cross(w, u);
}
}

#endif
