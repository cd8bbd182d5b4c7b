// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowMapManager
 * @brief   Owns every shadowed light and every light-space texture: its
 *          frusta, the framework's maps, the technique's own per-light
 *          textures and the scratch maps shared by all lights.
 *
 * Part of the framework, data only: Update() decides which lights cast
 * shadows and fits their frusta to the scene. Techniques describe the
 * textures they need (vtkShadowTextureSpec) and the manager makes them at
 * the map size, keeps them across frames while the description holds, and
 * releases them. It draws nothing: vtkShadowDrawer does, through these
 * frusta into these textures.
 */

#ifndef vtkShadowMapManager_h
#define vtkShadowMapManager_h

#include "vtkSmartPointer.h"
#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <glm/mat4x4.hpp> // for glm::dmat4
#include <glm/vec3.hpp>   // for glm::dvec3
#include <glm/vec4.hpp>   // for glm::dvec4

#include <array>  // for std::array
#include <string> // for std::string
#include <vector> // for std::vector

class vtkLight;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkShadowParallelMaps;
class vtkTextureObject;
class vtkWindow;

/**
 * A light-space texture described rather than built: what a technique asks
 * the map manager for (vtkShadowMapManager::GetTexture(), GetScratch()).
 * Every one clamps to its edges; nearest filtering unless Linear.
 */
struct VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowTextureSpec
{
  enum class Format
  {
    Depth, ///< 32-bit depth compared in lookups (sampler2DShadow); 2D only
    Float, ///< Components 32-bit float channels
    Byte,  ///< Components 8-bit channels
  };
  Format Type = Format::Float;
  int Components = 1;
  bool Cube = false;   ///< a cube map, a point light's six faces
  bool Linear = false; ///< filtered bilinearly (a depth map: 2x2 PCF in one tap)
  int Size = 0;        ///< texels on a side; 0: the manager's map size

  /// The framework's depth map of a spot or directional light.
  static vtkShadowTextureSpec DepthMap(bool linear);
  /// The framework's distance cube of a point light: squared distances as
  /// one float, or (`packed`) as RGBA8.
  static vtkShadowTextureSpec DistanceCube(bool packed);
  /// Ask for `components` 32-bit float channels, whatever the driver's
  /// default for the channel count; before the texture is allocated.
  static void SetFloatFormat(vtkTextureObject* texture, int components);
  bool operator==(const vtkShadowTextureSpec& other) const;
  bool operator!=(const vtkShadowTextureSpec& other) const { return !(*this == other); }
};

/**
 * A texture the map manager made, with what it was made from: used as a
 * vtkTextureObject*, null until made.
 */
class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowLightTexture
{
public:
  vtkTextureObject* Get() const;
  operator vtkTextureObject*() const { return this->Get(); }
  vtkTextureObject* operator->() const { return this->Get(); }

private:
  friend class vtkShadowMapManager;
  vtkSmartPointer<vtkTextureObject> Texture;
  vtkShadowTextureSpec Spec;
  int Size = 0;
};

/// Where a light-space map looks from and what it covers.
struct VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowFrustum
{
  glm::dvec3 Eye{ 0.0 };
  glm::dvec3 Direction{ 0.0, 0.0, -1.0 }; ///< unit, from the light into the scene
  glm::dvec3 Up{ 0.0, 1.0, 0.0 };
  bool Parallel = false;
  double Near = 0.1;
  double Far = 1.0;
  glm::dmat4 View{ 1.0 };       ///< world to light eye coordinates
  glm::dmat4 Projection{ 1.0 }; ///< light eye to clip coordinates
  glm::dmat4 WorldToMap{ 1.0 }; ///< world to [0,1]^3 map coordinates
  /// World size of the whole map: x + y * (distance along Direction).
  glm::dvec2 Footprint{ 0.0 };
  /// World size of a texel of a `mapSize` map: for a parallel frustum, at
  /// any distance; for a perspective one, per unit of distance.
  double GetTexelSize(int mapSize) const
  {
    return (this->Parallel ? this->Footprint.x : this->Footprint.y) / mapSize;
  }
};

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowMapManager
{
public:
  using Frustum = vtkShadowFrustum;

  /// One shadowed light.
  struct Light
  {
    vtkLight* Source = nullptr; ///< not owned; valid during a frame
    int SceneIndex = -1;        ///< index in the renderer's light collection
    int ShaderIndex = -1;       ///< N in the mappers' lightColorN uniforms
    bool Directional = false;
    bool Point = false;         ///< positional with a cone of 90 degrees or more: a cube map
    int MapIndex = -1;          ///< index among the lights with the same kind of map
    double Radius = 0.0;        ///< world units, or degrees for directional lights
    double ConeAngle = 0.0;     ///< half-angle in degrees (spot lights)
    double Attenuation = 1.0;   ///< vtkLight::GetShadowAttenuation()
    glm::dvec3 Position{ 0.0 }; ///< world; for directional lights a point on the axis
    glm::dvec3 Direction{ 0.0, 0.0, -1.0 }; ///< point lights: towards the scene's centre
    Frustum Map;                    ///< the light's own (centre) frustum; not for point lights
    vtkShadowLightTexture DepthMap; ///< spot and directional lights
    std::array<Frustum, 6> Faces;   ///< point lights: +x -x +y -y +z -z
    vtkShadowLightTexture CubeMap;  ///< point lights: squared distances
    /// The light's width: its diameter (spot, point), or for directional
    /// lights 2 tan(angular radius), the width per unit of distance.
    double GetSize() const;
    /// Half of GetSize(): the radius, or tan(angular radius).
    double GetHalfSize() const;
    /// The light as a homogeneous point: (Position, 1) for spot and point
    /// lights, (the unit direction towards the light, 0) for directional ones
    /// (vtkShadowCaster::LightToModel() puts it in a caster's model space).
    glm::dvec4 GetHomogeneous() const;
    /// The technique's own textures for this light (e.g. a distance map),
    /// made by GetTexture(), kept for the light's slot across frames.
    std::vector<vtkShadowLightTexture> Textures;
  };

  vtkShadowMapManager();
  ~vtkShadowMapManager();

  /**
   * What a technique can shadow: whether it shadows point lights, and how
   * many texture units its receivers' shaders may give the shadows, each
   * light taking UnitsPerLight of them.
   */
  struct Budget
  {
    bool PointLights = true;
    int TextureUnits = -1; ///< < 0: no limit
    int UnitsPerLight = 1;
  };

  /**
   * Collect the lights that cast shadows and fit their frusta to the bounds of
   * the visible props. Returns the number of shadowed lights.
   *
   * When the lights that could cast shadows need more texture units than
   * `budget` has, the brightest (vtkLight::GetIntensity()) are shadowed,
   * then, among equally bright ones, those nearest the camera's focal point
   * (directional lights first, as they reach everywhere), then the first in
   * the renderer's collection: the same lights every frame while those do
   * not change. Each is taken if it still fits; the others are left
   * unshadowed (GetNumberOfUnshadowedLights()) and light the scene as VTK
   * lights it. The shadowed lights keep the collection's order.
   *
   * With `parallel` (a parallel render), the frusta are fitted to the
   * bounds of every process's visible props, the same on every process.
   */
  int Update(
    vtkRenderer* renderer, const Budget& budget, vtkShadowParallelMaps* parallel = nullptr);
  int Update(vtkRenderer* renderer); ///< every light, point lights too

  /// Lights the last Update() left unshadowed because the budget had no room for them.
  int GetNumberOfUnshadowedLights() const { return this->Unshadowed; }

  /// Point lights the last Update() skipped because the budget shadows none.
  int GetNumberOfSkippedPointLights() const { return this->SkippedPointLights; }

  std::vector<Light>& GetLights() { return this->Lights; }
  const std::vector<Light>& GetLights() const { return this->Lights; }
  vtkRenderer* GetRenderer() const { return this->Renderer; }

  /**
   * The frustum of `light` seen from `eye` along `direction` (a sample of an
   * area light): perspective for spot lights, orthographic around the scene
   * for directional ones.
   */
  Frustum FitFrustum(const Light& light, const glm::dvec3& eye, const glm::dvec3& direction) const;

  /**
   * The six 90-degree frusta of a cube map around `eye`, in OpenGL's face
   * order and orientation, depth range fitted to the scene.
   */
  std::array<Frustum, 6> CubeFaces(const glm::dvec3& eye) const;

  ///@{
  /// Texels on a side of every light-space texture the manager makes,
  /// unless its spec gives its own size. Default 1024.
  void SetMapSize(int size) { this->MapSize = size; }
  int GetMapSize() const { return this->MapSize; }
  ///@}

  /**
   * Make `light.CubeMap` a cube of squared distances (DistanceCube()) and
   * `light.DepthMap` a depth map (DepthMap()), unless they already are.
   * The renderer of the last Update() gives the context.
   */
  void AllocateCubeMap(Light& light, bool packed);
  void AllocateDepthMap(Light& light, bool linear);

  /**
   * The technique's own texture `index` of `light` (Light::Textures), made
   * to `spec` unless it already is: kept with the light's slot across
   * frames, released with the maps.
   */
  vtkTextureObject* GetTexture(Light& light, size_t index, const vtkShadowTextureSpec& spec);

  /**
   * A scratch texture shared by every light, for what a technique draws and
   * reads light by light (a sample's map, a draw's target): `index` numbers
   * a technique's own scratch textures.
   */
  vtkTextureObject* GetScratch(size_t index, const vtkShadowTextureSpec& spec);

  /**
   * Upload what shaders need of a frustum for lookups with normal offset
   * (vtkShadowNormalOffsetFS.glsl): `<prefix>WorldToMap<index>`, `Eye`,
   * `Axis` and `Footprint` (per texel of a `mapSize` map).
   */
  static void SetFrustumUniforms(vtkShaderProgram* program, const std::string& prefix,
    const std::string& index, const Frustum& frustum, int mapSize);

  /**
   * What receivers' lookups from the camera's view coordinates need of a
   * frustum (vtkShadowOffsetInMap, vtkShadowNormalOffsetFS.glsl), composed in
   * double once a frame: the view-to-map matrix, the light in view
   * coordinates (its eye, w = 1; its direction, w = 0) and the offset of
   * `texels` texels as a plane.
   */
  struct ViewLookup
  {
    glm::mat4 ViewToMap{ 1.0f };
    glm::vec4 Light{ 0.0f };
    glm::vec4 Offset{ 0.0f };
  };
  static ViewLookup GetViewLookup(const Frustum& frustum, int mapSize, double texels,
    const glm::dmat4& viewToWorld, const glm::dmat4& worldToView);

  /// GetViewLookup() of every shadowed light (a default one for a point
  /// light) through the renderer's active camera; none without a renderer.
  std::vector<ViewLookup> GetViewLookups(int mapSize, double texels) const;

  /// Upload `lookup` as `<prefix>ViewToMap<index>`, `LightVC` and `OffsetVC`.
  static void SetViewLookupUniforms(vtkShaderProgram* program, const std::string& prefix,
    const std::string& index, const ViewLookup& lookup);

  /**
   * Upload what shaders need of a cube map for vtkShadowCubeLookupFS.glsl:
   * `<prefix>CubeCenter<index>` (the light, the faces' common eye) and
   * `<prefix>CubeRange<index>` (0 for a float map; far^2 of `faces` when
   * `packed` into RGBA8).
   */
  static void SetCubeUniforms(vtkShaderProgram* program, const std::string& prefix,
    const std::string& index, const std::array<Frustum, 6>& faces, bool packed);

  /**
   * The lookups' shared settings: `<prefix>NormalBias` (texels),
   * `<prefix>CubeTexel` (a cube texel's size per unit of distance, for a
   * `mapSize` map) and `<prefix>DistanceBias`.
   */
  static void SetLookupUniforms(vtkShaderProgram* program, const std::string& prefix, int mapSize,
    double normalBias, double distanceBias);

  void ReleaseGraphicsResources(vtkWindow* w);

private:
  glm::dvec3 SceneCenter() const;
  void Make(vtkShadowLightTexture& texture, const vtkShadowTextureSpec& spec);
  void Choose(std::vector<Light>& candidates, const Budget& budget);

  vtkRenderer* Renderer = nullptr; ///< of the last Update(), not owned
  std::vector<Light> Lights;
  std::vector<vtkShadowLightTexture> Scratch;
  int MapSize = 1024;
  int Unshadowed = 0;
  int SkippedPointLights = 0;
  double SceneBounds[6];
};

#endif
