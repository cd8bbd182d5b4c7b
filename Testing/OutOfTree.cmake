# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# The installed module as an outside project sees it: install this build
# into a fresh prefix, build Examples/Cxx/OutOfTree (a technique written
# against the installed framework headers) with find_package(SoftShadows),
# and run it. Run as
#   cmake -DBUILD=<build tree> -DSOURCE=<example> -DWORK=<scratch>
#         [-DFLAGS=<flags>] [-DPRELOAD=<libraries>] -P OutOfTree.cmake
# FLAGS (space-separated) compile and link the example as the build was: with
# the sanitizers, ASan's runtime must come first in the program's libraries.
# PRELOAD (colon-separated) is the program's LD_PRELOAD, not cmake's.
file(REMOVE_RECURSE "${WORK}")
function (run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${what}: ${out}")
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "${what} failed (${result}):\n${out}\n${err}")
  endif ()
endfunction ()
run("install" "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${WORK}/prefix")
if (NOT EXISTS "${WORK}/prefix/share/doc/softshadows/LICENSE")
  message(FATAL_ERROR "the install has no share/doc/softshadows/LICENSE")
endif ()
set(flag_options "")
if (FLAGS)
  set(flag_options "-DCMAKE_CXX_FLAGS=${FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${FLAGS}")
endif ()
run("configure" "${CMAKE_COMMAND}" -S "${SOURCE}" -B "${WORK}/build"
  "-DCMAKE_PREFIX_PATH=${WORK}/prefix" -DCMAKE_BUILD_TYPE=Release ${flag_options})
run("build" "${CMAKE_COMMAND}" --build "${WORK}/build")
set(program "${WORK}/build/TexelGrid")
if (PRELOAD)
  set(program "${CMAKE_COMMAND}" -E env "LD_PRELOAD=${PRELOAD}" "${program}")
endif ()
run("TexelGrid" ${program} "${WORK}/grid.png")
