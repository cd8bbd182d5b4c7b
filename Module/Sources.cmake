# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The Filters module's classes, shared by the standalone build (CMakeLists.txt
# here) and the remote-module build (cmake/RemoteModule.cmake).
set(softshadows_filters_classes
  vtkEdgeAdjacencyFilter
  vtkFenceSource
  vtkLightSilhouetteFilter
  vtkSoftShadowsMeshCheck
  vtkTopologyAwareMeshFilter)
# Internal helpers (OpenMesh and the silhouette hierarchy live here, out of the
# public headers): compiled in, neither installed nor wrapped.
set(softshadows_filters_private_classes
  vtkSoftShadowsEdgeTable
  vtkSoftShadowsNormalConeTree
  vtkSoftShadowsTriangleMesh)
set(softshadows_filters_private_headers
  vtkSoftShadowsLargeBuffers.h
  vtkSoftShadowsVTKVersion.h)
