// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowDepthStage
 * @brief   Depth only: the mappers skip all shading. Light depth maps and the
 *          depth pre-pass draw through it.
 *
 * Points drawn as spheres and lines as tubes are sprites whose depth VTK
 * bends into a sphere or tube a few pixels wide, pixels of whichever view
 * draws them: from the light they are another size than from the camera,
 * and they would shadow themselves. In light space (LightSpace, the default)
 * they write their primitive's own depth: they shadow others from their
 * points and lines, receive others' shadows, and their own terminator comes
 * from their shading, as in plain VTK.
 */

#ifndef vtkShadowDepthStage_h
#define vtkShadowDepthStage_h

#include "vtkShadowStage.h"

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowDepthStage : public vtkShadowStage
{
public:
  /// Light-space draws flatten sprites' depth (see above). Default true.
  void SetLightSpace(bool lightSpace) { this->LightSpace = lightSpace; }
  std::string GetName() const override
  {
    return this->LightSpace ? "a shadow map" : "the depth pre-pass";
  }

  void PreReplace(vtkShadowShaderSources& sources) override;
  void PostReplace(vtkShadowShaderSources& sources) override;
  bool GetCodeKey(std::string& key) const override
  {
    key = this->LightSpace ? "light" : "camera";
    return true;
  }

private:
  bool LightSpace = true;
};

#endif
