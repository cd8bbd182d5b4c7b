// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowStage
 * @brief   What VTK's mapper shaders do during one kind of drawing: light
 *          depth, cube-face distances, the camera pass, the receivers, or a
 *          technique's own.
 *
 * While a stage is active (vtkShadowDrawer::Draw(), or the receivers drawn
 * by the technique's delegate), every vtkOpenGLPolyDataMapper's shader hooks
 * reach it through vtkShadowShaderHooks. PreReplace() runs before the mapper
 * writes its code, while the //VTK:: tags are in place; PostReplace() after,
 * with the mapper's lighting code written. A stage edits all three shaders
 * (vertex, geometry, fragment) through vtkShadowShaderSources, whose
 * Require() records every edit that found nothing to edit: the framework
 * then warns once, naming the mapper, instead of leaving an actor silently
 * unshadowed.
 *
 * A technique adds a stage by subclassing this and giving it to a draw; the
 * framework's switch of stages is gone.
 */

#ifndef vtkShadowStage_h
#define vtkShadowStage_h

#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <string> // for std::string
#include <vector> // for std::vector

class vtkAbstractMapper;
class vtkProp;
class vtkRenderer;
class vtkShaderProgram;
struct vtkShadowDrawSetup;

/// The three shader sources of one mapper's program, being edited.
class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowShaderSources
{
public:
  vtkShadowShaderSources(std::string& vertex, std::string& geometry, std::string& fragment,
    vtkAbstractMapper* mapper, vtkProp* prop)
    : Vertex(vertex)
    , Geometry(geometry)
    , Fragment(fragment)
    , Mapper(mapper)
    , Prop(prop)
  {
  }

  std::string& Vertex;
  std::string& Geometry; ///< empty when the mapper has no geometry shader
  std::string& Fragment;
  vtkAbstractMapper* Mapper;
  vtkProp* Prop;

  /// Put `code` before the first `tag` of `source` (keeping the tag).
  static bool Before(std::string& source, const std::string& tag, const std::string& code);

  /**
   * Replace the first (or every) `tag` of `source` with `code`; when there is
   * none, record `what` (e.g. "the shadow term") as a miss.
   */
  bool Require(std::string& source, const std::string& tag, const std::string& code,
    const std::string& what, bool all = false);

  /// A `#extension` line after the version line of the fragment shader.
  void AddFragmentExtension(const std::string& extension);

  /// Whether the fragment shader has a lit view-space position (see vtkShadowMapperCode).
  bool IsLit() const;

  /**
   * Statements giving each lit fragment's surface (vtkShadowSurfaceFS.glsl:
   * `vtkShadowPositionWC`, `vtkShadowNormalWC` (unit), the same in view
   * coordinates `vtkShadowPositionVC` (vec3), `vtkShadowNormalVC`, and
   * `vtkShadowFaceDefined`), as
   * the camera pass and the receivers' visibility see it: from the
   * fragment's view-space position, which sphere and stick imposters compute
   * in the fragment shader, and its shading normal.
   */
  std::string GetSurfaceCode() const;

  /// Texture units the three shaders declare (sampler uniforms, arrays by
  /// their size): before the receiver stage's code, the mapper's own.
  int CountTextures() const;

  /// What the mapper's actors miss, one sentence each after the mapper's
  /// name (Require()'s misses, and any a stage adds), in order.
  const std::vector<std::string>& GetMisses() const { return this->Misses; }
  void AddMiss(const std::string& sentence) { this->Misses.push_back(sentence); }

private:
  std::vector<std::string> Misses;
};

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowStage
{
public:
  virtual ~vtkShadowStage();

  /// A draw through this stage begins (`setup`: what is drawn where) or ends.
  virtual void Begin(const vtkShadowDrawSetup&) {}
  virtual void End() {}

  /// Before the mapper writes its own code.
  virtual void PreReplace(vtkShadowShaderSources&) {}
  /// After the mapper's code is in place.
  virtual void PostReplace(vtkShadowShaderSources&) {}
  /// Each program, each draw: the stage's uniforms.
  virtual void SetUniforms(vtkShaderProgram*, vtkProp*) {}

  /// What the stage draws, for messages ("the receivers").
  virtual std::string GetName() const { return "a shadow map"; }

  /**
   * What the stage's code depends on besides each mapper's own sources, as
   * `key`: while it stays the same, the mappers keep the programs they built
   * through the stage instead of building them again at every draw (VTK's
   * mappers rebuild their shaders whenever a render pass says its code
   * changed). False, the default: the stage has no such key, and every draw
   * rebuilds.
   */
  virtual bool GetCodeKey(std::string& key) const
  {
    (void)key;
    return false;
  }

  /// `vtkShadowViewToWorld`, the camera's view to world matrix, which the
  /// surface code (vtkShadowShaderSources::GetSurfaceCode()) reads.
  static void SetViewToWorld(vtkShaderProgram* program, vtkRenderer* renderer);
};

#endif
