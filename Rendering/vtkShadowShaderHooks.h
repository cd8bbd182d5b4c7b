// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkShadowShaderHooks
 * @brief   The render pass VTK's mappers see while the framework draws: it
 *          forwards their shader hooks to the active vtkShadowStage.
 *
 * Part of the framework (vtkShadowDrawer owns one a stage). Registered on
 * props around a draw (Attach(), Detach()), it hands each mapper's shader
 * sources to the stage, adds the layered geometry shader when a draw fills
 * all six faces of a cube map, and warns once per mapper class and edit
 * when a stage's required edit found nothing to edit. Its Render() draws
 * nothing. The mappers rebuild their shaders only when the stage's code
 * key changes (SetStage()).
 *
 * It also compiles each program the stage edited, as the mapper is about to
 * ask for it, through the window's shader cache (so it still compiles once):
 * a program that fails is reported in one error, from the owner (the
 * technique), naming the stage, the mapper and the first line of OpenGL's
 * log, and the mapper gets its shaders as they were before the stage's
 * PostReplace(), the framework's tags emptied: drawn as VTK draws it, not
 * blank. With the environment variable SOFTSHADOWS_DEBUG_SHADERS set (to
 * anything but 0) the error also holds the numbered sources and the whole
 * log. A program that failed once is not compiled or reported again.
 */

#ifndef vtkShadowShaderHooks_h
#define vtkShadowShaderHooks_h

#include "vtkOpenGLRenderPass.h"
#include "vtkSmartPointer.h"               // for vtkSmartPointer
#include "vtkSoftShadowsRenderingModule.h" // for export macro

#include <set>           // for std::set
#include <string>        // for std::string
#include <unordered_map> // for std::unordered_map
#include <utility>       // for std::pair
#include <vector>        // for std::vector

class vtkInformation;
class vtkObject;
class vtkOpenGLRenderWindow;
class vtkShadowShaderSources;
class vtkShadowStage;

class VTKSOFTSHADOWSRENDERING_EXPORT vtkShadowShaderHooks : public vtkOpenGLRenderPass
{
public:
  static vtkShadowShaderHooks* New();
  vtkTypeMacro(vtkShadowShaderHooks, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The stage the mappers' hooks go to (null: none, between draws).
   * `faceFromFirst`, six column-major matrices, makes the draw layered: every
   * triangle goes to the six faces of a cube map, face f's clip position
   * being faceFromFirst[f] times face 0's. The mappers build their shaders
   * again only when the stage, its code key (vtkShadowStage::GetCodeKey())
   * or the layering differs from the last draw's.
   */
  void SetStage(vtkShadowStage* stage, const float (*faceFromFirst)[16] = nullptr);
  vtkShadowStage* GetStage() const { return this->Stage; }

  /**
   * Who reports the shaders that fail (vtkErrorWithObjectMacro), and whose
   * class names them: the technique. Not owned. Default: these hooks.
   */
  void SetOwner(vtkObject* owner) { this->Owner = owner; }

  ///@{
  /**
   * Register on (remove from) the props of `s`, and on the parts of
   * composite props that draw their parts without handing on their keys
   * (vtkAxesActor's shafts and tips; vtkAssembly gives its parts its own
   * keys while it draws them). Parts a prop does not list (vtkProp::GetActors()), such as
   * vtkLightActor's, draw as plain VTK draws them.
   */
  void Attach(const vtkRenderState* s);
  void Detach(const vtkRenderState* s);
  ///@}

  void Render(const vtkRenderState*) override {}

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* vao = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override { return this->StageTime; }
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkShadowShaderHooks();
  ~vtkShadowShaderHooks() override;

private:
  vtkShadowShaderHooks(const vtkShadowShaderHooks&) = delete;
  void operator=(const vtkShadowShaderHooks&) = delete;

  void Report(vtkShadowShaderSources& sources);
  bool Compiles(const vtkShadowShaderSources& sources, std::string* log, std::string* details);

  // The keys Attach() registered in, kept until Detach(): a vtkAssembly
  // replaces its parts' keys with its own while it draws them, and keys
  // destroyed still holding this keep a reference to it (VTK's vector key
  // registers twice and only Remove() undoes both).
  std::vector<vtkSmartPointer<vtkInformation>> PartKeys;
  vtkShadowStage* Stage = nullptr;
  vtkObject* Owner = nullptr;
  vtkOpenGLRenderWindow* Window = nullptr; ///< of the last Attach()
  // Whether each program (by the hash of its sources) compiled and linked:
  // the mapper rebuilds its sources each time the stage changes, twice a
  // frame, and a trial compile hashes them with MD5 the way its cache does.
  std::unordered_map<size_t, bool> Compiled;
  const float (*FaceFromFirst)[16] = nullptr;
  vtkTimeStamp StageTime;
  vtkShadowStage* KeyedStage = nullptr; ///< the stage of the last draw, when it had a key
  std::string Key;                      ///< and that key
  std::set<std::pair<std::string, std::string>> Reported; ///< (mapper class, edit) warned about
};

#endif
