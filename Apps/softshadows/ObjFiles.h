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

#include <filesystem>
#include <string>

namespace softshadows
{
/// Why `bytes`, a whole OBJ file, must not be given to vtkOBJReader, in one
/// sentence; empty when it may (the reader may still refuse it, saying why).
std::string FindObjProblem(const std::string& bytes);

/**
 * The OBJ text `bytes` with every negative (relative) index of its
 * elements written as the absolute one it means, counted from 1. VTK 9.3.0's
 * reader resolves a face's relative texture coordinates against the count
 * of normals and the other way round (fixed upstream since), which reads
 * past its arrays; absolute indices read alike in every release.
 */
std::string AbsoluteObjIndices(const std::string& bytes);

/**
 * A file of `text` in the temporary folder, named with `suffix` (".obj",
 * ".mtl"), for VTK's readers that read only from files; removed when this
 * goes.
 */
class TemporaryFile
{
public:
  TemporaryFile(const std::string& text, const std::string& suffix);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::filesystem::path& Path() const { return this->File; }

private:
  std::filesystem::path File;
};
}

#endif
