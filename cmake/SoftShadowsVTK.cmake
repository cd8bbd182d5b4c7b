# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# What differs between the VTK releases the module builds against (9.1 on
# Debian 12, 9.3 on Debian 13, 9.6 on unstable, and ParaView's own), in one
# place for CMake; the C++ side is Rendering/vtkShadowVTKVersion.h and
# Rendering/vtkShadowMapperCode.h. Include after find_package(VTK).

# SOFTSHADOWS_VTK_OPENGL: the targets that give OpenGL's functions. VTK 9.4
# replaced GLEW (VTK::glew, with VTK::opengl for OpenGL 1.x's symbols) by
# glad (VTK::glad), which loads them all. The modules' .module files list
# all three as OPTIONAL_DEPENDS, which links those that exist.
if (TARGET VTK::glad)
  set(SOFTSHADOWS_VTK_OPENGL VTK::glad)
else ()
  set(SOFTSHADOWS_VTK_OPENGL VTK::glew VTK::opengl)
endif ()
