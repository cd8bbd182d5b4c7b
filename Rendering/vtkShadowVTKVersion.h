// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkShadowVTKVersion.h
 * @brief  What differs between the VTK releases the module builds against,
 *         in one place for C++: 9.1 (Debian 12), 9.2 (ParaView 5.11), 9.3
 *         (Debian 13, ParaView 5.13) and 9.6 (Debian unstable, ParaView 6.1).
 *
 * The shader text VTK writes is in vtkShadowMapperCode.h, the build's
 * differences in cmake/SoftShadowsVTK.cmake; nothing else in the module
 * checks VTK's version.
 *
 * - OpenGL's functions: VTK loads them with GLEW up to 9.3 (`vtk_glew.h`)
 *   and with glad from 9.4 on (`vtk_glad.h`). Code that calls OpenGL
 *   includes this header instead of either, and asks for versions and
 *   extensions with VTK_SHADOW_GL_HAS(VERSION_4_3), VTK_SHADOW_GL_HAS(ARB_...).
 * - Shader programs: vtkOpenGLShaderCache's factory gained tessellation
 *   stages in 9.4 (and in ParaView 5.13's VTK, a "9.3" snapshot, so this is
 *   told from the class, not the version); vtkShadowObservedShaderCache
 *   hands a subclass each program it makes whichever the release.
 * - Composite data: VTK 9.1 and 9.2 draw it with vtkCompositePolyDataMapper2
 *   (OpenGL2); 9.3 moved that work into vtkCompositePolyDataMapper
 *   (RenderingCore), deprecated the former and 9.5 removed it.
 */

#ifndef vtkShadowVTKVersion_h
#define vtkShadowVTKVersion_h

#include "vtkVersionMacros.h" // for VTK_VERSION_NUMBER

#include "vtkOpenGLShaderCache.h" // for vtkShadowObservedShaderCache

#include <type_traits> // for std::void_t
#include <utility>     // for std::declval

#if __has_include("vtk_glad.h")
#include "vtk_glad.h" // IWYU pragma: export
/// Whether the context has OpenGL version or extension `name`, e.g.
/// VTK_SHADOW_GL_HAS(VERSION_4_3), VTK_SHADOW_GL_HAS(ARB_compute_shader).
#define VTK_SHADOW_GL_HAS(name) (GLAD_GL_##name != 0)
#else
#include "vtk_glew.h" // IWYU pragma: export
#define VTK_SHADOW_GL_HAS(name) (GLEW_##name != 0)
#endif

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositePolyDataMapper.h"
#else
#include "vtkCompositePolyDataMapper2.h"
#endif

class vtkCompositeDataDisplayAttributes;
class vtkMapper;
class vtkShaderProgram;
class vtkTransformFeedback;

namespace vtkShadowVTKVersion
{
/// Whether vtkOpenGLShaderCache takes tessellation stages: VTK 9.4, and
/// snapshots before it such as ParaView 5.13's VTK "9.3", whose version
/// cannot tell.
template <typename Cache, typename = void>
struct HasTessellation : std::false_type
{
};
template <typename Cache>
struct HasTessellation<Cache,
  std::void_t<decltype(std::declval<Cache&>().ReadyShaderProgram(static_cast<const char*>(nullptr),
    static_cast<const char*>(nullptr), static_cast<const char*>(nullptr),
    static_cast<const char*>(nullptr), static_cast<const char*>(nullptr),
    static_cast<vtkTransformFeedback*>(nullptr)))>> : std::true_type
{
};

/// The program factory's override for each form: instantiated only for the
/// one the release has.
template <bool Tessellation, typename Cache>
class ObservedShaderCache;

template <typename Cache>
class ObservedShaderCache<true, Cache> : public Cache
{
protected:
  virtual void Created(vtkShaderProgram* program) = 0;
  vtkShaderProgram* GetShaderProgram(const char* vertex, const char* fragment, const char* geometry,
    const char* tessControl, const char* tessEval) override
  {
    vtkShaderProgram* program =
      this->Cache::GetShaderProgram(vertex, fragment, geometry, tessControl, tessEval);
    this->Created(program);
    return program;
  }
};

template <typename Cache>
class ObservedShaderCache<false, Cache> : public Cache
{
protected:
  virtual void Created(vtkShaderProgram* program) = 0;
  vtkShaderProgram* GetShaderProgram(
    const char* vertex, const char* fragment, const char* geometry) override
  {
    vtkShaderProgram* program = this->Cache::GetShaderProgram(vertex, fragment, geometry);
    this->Created(program);
    return program;
  }
};
}

/**
 * A shader cache that passes every program it creates to Created() before
 * returning it, so that a subclass can observe the program's compile errors.
 */
using vtkShadowObservedShaderCache = vtkShadowVTKVersion::ObservedShaderCache<
  vtkShadowVTKVersion::HasTessellation<vtkOpenGLShaderCache>::value, vtkOpenGLShaderCache>;

namespace vtkShadowVTKVersion
{
/// The mapper VTK draws composite polydata with: blocks, their visibility
/// and opacity in its display attributes.
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
using CompositeMapper = vtkCompositePolyDataMapper;
#else
using CompositeMapper = vtkCompositePolyDataMapper2;
#endif

/// The display attributes of `mapper` when it draws composite data as
/// CompositeMapper does, else nullptr.
inline vtkCompositeDataDisplayAttributes* CompositeDisplayAttributes(vtkMapper* mapper)
{
  auto* composite = CompositeMapper::SafeDownCast(mapper);
  return composite ? composite->GetCompositeDataDisplayAttributes() : nullptr;
}
}

#endif
