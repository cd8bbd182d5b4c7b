// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowCameraStage
 * @brief   The camera pass: the camera depth of the opaque props, and a
 *          technique's code on every fragment the camera sees.
 *
 * Part of the framework (vtkSoftShadowPass::RenderCameraDepth() draws
 * through it): the mappers' lighting code is replaced by the technique's
 * code, which sees each fragment's surface (vtkShadowSurfaceFS.glsl) and
 * writes the draw's colour targets. Unlit fragments (no view-space position
 * in the mapper) write what the targets hold where no surface is.
 */

#ifndef vtkShadowCameraStage_h
#define vtkShadowCameraStage_h

#include "vtkShadowStage.h"

#include <array>      // for std::array
#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkRenderer;

/**
 * A technique's code in the camera pass: GLSL declarations, statements that
 * see `vtkShadowPositionWC` (vec4), `vtkShadowNormalWC` (the face's unit
 * normal, towards the camera) and `vtkShadowFaceDefined` and write every
 * target, and the uniforms they need (may be unset).
 */
struct VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowCameraPassCode
{
  std::string Declarations;
  std::string Implementation;
  std::function<void(vtkShaderProgram*)> Uniforms;
  /// What each target holds where no surface is (the background, and
  /// unlit fragments); 0 for targets past the list.
  std::vector<std::array<float, 4>> ClearColours;
};

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowCameraStage : public vtkShadowStage
{
public:
  /// The code and camera of the next draws; `code` must outlive them.
  void SetCode(const vtkShadowCameraPassCode* code, vtkRenderer* renderer)
  {
    this->Code = code;
    this->Renderer = renderer;
  }

  void Begin(const vtkShadowDrawSetup& setup) override;
  void PreReplace(vtkShadowShaderSources& sources) override;
  void PostReplace(vtkShadowShaderSources& sources) override;
  void SetUniforms(vtkShaderProgram* program, vtkProp* prop) override;
  std::string GetName() const override { return "the camera pass"; }
  bool GetCodeKey(std::string& key) const override;

private:
  std::string UnlitCode() const;

  const vtkShadowCameraPassCode* Code = nullptr;
  vtkRenderer* Renderer = nullptr;
  int Targets = 0;
};

#endif
