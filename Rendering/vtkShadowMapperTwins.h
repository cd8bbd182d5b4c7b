// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowMapperTwins
 * @brief   A second mapper for each small mesh and each stage that draws it
 *          besides the receivers, so that no mapper builds its shaders twice a
 *          frame.
 *
 * Internal to the framework (vtkShadowDrawer owns it). VTK's mappers build
 * their shader sources again whenever the render passes they are drawn
 * with change: a mesh drawn into a light's map and then as a receiver did
 * so twice a frame, and with many small actors that copying, searching and
 * hashing of shader text was most of a frame (docs/benchmarks.md, "Scale").
 * A twin is a vtkOpenGLPolyDataMapper that shares the mapper's input and
 * settings (vtkPolyDataMapper::ShallowCopy(), again whenever the mapper
 * changes), draws the actor in one stage only and keeps its program from
 * frame to frame; the user's mapper keeps the receivers'. The geometry is
 * the same, the shaders the same: the maps are pixel for pixel the mapper's.
 *
 * Only plain actors (vtkOpenGLActor, no textures, no backface property) with
 * a plain vtkOpenGLPolyDataMapper, or a vtkDataSetMapper (PyVista's) of
 * polydata, get twins, and only for meshes of at most
 * GetMaximumPoints() points: their buffers are uploaded a second time, and
 * for a dense mesh the rebuild is small beside its draw. Actors with shader
 * replacements of their own draw through their mapper. Twins whose mapper
 * was not drawn for a while are dropped with their buffers.
 */

#ifndef vtkShadowMapperTwins_h
#define vtkShadowMapperTwins_h

#include "vtkSmartPointer.h" // for vtkSmartPointer
#include "vtkType.h"         // for vtkIdType, vtkMTimeType
#include "vtkWeakPointer.h"  // for vtkWeakPointer

#include <map>     // for std::map
#include <utility> // for std::pair

class vtkMapper;
class vtkOpenGLPolyDataMapper;
class vtkProp;
class vtkRenderer;
class vtkWindow;

class vtkShadowMapperTwins
{
public:
  vtkShadowMapperTwins();
  ~vtkShadowMapperTwins();

  /**
   * Draws `prop`'s opaque geometry through its twin for `stage` (any key
   * that tells the draws' stages apart) and returns true, or returns false
   * when the prop has no twin: draw it as VTK does.
   */
  bool RenderOpaqueGeometry(vtkProp* prop, vtkRenderer* renderer, const void* stage);

  /// A draw through RenderOpaqueGeometry() ended: twins long undrawn are dropped.
  void EndDraw();

  static vtkIdType GetMaximumPoints() { return 100000; }

  void ReleaseGraphicsResources(vtkWindow* w);

private:
  vtkShadowMapperTwins(const vtkShadowMapperTwins&) = delete;
  void operator=(const vtkShadowMapperTwins&) = delete;

  struct Twin
  {
    vtkWeakPointer<vtkMapper> Original;
    vtkSmartPointer<vtkOpenGLPolyDataMapper> Mapper;
    vtkMTimeType Copied = 0; ///< the original's MTime when last copied
    unsigned long LastDraw = 0;
  };
  std::map<std::pair<const vtkMapper*, const void*>, Twin> Twins;
  unsigned long Draws = 0;
};

#endif
