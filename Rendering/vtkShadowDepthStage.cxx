#include "vtkShadowDepthStage.h"

#include "vtkShadowMapperCode.h"

//------------------------------------------------------------------------------
void vtkShadowDepthStage::PreReplace(vtkShadowShaderSources& sources)
{
  // Clipping and depth code come before the lighting code. A shader without
  // the tag (a custom one) still draws its depth, only slower.
  vtkShadowShaderSources::Before(
    sources.Fragment, vtkShadowMapperCode::LightImpl, "gl_FragData[0] = vec4(1.0);\n  return;");
}
