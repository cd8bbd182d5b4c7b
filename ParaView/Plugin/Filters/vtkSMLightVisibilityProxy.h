// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkSMLightVisibilityProxy
 * @brief The proxy of vtkPVLightVisibilityFilter: the Radius of each of its
 *        ParaView lights made the light's size.
 *
 * As vtkSMShadowRenderViewProxy does for the view (ParaView without ray
 * tracing drops a light's Radius on the server): when its Lights are set,
 * and on every change to one of them, this proxy hands the light's Radius
 * to vtkPVLightVisibilityFilter::SetLightRadius(), so that a resized light
 * casts again. It watches each light's ModifiedEvent, which every change
 * fires (ParaView marks consumers dirty only on the first change between
 * updates).
 */

#ifndef vtkSMLightVisibilityProxy_h
#define vtkSMLightVisibilityProxy_h

#include "vtkSMSourceProxy.h"
#include "vtkSoftShadowsParaViewFiltersModule.h" // for export macro
#include "vtkWeakPointer.h"                      // for vtkWeakPointer

#include <utility> // for std::pair
#include <vector>  // for std::vector

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

private:
  vtkSMLightVisibilityProxy(const vtkSMLightVisibilityProxy&) = delete;
  void operator=(const vtkSMLightVisibilityProxy&) = delete;

  // Watches the lights the Lights property holds now, handing each one's
  // Radius over.
  void WatchLights();
  void StopWatching();
  void LightModified(vtkObject* light, unsigned long event, void* data);
  // Hands `light`'s Radius to the filter on every process that has it.
  void HandOverRadius(vtkSMProxy* light);

  /// The lights watched, and their observers' tags.
  std::vector<std::pair<vtkWeakPointer<vtkSMProxy>, unsigned long>> Watched;
};

#endif
