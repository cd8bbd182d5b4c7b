// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * What VTK 9.1's vtkPLYReader trusts in a PLY file, checked before it reads.
 *
 * The reader indexes the words of an ASCII line without counting them, reads
 * list counts into a byte and point ids without a bound, reads "face" before
 * it knows the points when the file says so, and on a short or truncated file
 * frees a face's ids twice. A file that passes
 * FindPlyProblem() is one the reader walks from start to end without reading
 * past what it has: the header's grammar, the order and kinds of the elements
 * and properties it reads by name, and every vertex and face in the body.
 */

#ifndef softshadows_PlyFiles_h
#define softshadows_PlyFiles_h

#include <string>

namespace softshadows
{
/// Why `bytes`, a whole PLY file, must not be given to vtkPLYReader, in one
/// sentence; empty when it may.
std::string FindPlyProblem(const std::string& bytes);
}

#endif
