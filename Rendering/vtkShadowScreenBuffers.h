// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowScreenBuffers
 * @brief   Screen-space side of the framework: the camera depth pre-pass,
 *          one visibility texture per shadowed light, and full-screen passes
 *          that reconstruct each pixel's world position.
 *
 * Part of the framework. A technique's screen-space pass is a fragment
 * shader body given to CreateQuad(); it gets `vtkShadowCameraDepth`,
 * `vtkShadowScreenPixel()` and `vtkShadowScreenPositionWC()` from
 * vtkShadowScreenCommonFS.glsl. Receivers read the visibility textures back
 * in vtkSoftShadowReceiverFS.glsl.
 */

#ifndef vtkShadowScreenBuffers_h
#define vtkShadowScreenBuffers_h

#include "vtkSmartPointer.h"
#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <functional> // for std::function
#include <map>        // for std::map
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderState;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowScreenBuffers
{
public:
  vtkShadowScreenBuffers();
  ~vtkShadowScreenBuffers();

  /**
   * Buffers are the viewport's size divided by this on each axis (rounded
   * up). Default 1.
   */
  void SetResolutionDivisor(int divisor) { this->Divisor = divisor < 1 ? 1 : divisor; }

  /**
   * Size the buffers to the renderer's viewport and take this frame's
   * camera. Before any screen-space pass.
   */
  bool Update(const vtkRenderState* s);

  /**
   * The camera depth of the opaque props, the buffers' size, which
   * vtkSoftShadowPass::RenderCameraDepth() draws and screen-space passes
   * read (`vtkShadowCameraDepth`).
   */
  vtkTextureObject* GetCameraDepth() const { return this->CameraDepth; }

  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }

  /// What a screen-space pass's draws cover: the whole buffer (DrawQuad()),
  /// or only the tiles a texture selects (DrawTiles()).
  enum class Coverage
  {
    Screen,
    Tiles
  };

  /**
   * A full-screen pass whose fragment shader is the common screen-space
   * declarations followed by `fragmentSource` (which defines main()).
   */
  std::unique_ptr<vtkOpenGLQuadHelper> CreateQuad(vtkOpenGLRenderWindow* context,
    const std::string& fragmentSource, Coverage coverage = Coverage::Screen) const;

  /**
   * A technique's full-screen pass, kept with the buffers as GetTexture()
   * keeps textures: CreateQuad() of `source()` on first use and again when
   * `variant` (what the source depends on, e.g. a define's value) or
   * `coverage` changes, released with the buffers; `source` is called only then. nullptr when
   * it does not build (VTK logs the compiler's output); a variant that
   * failed is not built again, and only that first time is `failed` set.
   */
  vtkOpenGLQuadHelper* GetQuad(const std::string& name, const std::string& variant,
    const std::function<std::string()>& source, bool* failed = nullptr,
    Coverage coverage = Coverage::Screen);

  /**
   * How a quad uses the target's depth buffer as a pixel mask, so that later
   * passes shade only the pixels an earlier one selected (the rasterizer
   * skips the others before shading).
   */
  enum class QuadMask
  {
    None,  ///< no depth test
    Write, ///< the shader sets gl_FragDepth (below the quad's depth selects)
    Test   ///< only pixels whose stored depth is below the quad's are drawn
  };

  /**
   * Draw a CreateQuad() pass over the current target: binds the camera depth,
   * uploads the reconstruction matrix, then lets `setUniforms` add the pass's
   * own. With QuadMask::Test the quad lies at `quadDepth` (window depth).
   */
  void DrawQuad(vtkOpenGLQuadHelper* quad,
    const std::function<void(vtkShaderProgram*)>& setUniforms, QuadMask mask = QuadMask::None,
    float quadDepth = 0.5f);

  /**
   * Draw a Coverage::Tiles pass as DrawQuad() does, but only over the tiles
   * `tiles` selects: a texture with a texel per `tileSize` x `tileSize`
   * pixels of the target (the buffers' size), whose last component is
   * positive where its tile is drawn. A software rasterizer pays for every
   * pixel a full-screen pass covers, even one whose shader only copies;
   * pixels outside the drawn tiles keep what the targets held.
   */
  void DrawTiles(vtkOpenGLQuadHelper* quad, vtkTextureObject* tiles, int tileSize,
    const std::function<void(vtkShaderProgram*)>& setUniforms, QuadMask mask = QuadMask::None,
    float quadDepth = 0.5f);

  /**
   * Draw into light `slot`'s visibility texture (allocated on demand, the
   * buffers' size). A texel holds r = visibility (1 lit, 0 umbra), g = 1
   * where r is valid and 0 where receivers should keep their own hard
   * shadow, b = the camera distance of the surface it belongs to (receivers
   * use only texels of their own surface). Float, cleared to (clear, 0, 0, 0)
   * first.
   */
  void BeginVisibility(int slot, float clear);
  void EndVisibility();

  /**
   * A float texture of 1 to 4 components, clamped to its edges: what
   * screen-space passes draw into and read texel by texel (nearest
   * filtering), or with `data` (width * height * components floats) and
   * `linear` filtering a technique's table read between texels.
   */
  static vtkSmartPointer<vtkTextureObject> NewFloatTexture(vtkOpenGLRenderWindow* context,
    int width, int height, int components, const float* data = nullptr, bool linear = false);

  /**
   * A technique's own texture, kept with the buffers: a NewFloatTexture() of
   * `components`, or (0 components) a 24-bit depth texture, e.g. a mask that
   * later quads test against. `width` x `height`, 0 for the buffers' size;
   * created on first use, resized after, released with the buffers or by
   * ReleaseTexture(). `name` tells a technique's textures apart.
   */
  vtkTextureObject* GetTexture(
    const std::string& name, int components, int width = 0, int height = 0);
  void ReleaseTexture(const std::string& name);

  /**
   * The targets of the next screen-space passes for as long as it lives:
   * `colours` (and `depth`) over `width` x `height` (0: the buffers' size),
   * detached when it goes. The caller pushes the framebuffer bindings
   * (vtkOpenGLState) before its passes and pops them after.
   *
   *   {
   *     vtkShadowScreenBuffers::Targets bound(screen, { texture });
   *     screen->DrawQuad(...);
   *   }
   */
  class VTKSOFTSHADOWSRENDERING_EXPORT Targets
  {
  public:
    Targets(vtkShadowScreenBuffers* buffers, const std::vector<vtkTextureObject*>& colours,
      vtkTextureObject* depth = nullptr, int width = 0, int height = 0);
    ~Targets();
    Targets(const Targets&) = delete;
    Targets& operator=(const Targets&) = delete;

  private:
    vtkShadowScreenBuffers* Buffers;
  };

  /// Colour targets one pass can write (GL_MAX_DRAW_BUFFERS, at most 8).
  int GetMaximumTargets();

  /// Whether the context has sampler objects (OpenGL 3.3), which Sampler needs.
  bool SupportsSamplers() const;

  /// Whether DrawTiles() can draw tiles of `tileSize` pixels: OpenGL
  /// guarantees points of only 1 pixel (GL_POINT_SIZE_RANGE).
  bool SupportsTiles(int tileSize) const;

  /**
   * A texture activated and read through one of the framework's sampler
   * objects for as long as it lives: a depth map as raw depths (no
   * comparison, nearest), or a screen texture with bilinear filtering. When
   * it goes, the texture's own sampling is back and it is deactivated.
   * Movable, so that a vector can hold one per light.
   */
  class VTKSOFTSHADOWSRENDERING_EXPORT Sampler
  {
  public:
    enum class Reading
    {
      RawDepth,
      Bilinear
    };
    Sampler(vtkShadowScreenBuffers* buffers, vtkTextureObject* texture, Reading reading);
    ~Sampler();
    Sampler(Sampler&& other) noexcept;
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;
    Sampler& operator=(Sampler&&) = delete;

  private:
    vtkTextureObject* Texture;
  };

  /**
   * World size of one of the buffers' pixels on a surface at camera distance
   * d: footprint[0] + footprint[1] * d (parallel projection: [0] only).
   */
  const float* GetPixelFootprint() const { return this->PixelFootprint; }

  /**
   * Light `slot`'s visibility texture (as above), allocated on demand, for a
   * technique that draws into it with its own framebuffer: every texel must
   * be written, nothing clears it.
   */
  vtkTextureObject* GetVisibility(int slot);

  /**
   * Light `slot`'s receivers' texture, allocated on demand (one float a
   * texel, the buffers' size), for a technique that writes the codes itself
   * (vtkShadowPackTexel() in vtkShadowScreenCodeFS.glsl, which a quad's
   * shader gets) in its last passes and saves Pack() a full-screen pass.
   * Every texel must be written.
   */
  vtkTextureObject* GetPacked(int slot);

  /**
   * For a camera pass (vtkSoftShadowPass::RenderCameraDepth()) that writes
   * receivers' codes itself: the declarations of vtkShadowPackTexel()
   * (vtkShadowScreenCodeFS.glsl), and the uniforms they need this frame.
   */
  static std::string GetCodeDeclarations();
  void SetCodeUniforms(vtkShaderProgram* program) const;

  /**
   * After the technique's passes: code the visibility texture of each light
   * drawn through BeginVisibility() or GetVisibility() for the receivers
   * (vtkShadowPackFS.glsl), so that their bilinear lookup gathers four texels
   * in one fetch; lights whose codes the technique wrote (GetPacked()) stay
   * as they are. Returns false, with a warning, if a light got neither this
   * frame, or without OpenGL 4.0 or ARB_texture_gather (reported once).
   */
  bool Pack(int numberOfLights);

  ///@{
  /** Receivers: bind the packed textures and upload their uniforms. */
  void ActivateTextures();
  void DeactivateTextures();
  void SetUniforms(vtkShaderProgram* program, int numberOfLights) const;
  /**
   * The receivers' declarations of the buffers' layout this frame. Where
   * the buffers divide the viewport exactly (its size a multiple of the
   * divisor), the divisor and the viewport's origin are compiled in and
   * receivers read no uniform for them: llvmpipe loads a uniform for every
   * fragment that reads it. Otherwise nothing, and they read the uniforms
   * SetUniforms() sets. (A window resized between sizes that are and are
   * not multiples switches between two cached shaders.) Set by Update().
   */
  const std::string& GetLayoutDeclarations() const { return this->LayoutDeclarations; }
  ///@}

  void ReleaseGraphicsResources(vtkWindow* w);

private:
  void CreateSamplers();
  void UpdateLayoutDeclarations();
  /// DrawQuad() and DrawTiles(): the state and uniforms around `draw`.
  void DrawPass(vtkShaderProgram* program,
    const std::function<void(vtkShaderProgram*)>& setUniforms, QuadMask mask, float quadDepth,
    const std::function<void()>& draw);
  void BindTargets(
    const std::vector<vtkTextureObject*>& colours, vtkTextureObject* depth, int width, int height);
  void UnbindTargets();

  /// What a light's receivers' texture comes from this frame.
  enum class Written
  {
    None,
    Visibility, ///< a visibility texture, coded by Pack()
    Packed      ///< the technique's own codes
  };
  void MarkWritten(int slot, Written writer);

  vtkOpenGLRenderWindow* Context = nullptr;
  int Divisor = 1;
  int Width = 0; // the buffers', Divisor times smaller than the viewport
  int Height = 0;
  int ViewportSize[2] = { 0, 0 };
  double CameraPosition[3] = { 0.0, 0.0, 0.0 };
  int Origin[2] = { 0, 0 };
  std::string LayoutDeclarations; // see GetLayoutDeclarations()
  float MaximumPointSize = 1.0f;  // GL_POINT_SIZE_RANGE's upper end, per context
  float ClipToWorld[16];
  vtkSmartPointer<vtkTextureObject> CameraDepth;
  std::vector<vtkSmartPointer<vtkTextureObject>> Visibility;
  std::vector<vtkSmartPointer<vtkTextureObject>> Packed;
  std::vector<Written> Writer; // per light, reset by Update()
  std::unique_ptr<vtkOpenGLQuadHelper> PackQuad;
  float LogNear = 0.0f;     // packed camera distances: log2 of the smallest
  float CodesPerLog = 1.0f; // and codes per unit of log2
  bool GatherReported = false;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  unsigned int BoundTargets = 0;
  bool BoundDepth = false;
  std::map<std::string, vtkSmartPointer<vtkTextureObject>> Textures;
  struct KeptQuad
  {
    std::string Variant;
    Coverage Covers = Coverage::Screen;
    std::unique_ptr<vtkOpenGLQuadHelper> Quad; ///< null when Variant failed
  };
  std::map<std::string, KeptQuad> Quads;
  int MaximumTargets = 0;
  unsigned int TilesArray = 0; // a vertex array with no arrays, for DrawTiles()
  unsigned int RawDepthSampler = 0;
  unsigned int BilinearSampler = 0;
  float PixelFootprint[2] = { 0.0f, 0.0f };
};

#endif
