# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The ray-cast ground truth's sources (SoftShadows::Truth), the one module
# that links Embree. Shared by the standalone build (CMakeLists.txt here) and
# the remote-module build (cmake/RemoteModule.cmake).
set(softshadows_truth_classes
  vtkLightVisibilityFilter
  vtkRayCastLightVisibility
  vtkSolarPosition)

# Neither installed nor wrapped: the ray casting the module's classes share.
set(softshadows_truth_private_classes
  vtkRayCastScene)
