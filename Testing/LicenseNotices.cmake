# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# Every source file carries the licence notice in its first lines, so that a
# file copied out of the project still says under what terms. Run as
#   cmake -DSOURCE=<source tree> -P LicenseNotices.cmake
if (NOT EXISTS "${SOURCE}/LICENSE")
  message(FATAL_ERROR "no LICENSE at the source tree's root")
endif ()
file(GLOB_RECURSE files RELATIVE "${SOURCE}"
  "${SOURCE}/*.h" "${SOURCE}/*.cxx" "${SOURCE}/*.txx" "${SOURCE}/*.glsl"
  "${SOURCE}/*.py" "${SOURCE}/*.sh" "${SOURCE}/*.cmake" "${SOURCE}/*CMakeLists.txt")
set(missing "")
set(checked 0)
foreach (file IN LISTS files)
  # Build trees and test inputs (meshes, fuzz corpora) are not sources.
  if (file MATCHES "^(build[^/]*|Testing/Data|Testing/Fuzz/(corpus|data|regressions))/"
      OR file MATCHES "/CMakeFiles/")
    continue ()
  endif ()
  file(STRINGS "${SOURCE}/${file}" head LIMIT_COUNT 4)
  if (NOT head MATCHES "SPDX-License-Identifier: BSD-3-Clause")
    list(APPEND missing "${file}")
  endif ()
  math(EXPR checked "${checked} + 1")
endforeach ()
if (missing)
  list(JOIN missing "\n  " missing)
  message(FATAL_ERROR "no SPDX-License-Identifier in the first lines of:\n  ${missing}")
endif ()
message(STATUS "${checked} source files carry the licence notice")
