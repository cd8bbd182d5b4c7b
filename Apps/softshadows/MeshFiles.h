// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Mesh files read as VTK reads them, refused before they can crash anything.
 *
 * PLY files are checked with FindPlyProblem() before VTK's reader sees them
 * (it trusts what it reads); every mesh read is then checked with
 * vtkSoftShadowsMeshCheck (point ids, finite points, attribute sizes), since
 * the normals computed for it would read out of bounds otherwise.
 */

#ifndef softshadows_MeshFiles_h
#define softshadows_MeshFiles_h

#include "SceneFile.h"

#include <vtkSmartPointer.h>

#include <filesystem>

class vtkPolyData;

namespace softshadows
{
/// The mesh in `file`, with at least one polygon or strip; throws
/// std::runtime_error with one printable sentence when it cannot be read.
vtkSmartPointer<vtkPolyData> ReadMeshFile(const std::filesystem::path& file, MeshFormat format);

}

#endif
