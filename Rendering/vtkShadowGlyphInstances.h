// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowGlyphInstances
 * @brief   The polydata a vtkGlyph3DMapper draws: every instance of its
 *          sources, placed as the mapper places it, in one mesh.
 *
 * Part of the framework's caster registry, so that techniques that take
 * triangles (their own topology, edges or triangle tests) see glyphs as
 * VTK draws them. Each point of the mapper's input (each leaf of a
 * composite input) that its mask keeps draws the source its index array
 * picks (SourceIndexing; the sources of a source table tree too), moved to
 * the point, turned as OrientationMode reads the orientation array
 * (DIRECTION, ROTATION or QUATERNION) and scaled as ScaleMode reads the
 * scale array (clamped to Range with Clamping, times ScaleFactor), the
 * transform vtkOpenGLGlyph3DMapper gives each instance: translate, rotate,
 * scale. Polygons, strips, lines and vertices are all kept, in the
 * actor's model coordinates. Levels of detail and culling are not applied:
 * every instance casts at full resolution. Instances of more than 2^24
 * points in all make no mesh (one error naming the mapper): they cast
 * through the light's depth map only.
 */

#ifndef vtkShadowGlyphInstances_h
#define vtkShadowGlyphInstances_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkMTimeType
#include "vtkWeakPointer.h"  // for vtkWeakPointer

#include <map> // for std::map

class vtkGlyph3DMapper;
class vtkPolyData;

class vtkShadowGlyphInstances
{
public:
  /// The instances' mesh, built again only when the mapper, its input or
  /// its sources change. Null when the mapper draws nothing, or too much.
  vtkPolyData* Get(vtkGlyph3DMapper* mapper);

  /// Forget mappers gone since.
  void Prune();

  /// The instances' mesh, built now.
  static vtkSmartPointer<vtkPolyData> Build(vtkGlyph3DMapper* mapper);

  /// Whether the mapper's sources hold faces and nothing else (no lines or
  /// vertices): what it draws is faces only.
  static bool DrawsFacesOnly(vtkGlyph3DMapper* mapper);

private:
  struct Entry
  {
    vtkWeakPointer<vtkGlyph3DMapper> Mapper;
    vtkMTimeType Time = 0;
    vtkSmartPointer<vtkPolyData> Mesh;
  };
  std::map<const vtkGlyph3DMapper*, Entry> Entries;
};

#endif
