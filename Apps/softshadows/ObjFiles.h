// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * What VTK 9.1's vtkOBJReader trusts in an OBJ file, checked before it reads.
 *
 * The reader copies a material name into a 100-byte buffer, looks up a
 * face's texture coordinates as it reads the face, and, when a face's
 * texture coordinates or normals are numbered differently from its
 * vertices, copies every face's vertices, texture coordinates and normals
 * by index, all without a bound. A file that passes FindObjProblem() is one
 * the reader reads without indexing past what it has; the vertex ids it
 * leaves in its output are checked after it, as every mesh's are
 * (vtkSoftShadowsMeshCheck).
 */

#ifndef softshadows_ObjFiles_h
#define softshadows_ObjFiles_h

#include <string>

namespace softshadows
{
/// Why `bytes`, a whole OBJ file, must not be given to vtkOBJReader, in one
/// sentence; empty when it may (the reader may still refuse it, saying why).
std::string FindObjProblem(const std::string& bytes);
}

#endif
