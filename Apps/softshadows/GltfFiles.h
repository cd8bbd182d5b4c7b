// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * What VTK 9.1's glTF loader (vtkGLTFDocumentLoader) trusts in a glTF file,
 * checked before vtkGLTFImporter reads it.
 *
 * The loader follows the document's indices and reads its types without
 * checking them: a document without scenes, a scene index that is a string,
 * a mesh's primitives that are not an array, nodes that are their own
 * ancestors, or a buffer file that is missing crash it, and a Draco
 * compressed mesh makes it allocate without bound. A document that passes
 * FindGltfProblem() has every collection it reads of the type it reads, every
 * index in range, a tree of nodes, and every buffer, view and accessor within
 * the bytes there are.
 */

#ifndef softshadows_GltfFiles_h
#define softshadows_GltfFiles_h

#include <filesystem>
#include <string>

namespace softshadows
{
/// Why `file` (.gltf or .glb) must not be given to vtkGLTFImporter, in one
/// sentence; empty when it may.
std::string FindGltfProblem(const std::filesystem::path& file);
}

#endif
