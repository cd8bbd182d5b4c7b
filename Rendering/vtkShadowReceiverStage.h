// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowReceiverStage
 * @brief   The receivers: every lit mapper shader the scene's delegate
 *          draws gets each shadowed light's visibility and scales that
 *          light's contribution by it.
 *
 * Part of the framework (vtkSoftShadowPass draws the scene through it).
 * Tags are placed before the mapper writes its lighting code and filled
 * after, once it is known whether the shader has lighting at all: the
 * framework's receiver code (vtkSoftShadowReceiverFS.glsl), the technique's
 * (vtkShadowReceiverCode), then per shadowed light `vtkShadowVisibilityN`
 * and `vtkShadowFactorN`, which scales light N's Phong diffuse and
 * specular or PBR radiance (vtkShadowMapperCode::ScaleLight()).
 *
 * A receiver's shader has a limited number of texture units: the shadowed
 * lights were chosen to fit beside the mappers' own textures, and a shader
 * with more of its own shadows the first lights that fit and says so once.
 */

#ifndef vtkShadowReceiverStage_h
#define vtkShadowReceiverStage_h

#include "vtkShadowStage.h"

#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkShadowMapManager;
class vtkShadowScreenBuffers;
class vtkTextureObject;

/// A texture the receivers read: the framework declares it (`uniform
/// <Sampler> <Name>;`), binds it while they draw and sets its unit.
struct VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowReceiverTexture
{
  std::string Name;
  std::string Sampler; ///< e.g. "sampler2D"
  vtkTextureObject* Texture;
};

/**
 * What a technique adds to receivers' fragment shaders: GLSL declarations
 * after the framework's own (vtkSoftShadowReceiverFS.glsl); statements run
 * once a fragment before any light's visibility; the expression of shadowed
 * light `slot`'s visibility (1 lit, 0 umbra) at `vtkShadowPositionWC`
 * (unset: the framework's, vtkSoftShadowPass::GetDefaultVisibility()); the
 * textures they read, per light (e.g. vtkShadowMapManager::Light::Textures)
 * or per frame, with names that differ; and the technique's uniforms (may
 * be unset).
 */
struct VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowReceiverCode
{
  std::string Declarations;
  std::string Setup;
  std::function<std::string(int slot)> Visibility;
  std::vector<vtkShadowReceiverTexture> Textures;
  std::function<void(vtkShaderProgram*)> Uniforms;
};

/// What a technique changes in a receiver's shading besides the shadow
/// (e.g. bent normals): code for the vertex shader (declarations; and
/// statements in main, before the mapper's lighting code, that may read
/// `vertexMC`), declarations for the fragment shader, and per light slot
/// an expression scaling that light's Phong diffuse and specular, which
/// may read its diffuse cosine `df`. Empty strings: nothing.
struct VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowReceiverShading
{
  std::string VertexDeclarations;
  std::string VertexImplementation;
  std::string FragmentDeclarations;
  std::vector<std::string> PhongScales;
};

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowReceiverStage : public vtkShadowStage
{
public:
  /// What this frame's receivers are drawn with, set before the scene draws.
  struct Frame
  {
    const vtkShadowMapManager* Maps = nullptr; ///< the shadowed lights and their maps
    /// A screen-space technique's buffers (their textures, one a light); null: none.
    const vtkShadowScreenBuffers* Screen = nullptr;
    vtkShadowReceiverCode Code;
    /// The framework's visibility of light `slot`, where Code has none.
    std::function<std::string(int slot)> DefaultVisibility;
    /// The technique's shading change for a receiver, asked each time its
    /// shaders are built; and its uniforms, each time it is drawn (may be unset).
    std::function<vtkShadowReceiverShading(const vtkShadowShaderSources&)> Shading;
    std::function<void(vtkShaderProgram*, vtkProp*)> ShadingUniforms;
    std::vector<std::string> Extensions; ///< GLSL extensions the code needs
    int TextureUnits = 0;                ///< a receiver's texture units in this context
    int TexturesPerFrame = 0;            ///< the technique's own, besides any light's
    int TexturesPerLight = 1;            ///< what one shadowed light takes
    int MapSize = 1024;
    double NormalBias = 1.0;
    double DistanceBias = 0.99;
    int PCFRadius = 0;        ///< the hard lookup's kernel, in texels
    bool PCFBilinear = false; ///< the maps are filtered: taps on texel corners
    bool PackedCubeMaps = false;
    int ShadowOnlyLight = -1; ///< the scene's light whose visibility alone is drawn
    std::string Technique;    ///< the technique's class, for messages
    /// What Shading() depends on besides the lights (e.g. the technique's
    /// modification time): part of the stage's code key.
    std::string ShadingKey;

    /// Light `slot`'s visibility expression: the technique's, else the framework's.
    std::string Visibility(int slot) const
    {
      return this->Code.Visibility ? this->Code.Visibility(slot) : this->DefaultVisibility(slot);
    }
  };

  vtkShadowReceiverStage();
  ~vtkShadowReceiverStage() override;

  /// Also composes what every receiver's draw uploads of the camera and
  /// the lights, once a frame.
  void SetFrame(Frame frame);
  const Frame& GetFrame() const { return this->Current; }

  /**
   * The framework's light-space lookups in GLSL: the receiver offset
   * (vtkShadowNormalOffsetFS.glsl) and the cube maps of squared distances
   * (vtkShadowCubeLookupFS.glsl).
   */
  static std::string GetLightSpaceLookupCode();

  /// The most texture units a receiver's shader declared of its own so far.
  int GetOwnTextures() const { return this->OwnTextures; }

  void PreReplace(vtkShadowShaderSources& sources) override;
  void PostReplace(vtkShadowShaderSources& sources) override;
  void SetUniforms(vtkShaderProgram* program, vtkProp* prop) override;
  std::string GetName() const override { return "the receivers"; }
  /// Everything of the frame that goes into the receivers' code.
  bool GetCodeKey(std::string& key) const override;

private:
  Frame Current;
  struct FrameUniforms;
  std::unique_ptr<FrameUniforms> Uniforms;
  int OwnTextures = 0;
};

#endif
