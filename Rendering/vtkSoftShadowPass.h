// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSoftShadowPass
 * @brief   Base of every shadow technique: renders a scene with each shadowed
 *          light's visibility injected into the actors' shaders.
 *
 * Set a subclass on a renderer with vtkRenderer::SetPass(). Every frame,
 * Render() runs the same steps for every technique:
 *
 *  1. decide which lights cast shadows and fit their light-space frusta
 *     (spot: perspective; directional: orthographic around the scene; point:
 *     six cube faces) in this->Maps, and collect this frame's casters in
 *     this->Casters,
 *  2. RenderShadowMaps(): the technique draws its light-space maps, through
 *     this->Drawer (Draw(), RenderLightDepthMaps()),
 *  3. RenderScreenSpace(): optional screen-space passes over the camera depth
 *     (RenderCameraDepth(), which can run technique code on every fragment)
 *     into this->Screen,
 *  4. the scene is drawn through the DelegatePass (opaque, translucent,
 *     volumes, overlay) while the receiver stage, reached by every
 *     vtkOpenGLPolyDataMapper's shader hooks, injects `vtkShadowFactorN`
 *     (GetReceiverCode()) and scales light N's diffuse and specular
 *     (Phong) or radiance (PBR) with it.
 *
 * docs/architecture.md walks through writing a technique.
 *
 * A light casts shadows when it is switched on and is not a headlight: spot
 * lights (cone angle < 90) and directional lights through 2D maps, point
 * lights (positional, cone angle >= 90) through cube maps of squared
 * distances, for the techniques that support them (Traits::PointLights);
 * the others report point lights once with an error and draw them unshadowed.
 *
 * The light's size comes from SetRadius()/GetRadius() (vtkShadowLightSize),
 * stored in the light's information like vtkOSPRayLightNode does: world units
 * for spot and point lights, angular radius in degrees for directional
 * lights. 0 is a point light. vtkLight::GetShadowAttenuation() is honoured as in vtkShadowMapPass.
 *
 * A receiver's shader has a limited number of texture units
 * (GL_MAX_TEXTURE_IMAGE_UNITS, and GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS over
 * all its stages), and every shadowed light takes some: its map, its
 * screen-space texture for screen-space techniques, and the technique's own
 * (Traits::ReceiverTexturesPerLight). When the lights would need more than the
 * context has, less ReservedTextureUnits for VTK's own textures, the
 * brightest lights, then those nearest the camera's focal point, are
 * shadowed (vtkShadowMapManager::Update()), the others light the scene
 * unshadowed, and one warning says how many, again only when that number
 * changes.
 *
 * ShadowOnlyLight >= 0 replaces each fragment's colour with the raw visibility
 * of that light (index in the renderer's light collection): 1 lit, 0 umbra.
 * It is what quality is measured on.
 */

#ifndef vtkSoftShadowPass_h
#define vtkSoftShadowPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkShadowCameraStage.h"          // for vtkShadowCameraPassCode
#include "vtkShadowGPUTimer.h"             // for vtkShadowGPUTimer
#include "vtkShadowReceiverStage.h"        // for vtkShadowReceiverCode
#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <array>      // for std::array
#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkInformationDoubleKey;
class vtkLight;
class vtkMultiProcessController;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkShadowShaderSources;
class vtkRenderer;
class vtkShadowCasterRegistry;
class vtkShadowDepthStage;
class vtkShadowDistanceStage;
class vtkShadowDrawer;
class vtkShadowMapManager;
class vtkShadowParallelMaps;
class vtkShadowSceneDelegate;
class vtkShadowScreenBuffers;
struct vtkShadowDrawSetup;
struct vtkShadowFrustum;
class vtkTextureObject;

class VTKSOFTSHADOWSRENDERING_EXPORT vtkSoftShadowPass : public vtkOpenGLRenderPass
{
public:
  vtkTypeMacro(vtkSoftShadowPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Size of a light, read by every technique. World units for spot and point
   * lights; angular radius in degrees for directional lights. Default 0.
   * The same functions as vtkShadowLightSize's.
   */
  static vtkInformationDoubleKey* RADIUS();
  static void SetRadius(double radius, vtkLight* light);
  static double GetRadius(vtkLight* light);
  ///@}

  ///@{
  /**
   * Width and height of each light's square shadow map in texels.
   * Default 1024.
   */
  vtkSetClampMacro(MapSize, int, 16, 16384);
  vtkGetMacro(MapSize, int);
  ///@}

  ///@{
  /**
   * Slope-scaled and constant depth offsets applied while drawing shadow maps
   * (glPolygonOffset factor and units). The slope term is multiplied by
   * (1 + PCF radius): wider kernels compare farther from the looked-up point.
   * Defaults 2.0 and 4.0.
   */
  vtkSetMacro(SlopeScaledBias, double);
  vtkGetMacro(SlopeScaledBias, double);
  vtkSetMacro(ConstantBias, double);
  vtkGetMacro(ConstantBias, double);
  ///@}

  ///@{
  /**
   * Receiver-side offset, in shadow-map texels: the point looked up in a
   * map moves towards the light along its own ray until it lies this far in
   * front of its surface's plane (as far as a normal offset of this many
   * texels puts it, without the normal offset's sideways shift of shadow
   * edges; vtkShadowNormalOffsetFS.glsl). Default 1.0.
   */
  vtkSetClampMacro(NormalBias, double, 0.0, 16.0);
  vtkGetMacro(NormalBias, double);
  ///@}

  ///@{
  /**
   * Multiplicative bias on squared distances in point lights' cube maps
   * (Gerasimov, section 12.3.7): a point is lit when its squared distance
   * times this factor is at most the stored one. Default 0.99.
   */
  vtkSetClampMacro(DistanceBias, double, 0.5, 1.0);
  vtkGetMacro(DistanceBias, double);
  ///@}

  ///@{
  /**
   * Draw the six faces of a point light's cube map in one pass (layered
   * rendering, a geometry shader sending each triangle to every face) rather
   * than in six passes, one per face, as the paper does. Default on.
   */
  vtkSetMacro(SinglePassCubeMaps, bool);
  vtkGetMacro(SinglePassCubeMaps, bool);
  vtkBooleanMacro(SinglePassCubeMaps, bool);
  ///@}

  ///@{
  /**
   * Store point lights' squared distances packed into RGBA8 cube maps (the
   * paper's integer variant, section 12.2.3, for contexts without float
   * render targets) instead of single-channel float ones. Default off.
   */
  vtkSetMacro(PackedCubeMaps, bool);
  vtkGetMacro(PackedCubeMaps, bool);
  vtkBooleanMacro(PackedCubeMaps, bool);
  ///@}

  ///@{
  /**
   * Draw the opaque props' depth before shading them (Gerasimov's depth-only
   * pre-pass), so that shadow lookups run only for visible fragments. Needs
   * the default delegate (a vtkRenderStepsPass). Default off; on for
   * vtkOmnidirectionalShadowPass.
   */
  vtkSetMacro(DepthPrePass, bool);
  vtkGetMacro(DepthPrePass, bool);
  vtkBooleanMacro(DepthPrePass, bool);
  ///@}

  ///@{
  /**
   * When >= 0, draw the visibility of this light (index in the renderer's
   * light collection) instead of the shaded colour. Default -1 (off).
   */
  vtkSetMacro(ShadowOnlyLight, int);
  vtkGetMacro(ShadowOnlyLight, int);
  ///@}

  ///@{
  /**
   * The pass that draws the scene once the shadow term is in place.
   * Default: camera, lights, opaque, translucent, volumes and overlay
   * (a vtkRenderStepsPass), translucency drawn as VTK's renderer draws it
   * without a pass: order independent (vtkOrderIndependentTranslucentPass),
   * or with dual depth peeling when the renderer's UseDepthPeeling is on
   * (its MaximumNumberOfPeels, OcclusionRatio and UseDepthPeelingForVolumes
   * honoured).
   */
  void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  ///@}

  ///@{
  /**
   * Texture units of a receiver's shader left to VTK's own textures (an
   * actor's texture, scalar colours, PBR's material and environment maps,
   * depth peeling's buffers) when deciding how many lights can be shadowed;
   * a receiver whose shader declares more textures of its own raises it for
   * the frames after. Default 4.
   */
  vtkSetClampMacro(ReservedTextureUnits, int, 0, 64);
  vtkGetMacro(ReservedTextureUnits, int);
  ///@}

  ///@{
  /**
   * The processes of a sort-last parallel render (e.g. ParaView's pvbatch
   * under MPI), each drawing its piece of the data. With more than one, the
   * light frusta are fitted to every process's bounds and the light-space
   * depth and distance maps are reduced across the processes, nearest wins,
   * before receivers read them (vtkShadowParallelMaps), so that a caster on
   * one process shadows receivers on every other. Every process must then
   * render every frame, with the same lights and technique. Techniques whose
   * own light-space data is not combined yet say so once
   * (Traits::UncombinedLightSpaceData). Default none: each process shadows
   * with what it draws.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController() const;
  ///@}

  /**
   * Number of lights that cast a shadow in the last frame.
   */
  int GetNumberOfShadowedLights() const;

  /**
   * Number of lights drawn without shadows in the last frame because the
   * receivers' texture units had no room for them.
   */
  int GetNumberOfUnshadowedLights() const;

  /**
   * How many lights of one kind (point lights, or spot and directional
   * lights) the technique could shadow at once in the last frame's context:
   * the texture units for shadows over those one light takes. 0 before the
   * first frame.
   */
  int GetMaximumNumberOfShadowedLights(bool pointLights) const;

  /**
   * Whether the technique's receivers read screen-space buffers of the
   * viewport's size (Traits::ScreenSpace: contact, reference, aliasfree):
   * passes that draw the scene larger than the viewport, or away from its
   * corner, cannot wrap such a technique.
   */
  bool GetUsesScreenSpace() const { return this->GetTraits().ScreenSpace; }

  ///@{
  /**
   * GPU time in milliseconds of each step of the last frame whose timer
   * queries had completed when it ended (so usually the frame before): the
   * light-space maps (step 2, the technique's own light-space passes
   * included), the screen-space passes (step 3; 0 for techniques without),
   * and the scene drawn with the shadow term (step 4). Measured for every
   * technique alike by timer queries, which do not stall the frame; 0 where
   * the context has none, and before the second frame.
   */
  double GetLightSpaceTime() const { return this->LightSpaceTimer.GetMilliseconds(); }
  double GetScreenSpaceTime() const { return this->ScreenSpaceTimer.GetMilliseconds(); }
  double GetReceiversTime() const { return this->ReceiversTimer.GetMilliseconds(); }
  ///@}

  ///@{
  /**
   * The technique's own work beside those steps, in milliseconds, for
   * techniques that time it (negative for the others): on the CPU in the
   * last frame (smoothies: its silhouette searches and edge lists), and on
   * the GPU as the steps are (silhouette: its pass 2).
   */
  double GetTechniqueCPUTime() const { return this->TechniqueCPUTime; }
  double GetTechniqueGPUTime() const
  {
    return this->TechniqueTimer.IsUsed() ? this->TechniqueTimer.GetMilliseconds() : -1.0;
  }
  ///@}

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkSoftShadowPass();
  ~vtkSoftShadowPass() override;

  /**
   * Step 2: draw the light-space maps of every shadowed light
   * (this->Maps). Return false on failure: the frame is then drawn unshadowed.
   */
  virtual bool RenderShadowMaps(const vtkRenderState* s) = 0;

  /**
   * Helper for RenderShadowMaps(): draw every shadowed light's own depth map
   * at MapSize, filtered bilinearly by the hardware when `linear`, or, for
   * point lights, its cube map of squared distances.
   */
  bool RenderLightDepthMaps(const vtkRenderState* s, bool linear);

  ///@{
  /**
   * The framework's light-space draws, for techniques that draw more maps
   * than the light's own (e.g. from points sampled over it): the casters'
   * depth through `frustum` into `target` with the slope-scaled and constant
   * biases; the casters' squared distances into the six faces of `cube`
   * (layered when SinglePassCubeMaps). With `beyondFaces`, only the
   * casters that draw more than faces (lines, points, imposters:
   * vtkShadowCasterRegistry::GetDepthMapProps()).
   */
  /// Whether `value` holds on any process (this one's when not parallel):
  /// decisions to draw maps that are combined must be the same on all.
  bool OnAnyProcess(bool value);

  bool RenderDepthMap(const vtkRenderState* s, const vtkShadowFrustum& frustum,
    vtkTextureObject* target, bool beyondFaces = false);
  bool RenderDistanceCube(const vtkRenderState* s, const std::array<vtkShadowFrustum, 6>& faces,
    vtkTextureObject* cube, bool beyondFaces = false);
  ///@}

  /**
   * Draw as `setup` says (vtkShadowDrawer): any frustum, target, blending
   * and stage, with the scene's props and the technique's own geometry.
   */
  bool Draw(const vtkRenderState* s, const vtkShadowDrawSetup& setup);

  /// What the framework needs to know of a technique, asked once a frame
  /// (GetTraits()): what it shadows and draws, and what it needs of the
  /// context and of the receivers' shaders.
  struct Traits
  {
    /// Shadows point lights (cube maps); else they are reported once with an
    /// error and light the scene unshadowed.
    bool PointLights = false;
    /// Takes the casters' polydata (its own topology, edges or triangles):
    /// the registry then builds glyph instances' meshes.
    bool CasterGeometry = false;
    /// Needs OpenGL 4.3 compute (vtkShadowCompute); without it one clear
    /// error, and frames are drawn without the technique's shadows.
    bool Compute = false;
    /// Needs sampler objects (OpenGL 3.3 or ARB_sampler_objects) to read
    /// depths of the light's maps raw; the same when missing.
    bool Samplers = false;
    /// Reads point lights' cube maps as floats: with PackedCubeMaps on, one
    /// warning, and the maps are drawn as floats all the same.
    bool FloatCubeMaps = false;
    /// Step 3: RenderScreenSpace() writes, for each light, a visibility
    /// texture (vtkShadowScreenBuffers::BeginVisibility()) or the receivers'
    /// codes directly (vtkShadowScreenBuffers::GetPacked()) in this->Screen.
    bool ScreenSpace = false;
    /// Screen-space passes run on buffers this many times smaller than the
    /// viewport on each axis; receivers upsample the result, following
    /// surfaces, and keep their own full-resolution hard shadow where the
    /// screen-space pass left a pixel alone.
    int ScreenResolutionDivisor = 1;
    /// Texture units the receivers read for one shadowed light besides the
    /// framework's own (the light's map, and with ScreenSpace its
    /// screen-space texture), and per frame besides those of any light:
    /// what limits how many lights can be shadowed.
    int ReceiverTexturesPerLight = 0;
    int ReceiverTexturesPerFrame = 0;
    /// GLSL extensions the receiver code needs in the mappers' GLSL 1.50
    /// fragment shaders (e.g. "GL_ARB_texture_gather").
    std::vector<std::string> ReceiverExtensions;
    /// What of the technique's own light-space data (beyond the framework's
    /// depth and distance maps, which are combined) a parallel render does
    /// not combine across processes yet, e.g. "silhouette distance maps";
    /// null when everything is combined.
    const char* UncombinedLightSpaceData = nullptr;
  };

  /**
   * The technique's traits with its current settings. Default: all off,
   * which is what a technique drawing only 2D light-space maps is.
   */
  virtual Traits GetTraits() const { return {}; }

  /**
   * Step 3, optional: screen-space passes, for techniques whose traits say
   * ScreenSpace. Default: nothing.
   */
  virtual bool RenderScreenSpace(const vtkRenderState*) { return true; }
  /**
   * Helper for RenderScreenSpace(): the technique's full-screen pass `name`
   * (vtkShadowScreenBuffers::GetQuad()), built from `source()` on first use
   * and again when `variant` (what the source depends on) changes;
   * `tiled` for a pass drawn by tiles (vtkShadowScreenBuffers::DrawTiles()).
   * nullptr when it does not build, reported once; the pass then draws
   * without shadows.
   */
  vtkOpenGLQuadHelper* GetScreenQuad(const std::string& name,
    const std::function<std::string()>& source, const std::string& variant = std::string(),
    bool tiled = false);

  /// A technique's code in the camera pass (vtkShadowCameraStage.h).
  using CameraPassCode = vtkShadowCameraPassCode;

  /**
   * Helper for RenderScreenSpace(): draw the camera depth of the opaque props
   * into this->Screen. With `targets` (textures of this->Screen's size), each
   * fragment the camera sees also runs `code`, which writes
   * gl_FragData[0 .. targets - 1]: per-pixel work done with the geometry's
   * own position and normal instead of a full-screen pass rebuilding them
   * from depth. Targets are cleared to `code.ClearColours` (default 0)
   * first; unlit fragments (no view-space position in the mapper) write
   * them too.
   */
  bool RenderCameraDepth(const vtkRenderState* s,
    const std::vector<vtkTextureObject*>& targets = {}, const CameraPassCode& code = {});

  ///@{
  /// What a technique adds to the receivers (vtkShadowReceiverStage.h).
  using ReceiverTexture = vtkShadowReceiverTexture;
  using ReceiverCode = vtkShadowReceiverCode;
  using ReceiverShading = vtkShadowReceiverShading;
  ///@}

  /// The technique's receiver code, asked once a frame before receivers
  /// draw. Default: none, each light's GetDefaultVisibility().
  virtual ReceiverCode GetReceiverCode() { return {}; }

  /**
   * The framework's visibility expression for shadowed light `slot`: the
   * hard lookup in the light's depth map with GetPCFRadius(), or, for
   * ScreenSpace traits, the light's screen-space visibility texture,
   * upsampled, where it holds a value for the fragment's surface, and that
   * hard lookup elsewhere.
   */
  std::string GetDefaultVisibility(int slot) const;

  /// GLSL expression for the framework's hard lookup of shadowed light
  /// `slot` in its own map: a depth map's or a cube map's with GetPCFRadius().
  std::string GetHardVisibility(int slot) const;

  /**
   * GLSL expression for the framework's hard lookup of shadowed light
   * `slot` (with GetPCFRadius() and the receiver offset) in `map`, a
   * sampler the receivers declare that is laid out as the light's own map:
   * a depth texture with comparison, or for point lights a cube of squared
   * distances.
   */
  std::string GetHardLookupExpression(int slot, const std::string& map) const;

  /**
   * The framework's light-space lookups in GLSL, for a technique's own
   * shaders: the receiver offset (vtkShadowNormalOffsetFS.glsl) and the cube
   * maps of squared distances (vtkShadowCubeLookupFS.glsl).
   */
  static std::string GetLightSpaceLookupCode();

  /**
   * Whether shadowed light `slot` is the first point light: the one whose
   * visibility expression fills every cube map's in one loop, which the
   * others then read (vtkShadowCubeLookupAll in vtkSoftShadowReceiverFS.glsl,
   * and techniques' own loops).
   */
  bool IsFirstPointLight(int slot) const;

  /**
   * The technique's change to the shading of the receiver whose shaders are
   * `sources` (its mapper and prop), asked each time they are built.
   * Default: none.
   */
  virtual ReceiverShading GetReceiverShading(const vtkShadowShaderSources&) { return {}; }

  /**
   * Upload that change's uniforms (and bind its textures) for `prop`, each
   * time a receiver is drawn; ReceiversDrawn() follows the last, each frame.
   */
  virtual void SetReceiverShadingUniforms(vtkShaderProgram*, vtkProp*) {}
  virtual void ReceiversDrawn() {}

  /**
   * Radius, in texels, of the square PCF kernel the framework's hard lookup
   * uses in receivers (0: one hardware-filtered tap).
   */
  virtual int GetPCFRadius() const { return 0; }

  /// PackedCubeMaps as this frame's cube maps are drawn: off when the
  /// technique reads floats (Traits::FloatCubeMaps).
  bool DrawsPackedCubeMaps() const;

  /**
   * Whether the light depth maps are filtered bilinearly (set by the
   * technique through RenderLightDepthMaps()); PCF then samples texel corners.
   */
  bool GetPCFBilinear() const { return this->LinearMaps; }

  int MapSize = 1024;
  double SlopeScaledBias = 2.0;
  double ConstantBias = 4.0;
  double NormalBias = 1.0;
  double DistanceBias = 0.99;
  bool SinglePassCubeMaps = true;
  bool PackedCubeMaps = false;
  bool DepthPrePass = false;
  int ShadowOnlyLight = -1;
  int ReservedTextureUnits = 4;
  vtkRenderPass* DelegatePass = nullptr;

  // The framework: what a frame casts, its lights and maps, its screen
  // buffers, the one place that draws, and the framework's depth stage.
  std::unique_ptr<vtkShadowCasterRegistry> Casters;
  std::unique_ptr<vtkShadowMapManager> Maps;
  std::unique_ptr<vtkShadowScreenBuffers> Screen;
  std::unique_ptr<vtkShadowDrawer> Drawer;
  std::unique_ptr<vtkShadowDepthStage> DepthStage; ///< light space

  /// A technique timing its own work starts and stops this timer around it
  /// every frame, and stores its CPU work's milliseconds in TechniqueCPUTime
  /// (GetTechniqueGPUTime(), GetTechniqueCPUTime()).
  vtkShadowGPUTimer TechniqueTimer;
  double TechniqueCPUTime = -1.0;

private:
  vtkSoftShadowPass(const vtkSoftShadowPass&) = delete;
  void operator=(const vtkSoftShadowPass&) = delete;

  std::unique_ptr<vtkShadowDepthStage> PrePassStage; ///< the camera's depth pre-pass
  std::unique_ptr<vtkShadowDistanceStage> DistanceStage;
  std::unique_ptr<vtkShadowCameraStage> CameraStage;
  std::unique_ptr<vtkShadowReceiverStage> ReceiverStage;
  Traits FrameTraits;                 ///< GetTraits(), asked at the start of this frame
  vtkShadowGPUTimer LightSpaceTimer;  ///< step 2
  vtkShadowGPUTimer ScreenSpaceTimer; ///< step 3
  vtkShadowGPUTimer ReceiversTimer;   ///< step 4
  bool LinearMaps = false;
  bool PointLightReported = false;
  bool UncombinedReported = false;
  std::unique_ptr<vtkShadowParallelMaps> Parallel;
  bool ComputeReported = false;
  bool SamplersReported = false;
  bool PackedReported = false;
  int ReportedUnshadowed = 0; ///< the count the last warning gave
  int TextureUnits = 0;       ///< a receiver's units, in the last frame's context
  /// TextureUnits less the reserve and the traits' ReceiverTexturesPerFrame.
  int ShadowTextureUnits() const;
  /// Units one shadowed light takes.
  int ReceiverTextures() const;
  /// Whether the context has what the traits need; reports each lack once.
  bool CheckRequirements(vtkOpenGLRenderWindow* context);

  void RenderDepthPrePass(const vtkRenderState* s);
  std::unique_ptr<vtkShadowSceneDelegate> Scene; ///< the delegate's default, translucency
  void RenderReceivers(const vtkRenderState* s, bool screenSpace);
  /// What this frame's receivers are drawn with: the lights, the
  /// technique's receiver code and shading, the settings.
  vtkShadowReceiverStage::Frame GetReceiverFrame();
};

#endif
