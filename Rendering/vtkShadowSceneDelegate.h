// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowSceneDelegate
 * @brief   Draws the scene, receivers and all, through the pass's delegate,
 *          as VTK's renderer would draw it without a pass.
 *
 * Part of the framework (vtkSoftShadowPass's step 4). It holds VTK's render
 * steps, the default delegate, and gives them the translucent pass the
 * renderer asks for each frame: order independent, or depth peeling with its
 * peel count, occlusion ratio and volumes (as
 * vtkOpenGLRenderer::DeviceRenderTranslucentPolygonalGeometry() does). A
 * step to run before the opaque geometry (a depth-only pre-pass) is slotted
 * into the render steps' opaque pass for the one frame, after their camera
 * pass cleared.
 */

#ifndef vtkShadowSceneDelegate_h
#define vtkShadowSceneDelegate_h

#include "vtkNew.h"                        // for vtkNew
#include "vtkSmartPointer.h"               // for vtkSmartPointer
#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <functional> // for std::function

class vtkDualDepthPeelingPass;
class vtkOrderIndependentTranslucentPass;
class vtkRenderPass;
class vtkRenderState;
class vtkRenderStepsPass;
class vtkTranslucentPass;
class vtkVolumetricPass;
class vtkWindow;

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowSceneDelegate
{
public:
  vtkShadowSceneDelegate();
  ~vtkShadowSceneDelegate();
  vtkShadowSceneDelegate(const vtkShadowSceneDelegate&) = delete;
  vtkShadowSceneDelegate& operator=(const vtkShadowSceneDelegate&) = delete;

  /// VTK's render steps with the renderer's translucency: the default delegate.
  vtkRenderStepsPass* GetDefaultSteps() const;

  /**
   * Draw the scene through `delegate`, running `beforeOpaque` (if set)
   * before its opaque geometry when it is a vtkRenderStepsPass. Returns the
   * number of props it rendered.
   */
  int Render(const vtkRenderState* s, vtkRenderPass* delegate,
    const std::function<void(const vtkRenderState*)>& beforeOpaque = nullptr);

private:
  void ChooseTranslucency(const vtkRenderState* s);

  vtkSmartPointer<vtkRenderStepsPass> DefaultSteps;
  vtkNew<vtkTranslucentPass> Translucent;
  vtkNew<vtkOrderIndependentTranslucentPass> OrderIndependent;
  vtkNew<vtkDualDepthPeelingPass> DepthPeeling;
  vtkNew<vtkVolumetricPass> Volumetric;
};

#endif
