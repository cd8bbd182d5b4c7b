// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkSMShadowRenderViewProxy
 * @brief The proxy of vtkPVShadowRenderView: ParaView's light Radius made the
 *        lights' size.
 *
 * ParaView's light proxies have a `Radius` property (the light's size, as
 * OSPRay reads it), but vtkPVLight::SetRadius() keeps it only when ParaView
 * is built with ray tracing, which Debian's is not. Before each render, this
 * proxy reads the Radius of each of the view's AdditionalLights and, where it
 * changed, hands it to vtkPVShadowRenderView::SetLightRadius() on every
 * process that has the view, so a user sets the light size where ParaView
 * already offers it (the Light Inspector, or `light.Radius` in Python).
 */

#ifndef vtkSMShadowRenderViewProxy_h
#define vtkSMShadowRenderViewProxy_h

#include "vtkSMRenderViewProxy.h"
#include "vtkSoftShadowsViewModule.h" // for export macro

#include <map> // for std::map

class VTKSOFTSHADOWSVIEW_EXPORT vtkSMShadowRenderViewProxy : public vtkSMRenderViewProxy
{
public:
  static vtkSMShadowRenderViewProxy* New();
  vtkTypeMacro(vtkSMShadowRenderViewProxy, vtkSMRenderViewProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSMShadowRenderViewProxy();
  ~vtkSMShadowRenderViewProxy() override;

  vtkTypeUInt32 PreRender(bool interactive) override;

private:
  vtkSMShadowRenderViewProxy(const vtkSMShadowRenderViewProxy&) = delete;
  void operator=(const vtkSMShadowRenderViewProxy&) = delete;

  /// The radius last handed over, by light proxy (its global id).
  std::map<vtkTypeUInt32, double> Radii;
};

#endif
