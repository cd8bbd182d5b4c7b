// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkRayCastLightVisibility
 * @brief   Ground truth for soft shadows: the visible fraction of a light,
 *          by ray casting, at the surface each pixel of a view sees.
 *
 * Independent of every shadow map: the visible actors' triangles, placed in
 * the world, go into Embree's ray tracer. A camera ray through each pixel's
 * centre finds the surface the renderer's active camera sees there; from
 * it, Samples shadow rays (stratified, jittered per pixel with a fixed seed)
 * towards the light give the fraction of it that is visible:
 * - spot and point lights: a sphere of the light's radius
 *   (vtkShadowLightSize::GetRadius()) around its position, sampled uniformly
 *   over the solid angle it subtends;
 * - directional lights: a cone of directions of that angular radius.
 * Rays leaving below the surface's side the camera sees are blocked by the
 * surface itself. Opaque actors cast; translucent ones only receive, as in
 * the render passes. Only polygons count: lines and vertices neither cast
 * nor receive, and points and lines drawn as spheres and tubes count as the
 * flat primitives they are.
 *
 * The output is an image of Size pixels, rows from the bottom as VTK's
 * images, with three point arrays:
 * - "Visibility" (float, the active scalars): 1 lit, 0 umbra, 0 where no
 *   surface is seen;
 * - "Geometry" (unsigned char): 1 where a surface is seen;
 * - "QualityMask" (unsigned char): 1 on the pixels quality is measured on:
 *   a surface whose geometric normal faces the light (N.L >= 0.1), inside
 *   0.9 of a spot light's cone, and whose four neighbours lie on the same
 *   actor's surface without a step in depth (silhouettes excluded).
 *
 * Needs no OpenGL context: the renderer need not be in a window. Reports
 * progress (vtkAlgorithm::UpdateProgress, ProgressEvent) in 32 bands of
 * rows.
 */

#ifndef vtkRayCastLightVisibility_h
#define vtkRayCastLightVisibility_h

#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h"           // for vtkSmartPointer
#include "vtkSoftShadowsTruthModule.h" // for export macro

class vtkRenderer;

class VTKSOFTSHADOWSTRUTH_EXPORT vtkRayCastLightVisibility : public vtkImageAlgorithm
{
public:
  static vtkRayCastLightVisibility* New();
  vtkTypeMacro(vtkRayCastLightVisibility, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The scene: the renderer's active camera, lights and visible actors. */
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer() const;
  ///@}

  ///@{
  /** Pixels of the image, and the camera's aspect ratio. Default 320 x 240. */
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);
  ///@}

  ///@{
  /**
   * The light: its index in the renderer's light collection, as
   * vtkSoftShadowPass::SetShadowOnlyLight() counts. Default 0.
   */
  vtkSetClampMacro(LightIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(LightIndex, int);
  ///@}

  ///@{
  /**
   * Shadow rays a pixel, stratified on a square grid (rounded to the
   * nearest square). A light of radius 0 takes one. Default 256.
   */
  vtkSetClampMacro(Samples, int, 1, 65536);
  vtkGetMacro(Samples, int);
  ///@}

  ///@{
  /** Seed of the per-pixel jitter. Default 1. */
  vtkSetMacro(Seed, unsigned int);
  vtkGetMacro(Seed, unsigned int);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkRayCastLightVisibility();
  ~vtkRayCastLightVisibility() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  int Size[2] = { 320, 240 };
  int LightIndex = 0;
  int Samples = 256;
  unsigned int Seed = 1;

private:
  vtkRayCastLightVisibility(const vtkRayCastLightVisibility&) = delete;
  void operator=(const vtkRayCastLightVisibility&) = delete;

  vtkSmartPointer<vtkRenderer> Renderer;
};

#endif
