// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowDrawer
 * @brief   The one place the framework draws geometry: "draw these casters
 *          through frustum F into target T with stage S".
 *
 * Part of the framework, used by every technique. A draw is described by a
 * vtkShadowDrawSetup: the frustum (a light's 2D map, one face of a cube map,
 * all six faces layered, or the renderer's camera), the target (depth and
 * colour attachments, cleared first), the viewport, polygon-offset bias,
 * blending (MIN for smoothie-like buffers), the stage whose code the mappers
 * run, and what is drawn: the scene's props, the props the camera sees, and
 * technique-owned geometry (vtkShadowGeometry). Light depth maps, cube maps
 * and the camera depth pass are all drawn here.
 *
 * Layered draws (all six cube faces at once) put the framework's layered
 * geometry shader (vtkShadowCubeLayersGS.glsl) into whatever stage is
 * drawing, so any stage can fill a cube map in one pass.
 */

#ifndef vtkShadowDrawer_h
#define vtkShadowDrawer_h

#include "vtkNew.h"                        // for vtkNew
#include "vtkShadowMapManager.h"           // for vtkShadowFrustum
#include "vtkSmartPointer.h"               // for vtkSmartPointer
#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <glm/mat4x4.hpp> // for glm::dmat4

#include <array>      // for std::array
#include <functional> // for std::function
#include <map>        // for std::map
#include <memory>     // for std::unique_ptr
#include <utility>    // for std::move
#include <vector>     // for std::vector

class vtkObject;
class vtkOpenGLCamera;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkProp;
class vtkRenderState;
class vtkShadowCasterRegistry;
class vtkShaderProgram;
class vtkShadowGeometry;
class vtkShadowMapperTwins;
class vtkShadowShaderHooks;
class vtkShadowStage;
class vtkTextureObject;
class vtkWindow;

/// What one draw does.
struct VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowDrawSetup
{
  using Frustum = vtkShadowFrustum;

  /// Which of the scene's props are drawn.
  enum class Props
  {
    Casters, ///< every visible prop, in the view or not: they may shadow what is
    /// the casters that draw more than faces (vtkShadowCasterRegistry::GetDepthMapProps())
    DepthMapCasters,
    Camera, ///< the props of the render state (what the camera pass draws)
    None    ///< only Geometry
  };
  enum class Blending
  {
    None,
    Add, ///< ONE, ONE
    Min, ///< GL_MIN: the nearest value wins
    Max
  };

  ///@{
  /**
   * Through which frustum: `View` (null: the renderer's own camera), or a
   * cube map's `Faces`, drawing face `CubeFace` or, when CubeFace < 0, all six
   * in one layered pass.
   */
  const Frustum* View = nullptr;
  const std::array<Frustum, 6>* Faces = nullptr;
  int CubeFace = -1;
  ///@}

  ///@{
  /**
   * Into which target: `Depth` (a depth texture; null: the drawer's own
   * depth buffer) and `Colours` (2D textures, or cube maps with Faces), both
   * cleared first, colours to `ClearColour`, or target i to
   * `ClearColours[i]` where the list has one. The viewport is the targets'
   * size.
   */
  vtkTextureObject* Depth = nullptr;
  std::vector<vtkTextureObject*> Colours;
  float ClearColour[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  std::vector<std::array<float, 4>> ClearColours;
  ///@}

  /// glPolygonOffset factor and units; both 0: no offset.
  double SlopeBias = 0.0;
  double ConstantBias = 0.0;
  Blending Blend = Blending::None;
  /// Depth test (LESS) and depth writes; off for blended buffers, where the
  /// blending decides what stays.
  bool DepthTest = true;

  /// One draw of technique-owned geometry.
  struct GeometryDraw
  {
    /// At the geometry's own placement, with its own uniforms.
    GeometryDraw(vtkShadowGeometry* geometry)
      : Geometry(geometry)
    {
    }
    /// At `modelToWorld`, with `uniforms`: a geometry (of one polydata) drawn
    /// once for each actor that draws the polydata.
    GeometryDraw(vtkShadowGeometry* geometry, const glm::dmat4& modelToWorld,
      std::function<void(vtkShaderProgram*)> uniforms)
      : Geometry(geometry)
      , Placed(true)
      , ModelToWorld(modelToWorld)
      , Uniforms(std::move(uniforms))
    {
    }
    vtkShadowGeometry* Geometry;
    bool Placed = false;
    glm::dmat4 ModelToWorld{ 1.0 };
    std::function<void(vtkShaderProgram*)> Uniforms;
  };

  Props Draw = Props::Casters;
  std::vector<GeometryDraw> Geometry; ///< technique-owned, drawn after the props
  vtkShadowStage* Stage = nullptr;    ///< the props' shader code; required with props
};

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowDrawer
{
public:
  explicit vtkShadowDrawer(const vtkShadowCasterRegistry& casters);
  ~vtkShadowDrawer();

  /// Draw as `setup` says. False (with a warning) if the target is unusable.
  bool Draw(const vtkRenderState* s, const vtkShadowDrawSetup& setup);

  /**
   * The mapper hooks of draws through `stage`: a render pass registered on
   * props while the stage is active. The receivers' pass attaches its
   * stage's around its delegate. One a stage, so that a mapper drawn
   * through one stage a frame keeps its program from frame to frame (VTK
   * rebuilds a mapper's shaders whenever its render passes change).
   */
  vtkShadowShaderHooks* GetHooks(vtkShadowStage* stage);
  /// Every stage's hooks made so far.
  const std::map<vtkShadowStage*, vtkSmartPointer<vtkShadowShaderHooks>>& GetAllHooks() const
  {
    return this->Hooks;
  }
  /// Who reports the shaders that fail (vtkShadowShaderHooks::SetOwner()).
  void SetOwner(vtkObject* owner);

  void ReleaseGraphicsResources(vtkWindow* w);

private:
  vtkShadowDrawer(const vtkShadowDrawer&) = delete;
  void operator=(const vtkShadowDrawer&) = delete;

  void SetCamera(const vtkShadowDrawSetup::Frustum& frustum);
  bool BindTarget(
    vtkOpenGLRenderWindow* context, const vtkShadowDrawSetup& setup, int& width, int& height);
  void UnbindTarget(const vtkShadowDrawSetup& setup);
  bool BindLayered(vtkOpenGLRenderWindow* context, vtkTextureObject* cube);

  const vtkShadowCasterRegistry& Casters;
  std::map<vtkShadowStage*, vtkSmartPointer<vtkShadowShaderHooks>> Hooks;
  vtkObject* Owner = nullptr;
  /// Small meshes' second mappers, so that each draws in one stage (vtkShadowMapperTwins.h).
  std::unique_ptr<vtkShadowMapperTwins> Twins;
  vtkSmartPointer<vtkOpenGLCamera> Camera;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkTextureObject> ScratchDepth; ///< z-buffer of draws without a depth target
  // Layered draws: a framebuffer and a depth cube map in raw OpenGL (VTK
  // 9.1 has neither).
  unsigned int LayeredFramebuffer = 0;
  unsigned int LayeredDepth = 0;
  int LayeredDepthSize = 0;
  vtkOpenGLRenderWindow* LayeredContext = nullptr;
};

#endif
