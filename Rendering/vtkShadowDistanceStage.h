// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowDistanceStage
 * @brief   Point lights' cube maps: each fragment writes its squared
 *          distance to the face's eye, the light (Gerasimov, section 12.3.3);
 *          or, with LinearDepth, any frustum's linear depth.
 *
 * The distance comes from the fragment's window position and the face's
 * inverse projection, independent of the mapper's lighting varyings. With
 * Packed, it is packed into RGBA8 over the face's far distance squared
 * (section 12.2.3) for contexts without float targets. Drawn one face at a
 * time or all six layered (vtkShadowDrawer).
 *
 * With LinearDepth, a draw through a 2D frustum (vtkShadowDrawSetup::View)
 * writes the fragment's distance along the frustum's axis from its eye, in
 * world units, into a float target: the linear shadow map smoothies compare
 * depths with (their ratio, Volokh section 3.2), drawn with MIN blending.
 * Colour targets take no polygon offset: SetSlopeBias() pushes the stored
 * depth back by that many times its largest change from one texel to the
 * next, as glPolygonOffset's factor does.
 */

#ifndef vtkShadowDistanceStage_h
#define vtkShadowDistanceStage_h

#include "vtkShadowStage.h"

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowDistanceStage : public vtkShadowStage
{
public:
  /// RGBA8 packed distances rather than float ones. Default false.
  void SetPacked(bool packed) { this->Packed = packed; }
  /// Linear depth along the axis rather than squared distance. Default false.
  void SetLinearDepth(bool linear) { this->LinearDepth = linear; }
  /// Linear depth: the slope-scaled offset, in texel-to-texel changes. Default 0.
  void SetSlopeBias(double bias) { this->SlopeBias = static_cast<float>(bias); }

  void Begin(const vtkShadowDrawSetup& setup) override;
  void PreReplace(vtkShadowShaderSources& sources) override;
  void PostReplace(vtkShadowShaderSources& sources) override;
  /// Its code is the same for every draw: packing, linear depth and the face are uniforms.
  bool GetCodeKey(std::string& key) const override
  {
    key.clear();
    return true;
  }
  void SetUniforms(vtkShaderProgram* program, vtkProp* prop) override;

private:
  bool Packed = false;
  bool LinearDepth = false;
  float SlopeBias = 0.0f;
  float FaceClipToView[16];
  float FaceSize = 1.0f;
  float FaceRange = 0.0f;
};

#endif
