# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Remote-module build: one module, VTK::RenderingSoftShadows, whose library
# name gives it the Rendering folder's export header; the other folders'
# headers are forwarding shims.
include("${CMAKE_CURRENT_LIST_DIR}/SoftShadowsShaders.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/../Module/Sources.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/../Rendering/Sources.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/../Techniques/Sources.cmake")
include("${CMAKE_CURRENT_LIST_DIR}/../Truth/Sources.cmake")

set(shims)
foreach (folder IN ITEMS Filters Techniques Truth)
  string(TOUPPER "${folder}" macro)
  set(shim "${CMAKE_CURRENT_BINARY_DIR}/vtkSoftShadows${folder}Module.h")
  file(WRITE "${shim}" "#include \"vtkSoftShadowsRenderingModule.h\"
#define VTKSOFTSHADOWS${macro}_EXPORT VTKSOFTSHADOWSRENDERING_EXPORT
#define VTKSOFTSHADOWS${macro}_NO_EXPORT VTKSOFTSHADOWSRENDERING_NO_EXPORT
")
  list(APPEND shims "${shim}")
endforeach ()

list(TRANSFORM softshadows_rendering_shaders PREPEND "${CMAKE_CURRENT_LIST_DIR}/../Rendering/")
list(TRANSFORM softshadows_techniques_shaders PREPEND "${CMAKE_CURRENT_LIST_DIR}/../Techniques/")
softshadows_encode_shaders(shader_sources shader_headers vtkSoftShadowsRendering
  ${softshadows_rendering_shaders} ${softshadows_techniques_shaders})

list(TRANSFORM softshadows_filters_classes PREPEND "Module/")
list(TRANSFORM softshadows_filters_private_classes PREPEND "Module/")
list(TRANSFORM softshadows_filters_private_headers PREPEND "Module/")
list(TRANSFORM softshadows_rendering_private_classes PREPEND "Rendering/")
list(TRANSFORM softshadows_rendering_classes PREPEND "Rendering/")
list(TRANSFORM softshadows_rendering_framework_classes PREPEND "Rendering/")
list(TRANSFORM softshadows_rendering_framework_headers PREPEND "Rendering/")
list(TRANSFORM softshadows_techniques_classes PREPEND "Techniques/")
list(TRANSFORM softshadows_techniques_private_classes PREPEND "Techniques/")
list(TRANSFORM softshadows_techniques_private_headers PREPEND "Techniques/")
list(TRANSFORM softshadows_techniques_catalog_sources PREPEND "Techniques/")
list(TRANSFORM softshadows_truth_classes PREPEND "Truth/")
list(TRANSFORM softshadows_truth_private_classes PREPEND "Truth/")
vtk_module_add_module(VTK::RenderingSoftShadows
  CLASSES ${softshadows_filters_classes} ${softshadows_rendering_classes}
    ${softshadows_techniques_classes} ${softshadows_truth_classes}
  SOURCES ${shader_sources} ${softshadows_techniques_catalog_sources}
  NOWRAP_CLASSES ${softshadows_rendering_framework_classes}
  NOWRAP_HEADERS ${softshadows_rendering_framework_headers}
  PRIVATE_CLASSES ${softshadows_filters_private_classes} ${softshadows_rendering_private_classes}
    ${softshadows_techniques_private_classes} ${softshadows_truth_private_classes}
  PRIVATE_HEADERS ${shader_headers} ${shims} ${softshadows_filters_private_headers}
    ${softshadows_techniques_private_headers})
vtk_module_include(VTK::RenderingSoftShadows PRIVATE Module Rendering Techniques Truth)
vtk_module_find_package(PACKAGE glm)
vtk_module_find_package(PACKAGE OpenMesh)
find_package(embree 4 QUIET)
if (embree_FOUND)
  vtk_module_find_package(PACKAGE embree VERSION 4)
else ()
  vtk_module_find_package(PACKAGE embree VERSION 3)
endif ()
vtk_module_link(VTK::RenderingSoftShadows PRIVATE glm::glm OpenMeshCore embree)
vtk_module_definitions(VTK::RenderingSoftShadows
  PRIVATE "SOFTSHADOWS_EMBREE_MAJOR=${embree_VERSION_MAJOR}")
if (CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  # Brute-force and tree silhouette searches must agree bit for bit.
  vtk_module_compile_options(VTK::RenderingSoftShadows PRIVATE -ffp-contract=off)
endif ()
