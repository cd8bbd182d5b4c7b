// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * The built-in geometry a scene's actors can use (`"source": "sphere"`), each
 * with its parameters (`"params": {"radius": 0.5}`).
 *
 * Every source stands upright in VTK's y-up world: the plane is the ground
 * (y = 0, normal +y), cylinders, cones and the torus have their axis along y,
 * the fence stands on y = 0. Sizes are in world units.
 */

#ifndef softshadows_Sources_h
#define softshadows_Sources_h

#include "JsonValues.h"

#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

class vtkPolyData;

namespace softshadows
{
struct SourceParameter
{
  std::string Key;
  ValueType Type;
  Range Allowed;
  Json Default;
  std::string Meaning;
};

struct Source
{
  std::string Name;
  std::string Summary;
  std::vector<SourceParameter> Parameters;
  /// Makes the mesh from a complete parameter object (see CompleteParameters).
  std::function<vtkSmartPointer<vtkPolyData>(const Json& parameters)> Create;
};

const std::vector<Source>& Sources();

/// Throws InputError at `path` when no source is called `name`.
const Source& FindSource(const std::string& name, const std::string& path);

/**
 * Checks a scene's `params` object ({} when absent) and returns it with
 * every parameter it leaves out set to its default.
 */
Json CompleteParameters(const Source& source, const Json& parameters, const std::string& path);
}

#endif
