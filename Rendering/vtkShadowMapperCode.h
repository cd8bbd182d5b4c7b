// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkShadowMapperCode.h
 * @brief  The text of VTK's mapper shaders that the framework edits: the
 *         //VTK:: tags it puts code at and the lighting lines it scales by a
 *         light's shadow factor.
 *
 * The one place that depends on the VTK version the module is built
 * against. VTK 9.1's vtkOpenGLPolyDataMapper (ReplaceShaderLight) writes, per
 * light N, `diffuse += (df * lightColorN);` and `specular += (sf *
 * lightColorN);` (Phong), `radiance = lightColorN;` (PBR, directional) and
 * `radiance = lightColorN * attenuation;` (PBR, positional).
 */

#ifndef vtkShadowMapperCode_h
#define vtkShadowMapperCode_h

#include "vtkShaderProgram.h" // for vtkShaderProgram::Substitute

#include <string> // for std::string

namespace vtkShadowMapperCode
{
// Tags every mapper shader has (vtkOpenGLPolyDataMapper, 9.1).
constexpr const char* SystemDec = "//VTK::System::Dec";
constexpr const char* LightDec = "//VTK::Light::Dec";
constexpr const char* LightImpl = "//VTK::Light::Impl";
// The framework's own tags, placed before the mapper writes its lighting
// code and filled after (see vtkShadowStage).
constexpr const char* ShadowDec = "//VTK::SoftShadow::Dec";
constexpr const char* ShadowImpl = "//VTK::SoftShadow::Impl";

/// Whether the mapper wrote lighting code with a view-space position: only
/// such fragments can be shadowed.
inline bool IsLit(const std::string& fragmentShader)
{
  return fragmentShader.find("vertexVCVSOutput") != std::string::npos;
}

/// Whether the mapper moves the fragment's depth but not its position:
/// points drawn as spheres (gl_PointCoord) and lines as tubes (tubeBasis1).
inline bool MovesDepthOnly(const std::string& fragmentShader)
{
  return fragmentShader.find("gl_FragDepth") != std::string::npos &&
    (fragmentShader.find("gl_PointCoord") != std::string::npos ||
      fragmentShader.find("tubeBasis1") != std::string::npos);
}

/**
 * Scale light `n`'s contribution in `fragmentShader` by the GLSL float
 * `factor`: Phong diffuse and specular, PBR radiance (directional and
 * positional forms); Phong's also by `phong` when given, an expression that
 * may read the light's diffuse cosine `df` (the mapper computes it just
 * before). Returns false if the shader has none of these lines, so that the
 * light would silently stay unshadowed.
 */
inline bool ScaleLight(
  std::string& fragmentShader, int n, const std::string& factor, const std::string& phong = "")
{
  const std::string color = "lightColor" + std::to_string(n);
  const std::string phongFactor = phong.empty() ? factor : factor + " * " + phong;
  bool found = false;
  found |= vtkShaderProgram::Substitute(fragmentShader, "diffuse += (df * " + color + ");",
    "diffuse += (df * " + phongFactor + " * " + color + ");", false);
  vtkShaderProgram::Substitute(fragmentShader, "specular += (sf * " + color + ");",
    "specular += (sf * " + phongFactor + " * " + color + ");", false);
  found |= vtkShaderProgram::Substitute(fragmentShader, "radiance = " + color + ";",
    "radiance = " + factor + " * " + color + ";", false);
  found |= vtkShaderProgram::Substitute(fragmentShader, "radiance = " + color + " * attenuation;",
    "radiance = " + factor + " * " + color + " * attenuation;", false);
  return found;
}
}

#endif
