// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * What VTK 9.1's vtkXMLPolyDataReader trusts in a VTP file, checked as it reads.
 *
 * The reader allocates every array for the counts its pieces claim (points,
 * cells, components) before it reads a value, and the connectivity for the
 * last offset it reads: a few changed digits have it allocate exabytes and
 * throw std::bad_alloc through VTK's pipeline. The reader made here refuses,
 * with one VTK error and nothing allocated, counts the file cannot hold:
 * every value takes at least a character of ASCII (the format when none is
 * given) or a byte of binary data (a bit array's value an eighth), and
 * compressed data expands at most 8192 times (deflate at most 1032:1, LZ4
 * 255:1, VTK's LZMA about 7000:1). Each piece's arrays must fit, and so must
 * the output's, which the reader sizes from the first piece's arrays for
 * the points and cells of every piece. Not checked: the block counts and
 * sizes in compressed arrays' headers, which VTK's parser allocates for
 * (ReadMeshFile() turns a failed allocation into its error).
 */

#ifndef softshadows_VtpFiles_h
#define softshadows_VtpFiles_h

#include <vtkAlgorithm.h>
#include <vtkSmartPointer.h>

#include <filesystem>

namespace softshadows
{
/// A vtkXMLPolyDataReader of `file` that fails with one error instead of
/// allocating more than the file can hold.
vtkSmartPointer<vtkAlgorithm> MakeVtpReader(const std::filesystem::path& file);
}

#endif
