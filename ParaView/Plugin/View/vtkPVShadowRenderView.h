// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkPVShadowRenderView
 * @brief ParaView's render view, drawn through one of the module's shadow passes.
 *
 * The technique's pass is the render pass of the view's synchronized
 * renderers: ParaView puts its camera pass around it, and its compositing
 * after it. ShadowTechnique picks the technique and variant by the names
 * `softshadows techniques` lists (vtkShadowTechniqueCatalog); ShadowMapSize
 * is the pass's MapSize; SetShadowParameter() sets any technique's parameter,
 * kept for when that technique is chosen again, and the panel has one
 * property per parameter, with the classes' defaults.
 *
 * Light sizes are ParaView's light `Radius` property: ParaView built without
 * ray tracing drops it in vtkPVLight::SetRadius(), so the view's proxy
 * (vtkSMShadowRenderViewProxy) hands each light's value to SetLightRadius()
 * on every process before rendering.
 *
 * In a distributed render (pvbatch or pvserver on MPI ranks, each rank with
 * its piece of the data) the pass combines its light-space maps across the
 * ranks (vtkSoftShadowPass::SetController()), so that a piece on one rank
 * shadows the pieces of the others; CombineShadowMaps turns that off.
 */

#ifndef vtkPVShadowRenderView_h
#define vtkPVShadowRenderView_h

#include "vtkPVRenderView.h"
#include "vtkSmartPointer.h"          // for vtkSmartPointer
#include "vtkSoftShadowsViewModule.h" // for export macro

#include <array>  // for std::array
#include <map>    // for std::map
#include <string> // for std::string

class vtkLight;
class vtkSoftShadowPass;

class VTKSOFTSHADOWSVIEW_EXPORT vtkPVShadowRenderView : public vtkPVRenderView
{
public:
  static vtkPVShadowRenderView* New();
  vtkTypeMacro(vtkPVShadowRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The technique and variant, `name[:variant]` (`contact`,
   * `contact:multipass`). An unknown name is an error and the view keeps its
   * technique. Default `contact` (its default variant, pcf).
   */
  void SetShadowTechnique(const char* spec);
  const char* GetShadowTechnique() const { return this->ShadowTechnique.c_str(); }
  ///@}

  ///@{
  /**
   * A technique's parameter, `technique.key` as scene files spell it
   * (`contact.pass_limit`, `aliasfree.light_scale`), with one value or
   * three for vectors (booleans 0 or 1). Applied at once when that technique
   * is the view's, and whenever it becomes so; unknown names and values its
   * class refuses are errors and leave the parameter as it was.
   */
  void SetShadowParameter(const char* name, double value);
  void SetShadowParameter(const char* name, double x, double y, double z);
  ///@}

  ///@{
  /**
   * The shadow maps' size in texels (vtkSoftShadowPass::SetMapSize). Default
   * 1024, as the pass's.
   */
  void SetShadowMapSize(int size);
  vtkGetMacro(ShadowMapSize, int);
  ///@}

  ///@{
  /**
   * Whether a distributed render combines the light-space maps across the
   * ranks. Off, each rank's casters shadow only its own receivers (right
   * only when every rank holds all the casters). Default on.
   */
  vtkSetMacro(CombineShadowMaps, bool);
  vtkGetMacro(CombineShadowMaps, bool);
  ///@}

  /**
   * The size of `light`, as vtkSoftShadowPass::SetRadius(): world units for
   * positional lights, degrees of angular radius for directional ones.
   */
  void SetLightRadius(vtkLight* light, double radius);

protected:
  vtkPVShadowRenderView();
  ~vtkPVShadowRenderView() override;

  /// Combine maps across the ranks only when the ranks composite their images.
  void AboutToRenderOnLocalProcess(bool interactive) override;

private:
  vtkPVShadowRenderView(const vtkPVShadowRenderView&) = delete;
  void operator=(const vtkPVShadowRenderView&) = delete;

  void MakePass();
  bool ApplyShadowParameter(const char* name, const double values[3], int size);

  std::string ShadowTechnique = "contact";
  int Technique = 0; ///< of vtkShadowTechniqueCatalog
  int Variant = -1;  ///< the default
  int ShadowMapSize = 1024;
  bool CombineShadowMaps = true;
  vtkSmartPointer<vtkSoftShadowPass> Pass;
  /// What SetShadowParameter() was given, by `technique.key`.
  std::map<std::string, std::array<double, 3>> Parameters;
};

#endif
