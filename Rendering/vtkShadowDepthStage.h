/**
 * @class   vtkShadowDepthStage
 * @brief   Depth only: the mappers skip all shading. Light depth maps, the
 *          camera depth and the depth pre-pass draw through it.
 */

#ifndef vtkShadowDepthStage_h
#define vtkShadowDepthStage_h

#include "vtkShadowStage.h"

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowDepthStage : public vtkShadowStage
{
public:
  void PreReplace(vtkShadowShaderSources& sources) override;
};

#endif
