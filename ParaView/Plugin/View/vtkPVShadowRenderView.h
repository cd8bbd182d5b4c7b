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

class vtkLight;
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

  int ShadowTechnique = Contact;
  int ShadowMapSize = 1024;
  bool CombineShadowMaps = true;
  vtkSmartPointer<vtkSoftShadowPass> Pass;
};

#endif
