/**
 * @class vtkPVShadowRenderView
 * @brief ParaView's render view, drawn through one of the module's shadow passes.
 *
 * The technique's pass is the render pass of the view's synchronized
 * renderers: ParaView puts its camera pass around it, and its compositing
 * after it. ShadowTechnique picks the technique and variant (the values of
 * ShadowTechniques, the names `softshadows techniques` lists); ShadowMapSize
 * is the pass's MapSize. The other parameters keep the classes' defaults.
 *
 * Not yet: light sizes from ParaView's light `Radius` (Debian's ParaView,
 * built without ray tracing, drops it in vtkPVLight::SetRadius), and maps
 * combined across MPI ranks.
 */

#ifndef vtkPVShadowRenderView_h
#define vtkPVShadowRenderView_h

#include "vtkPVRenderView.h"
#include "vtkSmartPointer.h"          // for vtkSmartPointer
#include "vtkSoftShadowsViewModule.h" // for export macro

class vtkSoftShadowPass;

class VTKSOFTSHADOWSVIEW_EXPORT vtkPVShadowRenderView : public vtkPVRenderView
{
public:
  static vtkPVShadowRenderView* New();
  vtkTypeMacro(vtkPVShadowRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The choices of ShadowTechnique, in order.
  enum ShadowTechniques
  {
    Hard = 0,
    Reference,
    Contact, ///< contact:pcf, the class's default
    ContactGaussian,
    ContactMultiPass,
    Omni, ///< omni:poisson
    OmniPCF4,
    Silhouette, ///< silhouette:soft
    SilhouetteHard,
    Smoothies,
    AliasFree, ///< aliasfree:soft
    AliasFreeHard,
    NumberOfShadowTechniques
  };

  ///@{
  /**
   * The technique and variant, one of ShadowTechniques. Default Contact.
   */
  void SetShadowTechnique(int technique);
  vtkGetMacro(ShadowTechnique, int);
  ///@}

  ///@{
  /**
   * The shadow maps' size in texels (vtkSoftShadowPass::SetMapSize). Default
   * 1024, as the pass's.
   */
  void SetShadowMapSize(int size);
  vtkGetMacro(ShadowMapSize, int);
  ///@}

protected:
  vtkPVShadowRenderView();
  ~vtkPVShadowRenderView() override;

private:
  vtkPVShadowRenderView(const vtkPVShadowRenderView&) = delete;
  void operator=(const vtkPVShadowRenderView&) = delete;

  void MakePass();

  int ShadowTechnique = Contact;
  int ShadowMapSize = 1024;
  vtkSmartPointer<vtkSoftShadowPass> Pass;
};

#endif
