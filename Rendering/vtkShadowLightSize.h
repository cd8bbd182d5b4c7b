// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowLightSize
 * @brief   The size of a light, and what kind of light casts which shadow:
 *          what every technique and the ray-cast truth read of a vtkLight.
 *
 * vtkLight has no size. As vtkOSPRayLightNode::SetRadius() does, the size is
 * stored in the light's information under RADIUS(): world units for spot and
 * point lights, the angular radius in degrees for directional lights (the
 * sun: about 0.27). 0, or no value, is a point light: hard shadows.
 *
 * vtkSoftShadowPass::SetRadius() and GetRadius() are the same functions.
 */

#ifndef vtkShadowLightSize_h
#define vtkShadowLightSize_h

#include "vtkObject.h"
#include "vtkSoftShadowsRenderingModule.h" // for export macro

class vtkInformationDoubleKey;
class vtkLight;

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowLightSize : public vtkObject
{
public:
  static vtkShadowLightSize* New();
  vtkTypeMacro(vtkShadowLightSize, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The key, and the light's radius under it. SetRadius() refuses negative
   * and NaN radii with a warning and ignores a null light; GetRadius() is 0
   * for a null light or one never given a size.
   */
  static vtkInformationDoubleKey* RADIUS();
  static void SetRadius(double radius, vtkLight* light);
  static double GetRadius(vtkLight* light);
  ///@}

  /**
   * Whether `light` shines in every direction: positional with a cone
   * half-angle of 90 degrees or more (vtkGLTFImporter gives point lights
   * 90). Such lights cast through cube maps; other positional lights are
   * spot lights.
   */
  static bool IsPointLight(vtkLight* light);

  /**
   * A light's width as its shadows see it: its diameter (spot and point
   * lights, world units), or for a `directional` light of angular radius
   * `radius` degrees, 2 tan(radius): its width per unit of distance.
   */
  static double GetWidth(double radius, bool directional);

protected:
  vtkShadowLightSize() = default;
  ~vtkShadowLightSize() override = default;

private:
  vtkShadowLightSize(const vtkShadowLightSize&) = delete;
  void operator=(const vtkShadowLightSize&) = delete;
};

#endif
