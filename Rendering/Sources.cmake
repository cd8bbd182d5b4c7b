# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The framework module's sources (SoftShadows::Rendering): what every
# technique stands on. Shared by the standalone build (CMakeLists.txt here)
# and the remote-module build (cmake/RemoteModule.cmake).
set(softshadows_rendering_classes
  vtkShadowLightSize
  vtkSoftShadowPass)

# Installed, so that a technique can be written outside the module, but not
# wrapped for Python.
set(softshadows_rendering_framework_classes
  vtkShadowCameraStage
  vtkShadowCasterRegistry
  vtkShadowCompute
  vtkShadowDepthStage
  vtkShadowDistanceStage
  vtkShadowDrawer
  vtkShadowGeometry
  vtkShadowGPUTimer
  vtkShadowMapManager
  vtkShadowParallelMaps
  vtkShadowReceiverStage
  vtkShadowSceneDelegate
  vtkShadowScreenBuffers
  vtkShadowShaderHooks
  vtkShadowStage)

set(softshadows_rendering_framework_headers
  vtkShadowMapperCode.h
  vtkShadowVTKVersion.h
  vtkShadowMatrices.h)

# Internals, not installed.
set(softshadows_rendering_private_classes
  vtkShadowGlyphInstances
  vtkShadowMapperTwins)

# The framework's shaders (the techniques' own live in Techniques/glsl/).
set(softshadows_rendering_shaders
  glsl/vtkShadowCubeDistanceFS.glsl
  glsl/vtkShadowCubeLayersGS.glsl
  glsl/vtkShadowCubeLookupFS.glsl
  glsl/vtkShadowNormalOffsetFS.glsl
  glsl/vtkShadowPackFS.glsl
  glsl/vtkShadowScreenCodeFS.glsl
  glsl/vtkShadowScreenCommonFS.glsl
  glsl/vtkShadowScreenTilesVS.glsl
  glsl/vtkShadowSurfaceFS.glsl
  glsl/vtkSoftShadowReceiverFS.glsl)
