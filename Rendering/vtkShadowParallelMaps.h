// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowParallelMaps
 * @brief   Light-space maps combined across the processes of a parallel
 *          render, so that a caster on one process shadows receivers on
 *          every other.
 *
 * Part of the framework. In sort-last parallel rendering (ParaView's pvbatch
 * and pvserver under MPI) each process draws only its piece of the data, so
 * each process's shadow maps hold only its own casters. As VTK's
 * vtkCompositeZPass does for its shadow baker, the maps are reduced across
 * the processes, nearest wins, before any receiver reads them: every
 * process then shades with the maps of the whole data, and the image
 * compositing after the pass does the rest.
 *
 * Every method here is collective: each process of the controller must make
 * the same calls in the same order, which holds when they draw the same
 * lights with the same technique: lights and camera are the same on every
 * process, CombineBounds() makes the frusta the same and CombineMinimum()
 * the lights chosen. A process whose light-space draw fails (an OpenGL
 * error the others do not have) leaves the others waiting in a reduction.
 */
#ifndef vtkShadowParallelMaps_h
#define vtkShadowParallelMaps_h

#include "vtkSmartPointer.h"
#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <vector> // for std::vector

class vtkMultiProcessController;
class vtkTextureObject;

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowParallelMaps
{
public:
  vtkShadowParallelMaps();
  ~vtkShadowParallelMaps();

  /// The processes to combine across; null (the default) or one process: none.
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController() const;

  /// Whether the maps are combined: a controller of more than one process.
  bool IsParallel() const;

  /**
   * Replace this process's scene `bounds` (VTK's order; uninitialized when
   * it shows nothing) by the bounds of every process's, so that every
   * process fits the same light frusta. `finite`: whether this process's
   * bounds are. Returns false, on every process, when any process's bounds
   * are not finite (`bounds` are then left as they were).
   */
  bool CombineBounds(double bounds[6], bool finite);

  /**
   * The least of every process's `value`: e.g. the texture units left for
   * shadows, which a process's own receivers can lower, so that every
   * process shadows the same lights.
   */
  int CombineMinimum(int value);

  /// Reduce a depth texture (a spot or directional light's map): the nearest depth wins.
  void CombineDepth(vtkTextureObject* map);

  /**
   * Reduce a cube map of squared distances (a point light's): the nearest
   * wins, for float maps and for maps packed into RGBA8, whose bytes, most
   * significant first, compare as the distances do.
   */
  void CombineCube(vtkTextureObject* cube);

private:
  vtkSmartPointer<vtkMultiProcessController> Controller;
  std::vector<float> Floats, ReducedFloats;
  std::vector<unsigned int> Words, ReducedWords;
  std::vector<unsigned char> Bytes8;
};

#endif
