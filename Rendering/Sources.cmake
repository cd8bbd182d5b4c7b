# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The Rendering module's sources, shared by the standalone build
# (CMakeLists.txt here) and the remote-module build (cmake/RemoteModule.cmake).
set(softshadows_rendering_classes
  vtkAliasFreeShadowPass
  vtkContactHardeningShadowPass
  vtkHardShadowPass
  vtkOmnidirectionalShadowPass
  vtkRayCastLightVisibility
  vtkReferenceShadowPass
  vtkShadowLightSize
  vtkShadowTechniqueCatalog
  vtkSilhouetteShadowPass
  vtkSmoothieShadowPass
  vtkSoftShadowPass)

# The framework the techniques stand on: installed, so that a technique can
# be written outside the module, but not wrapped for Python.
set(softshadows_rendering_framework_classes
  vtkShadowCasterRegistry
  vtkShadowCompute
  vtkShadowDepthStage
  vtkShadowDistanceStage
  vtkShadowDrawer
  vtkShadowGeometry
  vtkShadowMapManager
  vtkShadowParallelMaps
  vtkShadowScreenBuffers
  vtkShadowShaderHooks
  vtkShadowStage)

set(softshadows_rendering_framework_headers
  vtkShadowMapperCode.h
  vtkShadowVTKVersion.h
  vtkShadowMatrices.h)

# Internals: a technique's helpers, not installed.
set(softshadows_rendering_private_classes
  vtkAliasFreeBentNormals
  vtkShadowGlyphInstances)

# Header-only internals.
set(softshadows_rendering_private_headers
  vtkShadowSampling.h)

# Shaders live in glsl/ and are embedded as C strings at build time.
set(softshadows_rendering_shaders
  vtkAliasFreeBendFS
  vtkAliasFreeBendVS
  vtkAliasFreeCastersFS
  vtkAliasFreeCastersGS
  vtkAliasFreeCastersVS
  vtkAliasFreeListsCS
  vtkAliasFreeLookup
  vtkAliasFreeLookupBuildCS
  vtkContactCommonFS
  vtkContactDistanceFS
  vtkContactGaussianFS
  vtkContactMultiPassFS
  vtkContactPCFFS
  vtkContactPrepareFS
  vtkContactResolveFS
  vtkContactTileSpreadFS
  vtkContactTilesFS
  vtkOmniPoissonFS
  vtkShadowAccumulateFS
  vtkShadowCubeDistanceFS
  vtkShadowCubeLayersGS
  vtkShadowCubeLookupFS
  vtkShadowNormalOffsetFS
  vtkShadowPackFS
  vtkShadowScreenCommonFS
  vtkShadowSurfaceFS
  vtkSilhouetteBandsGS
  vtkSilhouetteCommon
  vtkSilhouetteEdgesFS
  vtkSilhouetteEdgesVS
  vtkSilhouetteLookupFS
  vtkSmoothieEdgesFS
  vtkSmoothieEdgesGS
  vtkSmoothieEdgesVS
  vtkSmoothieLookupFS
  vtkSmoothieQuadsVS
  vtkSoftShadowReceiverFS)

# Sets <sources_var> and <headers_var> to the generated C strings of the
# shaders in <glsl_dir>.
function (softshadows_rendering_shaders sources_var headers_var glsl_dir)
  set(sources)
  set(headers)
  foreach (shader IN LISTS softshadows_rendering_shaders)
    vtk_encode_string(
      INPUT         "${glsl_dir}/${shader}.glsl"
      EXPORT_SYMBOL "VTKSOFTSHADOWSRENDERING_NO_EXPORT"
      EXPORT_HEADER "vtkSoftShadowsRenderingModule.h"
      HEADER_OUTPUT header
      SOURCE_OUTPUT source)
    list(APPEND sources "${source}")
    list(APPEND headers "${header}")
  endforeach ()
  set("${sources_var}" "${sources}" PARENT_SCOPE)
  set("${headers_var}" "${headers}" PARENT_SCOPE)
endfunction ()
