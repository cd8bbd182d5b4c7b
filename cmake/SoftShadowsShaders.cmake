# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# softshadows_encode_shaders(<sources_var> <headers_var> <library> <glsl>...)
#
# Embeds each GLSL file as a C string named by the file (glsl/contact/
# vtkContactPCFFS.glsl: vtkContactPCFFS in vtkContactPCFFS.h), private to
# <library> (e.g. vtkSoftShadowsTechniques, whose module header gives the
# export macros), and sets <sources_var> and <headers_var> to the generated
# files.
function (softshadows_encode_shaders sources_var headers_var library)
  string(TOUPPER "${library}" macro)
  set(sources)
  set(headers)
  foreach (shader IN LISTS ARGN)
    vtk_encode_string(
      INPUT         "${shader}"
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
