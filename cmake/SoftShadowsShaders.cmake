# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# softshadows_encode_shaders(<sources_var> <headers_var> <library> <glsl>...)
#
# Embeds each GLSL file as a C string named by the file (glsl/contact/
# vtkContactPCFFS.glsl: vtkContactPCFFS in vtkContactPCFFS.h), private to
# <library> (e.g. vtkSoftShadowsTechniques, whose module header gives the
# export macros), and sets <sources_var> and <headers_var> to the generated
# files.
#
# Comments are left out of the embedded text (the //VTK:: tags stay): VTK's
# mappers copy, search and hash every shader's whole text each time they
# rebuild it, and a mapper drawn in two stages of a frame rebuilds twice a
# frame; comments were 40% of a receiver's fragment shader.
function (softshadows_encode_shaders sources_var headers_var library)
  string(TOUPPER "${library}" macro)
  set(sources)
  set(headers)
  foreach (shader IN LISTS ARGN)
    get_filename_component(name "${shader}" NAME)
    set(stripped "${CMAKE_CURRENT_BINARY_DIR}/glsl-embedded/${name}")
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${shader}")
    file(READ "${shader}" text)
    string(REPLACE "//VTK::" "@SOFTSHADOWS_TAG@" text "${text}")
    string(REGEX REPLACE "//[^\n]*" "" text "${text}")
    string(REPLACE "@SOFTSHADOWS_TAG@" "//VTK::" text "${text}")
    string(REGEX REPLACE "[ \t]+\n" "\n" text "${text}")
    string(REGEX REPLACE "\n\n+" "\n" text "${text}")
    string(REGEX REPLACE "^\n+" "" text "${text}")
    # Written only when it changes, so that an unchanged shader builds nothing.
    set(old "")
    if (EXISTS "${stripped}")
      file(READ "${stripped}" old)
    endif ()
    if (NOT old STREQUAL text)
      file(WRITE "${stripped}" "${text}")
    endif ()
    vtk_encode_string(
      INPUT         "${stripped}"
      EXPORT_SYMBOL "${macro}_NO_EXPORT"
      EXPORT_HEADER "${library}Module.h"
      HEADER_OUTPUT header
      SOURCE_OUTPUT source)
    list(APPEND sources "${source}")
    list(APPEND headers "${header}")
  endforeach ()
  set("${sources_var}" "${sources}" PARENT_SCOPE)
  set("${headers_var}" "${headers}" PARENT_SCOPE)
endfunction ()
