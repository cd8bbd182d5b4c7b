#include "vtkShadowDepthStage.h"

#include "vtkShadowMapperCode.h"

//------------------------------------------------------------------------------
void vtkShadowDepthStage::PreReplace(vtkShadowShaderSources& sources)
{
  // Clipping and depth code come before the lighting code.
  sources.Require(sources.Fragment, vtkShadowMapperCode::LightImpl,
    std::string("gl_FragData[0] = vec4(1.0);\n  return;\n  ") + vtkShadowMapperCode::LightImpl,
    "depth-only drawing");
}
