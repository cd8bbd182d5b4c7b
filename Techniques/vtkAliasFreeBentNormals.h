// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkAliasFreeBentNormals
 * @brief   Smooth shading without light leaks at shadow borders for
 *          vtkAliasFreeShadowPass: bent normals (Sintorn, Eisemann &
 *          Assarsson, section 6).
 *
 * Exact shadows darken every triangle that faces away from the light, while
 * Phong's interpolated normals still light parts of them: the terminator of
 * a coarse mesh turns into a jagged line of triangles. Per vertex and light,
 * l_bend = min over the faces around the vertex of dot(l, n_F), l towards the
 * light's centre; per fragment the light's diffuse cosine l_f becomes
 * alpha l_f + (1 - alpha) l_bend, alpha = min(1, max(3 l_bend, 0)), so that
 * shading reaches 0 smoothly before any light-back-facing face.
 *
 * The receivers' vertex shader reads each point's adjacent faces' normals
 * from two texture buffers, built per polydata when it changes (the paper:
 * face normals in a texture, adjacent faces' indices as texture
 * coordinates); the light's Phong diffuse and specular are scaled by the
 * ratio. It applies to vtkOpenGLPolyDataMapper's Phong- or Gouraud-shaded
 * surfaces with point normals and no geometry shader; others are drawn as
 * VTK draws them: flat faces leak nothing, and the vertices of composite and
 * glyph mappers are not their input's points.
 *
 * @sa vtkAliasFreeShadowPass vtkSoftShadowPass::GetReceiverShading
 */

#ifndef vtkAliasFreeBentNormals_h
#define vtkAliasFreeBentNormals_h

#include <glm/vec4.hpp> // for glm::vec4

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkOpenGLRenderWindow;
class vtkProp;
class vtkShaderProgram;
class vtkShadowCasterRegistry;
class vtkShadowShaderSources;
class vtkWindow;

class vtkAliasFreeBentNormals
{
public:
  vtkAliasFreeBentNormals();
  ~vtkAliasFreeBentNormals();

  /// Whether the receiver whose shaders are `sources` can be bent.
  static bool Applies(const vtkShadowShaderSources& sources);

  ///@{
  /// The receivers' code for `lights` shadowed lights, and the factor on
  /// light `slot`'s Phong terms (it reads VTK's `df`).
  static std::string VertexDeclarations(int lights);
  static std::string VertexImplementation();
  static std::string FragmentDeclarations(int lights);
  static std::string PhongScale(int slot);
  ///@}

  /**
   * Bind `prop`'s adjacency (built if its polydata changed) and set the
   * uniforms for its draw; `lights` per slot: world position (w = 1) or
   * direction towards the light (w = 0).
   */
  void SetUniforms(vtkShaderProgram* program, vtkProp* prop, const std::vector<glm::vec4>& lights,
    vtkOpenGLRenderWindow* context);

  /// After the frame's receivers: unbind, and drop the adjacency of data no
  /// longer drawn.
  void EndFrame(const vtkShadowCasterRegistry& casters);

  void ReleaseGraphicsResources(vtkWindow* w);

private:
  vtkAliasFreeBentNormals(const vtkAliasFreeBentNormals&) = delete;
  void operator=(const vtkAliasFreeBentNormals&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
