# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# SOFTSHADOWS_SANITIZE: AddressSanitizer and UndefinedBehaviorSanitizer on
# everything this project builds (module libraries, Python wrapping, the
# programs, the test drivers). Debian's VTK stays uninstrumented. Included by
# the root CMakeLists.txt before any target is made; docs/testing.md.
option(SOFTSHADOWS_SANITIZE
  "Build with -fsanitize=address,undefined (GCC); ctest then runs under the sanitizers" OFF)

# Read by Testing/CMakeLists.txt (the out-of-tree build, the preloads).
set(SOFTSHADOWS_SANITIZE_FLAGS "")
set(SOFTSHADOWS_ASAN_RUNTIME "")
set(SOFTSHADOWS_SANITIZE_PRELOAD "")
# The suppression files, each entry commented with why.
get_filename_component(SOFTSHADOWS_SANITIZE_SUPPRESSIONS
  "${CMAKE_CURRENT_LIST_DIR}/../Testing/Sanitize" ABSOLUTE)

if (SOFTSHADOWS_SANITIZE)
  if (SOFTSHADOWS_FUZZ)
    message(FATAL_ERROR
      "SOFTSHADOWS_SANITIZE and SOFTSHADOWS_FUZZ are separate builds (fuzz builds already "
      "use AddressSanitizer and UndefinedBehaviorSanitizer): turn one off.")
  endif ()
  if (NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    message(FATAL_ERROR "SOFTSHADOWS_SANITIZE is set up for GCC, not ${CMAKE_CXX_COMPILER_ID}: "
      "configure with CXX=g++ (clang builds are for SOFTSHADOWS_FUZZ).")
  endif ()
  # No recovery: a UBSan report fails its test instead of scrolling past.
  set(SOFTSHADOWS_SANITIZE_FLAGS
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_compile_options(${SOFTSHADOWS_SANITIZE_FLAGS})
  add_link_options(${SOFTSHADOWS_SANITIZE_FLAGS})

  # python3 is not instrumented: its tests preload the runtime so that our
  # wrapped libraries find ASan already there.
  execute_process(COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=libasan.so
    OUTPUT_VARIABLE SOFTSHADOWS_ASAN_RUNTIME OUTPUT_STRIP_TRAILING_WHITESPACE)
  # A bare name back means GCC did not find it (libasan not installed).
  if (NOT IS_ABSOLUTE "${SOFTSHADOWS_ASAN_RUNTIME}" OR NOT EXISTS "${SOFTSHADOWS_ASAN_RUNTIME}")
    message(FATAL_ERROR "SOFTSHADOWS_SANITIZE: ${CMAKE_CXX_COMPILER} has no libasan.so "
      "(got '${SOFTSHADOWS_ASAN_RUNTIME}'; on Debian it comes with g++, libasan8)")
  endif ()
  # libasan.so is the development symlink; preload the library it names.
  get_filename_component(SOFTSHADOWS_ASAN_RUNTIME "${SOFTSHADOWS_ASAN_RUNTIME}" REALPATH)

  # Mesa's driver (llvmpipe under Xvfb) is preloaded too: libGLX_mesa
  # unloads it when the display closes, before LeakSanitizer looks, and the
  # blocks its globals still held then count as leaks (240 bytes in every
  # process that renders). Loaded at startup, it stays until the end.
  find_file(SOFTSHADOWS_MESA_DRIVER swrast_dri.so
    PATHS "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/dri" /usr/lib/dri NO_DEFAULT_PATH
    DOC "Mesa's DRI driver, preloaded in sanitizer tests (empty: none)")
  set(SOFTSHADOWS_SANITIZE_PRELOAD "${SOFTSHADOWS_ASAN_RUNTIME}")
  if (SOFTSHADOWS_MESA_DRIVER)
    string(APPEND SOFTSHADOWS_SANITIZE_PRELOAD ":${SOFTSHADOWS_MESA_DRIVER}")
  else ()
    message(WARNING "SOFTSHADOWS_SANITIZE: no Mesa swrast_dri.so found; LeakSanitizer may report "
      "blocks of an OpenGL driver unloaded at exit (set SOFTSHADOWS_MESA_DRIVER to its path).")
  endif ()
  message(STATUS "Sanitizers on; tests preload ${SOFTSHADOWS_SANITIZE_PRELOAD}")
endif ()

#[==[
softshadows_sanitizer_environment(<test>... [PYTHON] [NO_PRELOAD])

With SOFTSHADOWS_SANITIZE on, runs the tests under the sanitizers' options
and SOFTSHADOWS_SANITIZE_PRELOAD; off, does nothing. PYTHON: the test is
python3 (not instrumented, and CPython leaves objects behind at exit by
design): no leak check in it, but shadowtest.py gives the softshadows
program it runs the leak-checking options. NO_PRELOAD: for tests whose own
process is a tool such as cmake, which must not be preloaded. Call it in the
folder that added the tests.
#]==]
function (softshadows_sanitizer_environment)
  cmake_parse_arguments(PARSE_ARGV 0 sanitize "PYTHON;NO_PRELOAD" "" "")
  if (NOT SOFTSHADOWS_SANITIZE OR NOT sanitize_UNPARSED_ARGUMENTS)
    return ()
  endif ()
  set(asan "detect_leaks=1:detect_stack_use_after_return=1")
  set(environment
    "LSAN_OPTIONS=suppressions=${SOFTSHADOWS_SANITIZE_SUPPRESSIONS}/lsan.supp:print_suppressions=0"
    "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  if (sanitize_PYTHON)
    list(APPEND environment "ASAN_OPTIONS=detect_leaks=0:detect_stack_use_after_return=1"
      "SOFTSHADOWS_PROGRAM_ASAN_OPTIONS=${asan}")
  else ()
    list(APPEND environment "ASAN_OPTIONS=${asan}")
  endif ()
  if (NOT sanitize_NO_PRELOAD)
    list(APPEND environment "LD_PRELOAD=${SOFTSHADOWS_SANITIZE_PRELOAD}")
  endif ()
  set_property(TEST ${sanitize_UNPARSED_ARGUMENTS} APPEND PROPERTY ENVIRONMENT ${environment})
endfunction ()
