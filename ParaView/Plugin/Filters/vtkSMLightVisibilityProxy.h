// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkSMLightVisibilityProxy
 * @brief The proxy of vtkPVLightVisibilityFilter: the Radius of each of its
 *        ParaView lights made the light's size.
 *
 * As vtkSMShadowRenderViewProxy does for the view (ParaView without ray
 * tracing drops a light's Radius on the server): when its Lights are set
 * and whenever one of them changes, this proxy hands each light's Radius to
 * vtkPVLightVisibilityFilter::SetLightRadius(), so that a resized light
 * casts again.
 */

#ifndef vtkSMLightVisibilityProxy_h
#define vtkSMLightVisibilityProxy_h

#include "vtkSMSourceProxy.h"
#include "vtkSoftShadowsParaViewFiltersModule.h" // for export macro

class VTKSOFTSHADOWSPARAVIEWFILTERS_EXPORT vtkSMLightVisibilityProxy : public vtkSMSourceProxy
{
public:
  static vtkSMLightVisibilityProxy* New();
  vtkTypeMacro(vtkSMLightVisibilityProxy, vtkSMSourceProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void UpdateVTKObjects() override;

protected:
  vtkSMLightVisibilityProxy();
  ~vtkSMLightVisibilityProxy() override;

  void MarkDirtyFromProducer(
    vtkSMProxy* modifiedProxy, vtkSMProxy* producer, vtkSMProperty* property) override;

private:
  vtkSMLightVisibilityProxy(const vtkSMLightVisibilityProxy&) = delete;
  void operator=(const vtkSMLightVisibilityProxy&) = delete;

  // Hands `light`'s Radius to the filter on every process that has it.
  void HandOverRadius(vtkSMProxy* light);
};

#endif
