/**
 * @class   vtkShadowDistanceStage
 * @brief   Point lights' cube maps: each fragment writes its squared
 *          distance to the face's eye, the light (Gerasimov, section 12.3.3).
 *
 * The distance comes from the fragment's window position and the face's
 * inverse projection, independent of the mapper's lighting varyings. With
 * Packed, it is packed into RGBA8 over the face's far distance squared
 * (section 12.2.3) for contexts without float targets. Drawn one face at a
 * time or all six layered (vtkShadowDrawer).
 */

#ifndef vtkShadowDistanceStage_h
#define vtkShadowDistanceStage_h

#include "vtkShadowStage.h"

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowDistanceStage : public vtkShadowStage
{
public:
  /// RGBA8 packed distances rather than float ones. Default false.
  void SetPacked(bool packed) { this->Packed = packed; }

  void Begin(const vtkShadowDrawSetup& setup) override;
  void PreReplace(vtkShadowShaderSources& sources) override;
  void SetUniforms(vtkShaderProgram* program, vtkProp* prop) override;

private:
  bool Packed = false;
  float FaceClipToView[16];
  float FaceSize = 1.0f;
  float FaceRange = 0.0f;
};

#endif
