# SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
# SPDX-License-Identifier: BSD-3-Clause
# SOFTSHADOWS_FUZZ: libFuzzer targets (Testing/Fuzz), and
# softshadows_add_fuzzer() to declare one. Included by the root
# CMakeLists.txt before any target is made; docs/testing.md.
#
# With SOFTSHADOWS_FUZZ on (clang only), every target of the project is
# compiled with coverage for the fuzzer plus ASan and UBSan, and each fuzz
# target is a libFuzzer program. With it off, each fuzz target becomes a
# small driver that runs its corpus and regression inputs once, as a ctest
# test: every build checks them, with any compiler.
option(SOFTSHADOWS_FUZZ "Build the libFuzzer targets of Testing/Fuzz (needs clang)" OFF)

set(SOFTSHADOWS_FUZZ_DIR "${CMAKE_CURRENT_LIST_DIR}/../Testing/Fuzz")
get_filename_component(SOFTSHADOWS_FUZZ_DIR "${SOFTSHADOWS_FUZZ_DIR}" ABSOLUTE)
# One file per fuzz target, which scripts/fuzz.sh reads: rewritten on each
# configure so that none outlives its target.
set(SOFTSHADOWS_FUZZ_MANIFESTS "${CMAKE_BINARY_DIR}/fuzzers")
file(REMOVE_RECURSE "${SOFTSHADOWS_FUZZ_MANIFESTS}")

if (SOFTSHADOWS_FUZZ)
  if (NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SOFTSHADOWS_FUZZ needs clang (libFuzzer), not "
      "${CMAKE_CXX_COMPILER_ID} (${CMAKE_CXX_COMPILER}): configure a fresh build folder with "
      "CC=clang-14 CXX=clang++-14, or run scripts/fuzz.sh.")
  endif ()
  # Fails here, not at the first fuzz target, when clang's runtime is missing.
  include(CheckCXXSourceCompiles)
  set(CMAKE_REQUIRED_FLAGS "-fsanitize=fuzzer,address,undefined")
  check_cxx_source_compiles([[
    #include <cstddef>
    #include <cstdint>
    extern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }
  ]] SOFTSHADOWS_HAVE_LIBFUZZER)
  unset(CMAKE_REQUIRED_FLAGS)
  if (NOT SOFTSHADOWS_HAVE_LIBFUZZER)
    message(FATAL_ERROR "SOFTSHADOWS_FUZZ: ${CMAKE_CXX_COMPILER} cannot link "
      "-fsanitize=fuzzer,address,undefined (on Debian 12: apt-get install libclang-rt-14-dev).")
  endif ()
  # Libraries get the fuzzer's coverage without its main(); only the fuzz
  # targets link libFuzzer itself (-fsanitize=fuzzer below).
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
    -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
  add_custom_target(fuzzers)
endif ()

#[==[
softshadows_add_fuzzer(<name>
  SOURCES <source>...        # define LLVMFuzzerTestOneInput (and optionally LLVMFuzzerInitialize)
  [LIBRARIES <target>...]
  [DEFINITIONS <name=value>...] # compile definitions of the target's sources
  [CORPUS <folder>]          # Testing/Fuzz/corpus/<folder> and regressions/<folder>; default <name>
  [DICTIONARY <file>]        # relative to Testing/Fuzz; a libFuzzer -dict
  [MAX_LEN <bytes>])         # libFuzzer -max_len; default 4096

SOFTSHADOWS_FUZZ on: the libFuzzer program <name>, part of the `fuzzers`
target, run by scripts/fuzz.sh. Off, with BUILD_TESTING: <name>Regressions,
which runs every file of the corpus and regression folders once, as the test
Fuzz.<name>.
#]==]
function (softshadows_add_fuzzer name)
  cmake_parse_arguments(PARSE_ARGV 1 fuzzer "" "CORPUS;DICTIONARY;MAX_LEN"
    "SOURCES;LIBRARIES;DEFINITIONS")
  if (fuzzer_UNPARSED_ARGUMENTS OR NOT fuzzer_SOURCES)
    message(FATAL_ERROR "softshadows_add_fuzzer(${name}): needs SOURCES; unparsed arguments: "
      "${fuzzer_UNPARSED_ARGUMENTS}")
  endif ()
  if (NOT fuzzer_CORPUS)
    set(fuzzer_CORPUS "${name}")
  endif ()
  if (NOT fuzzer_MAX_LEN)
    set(fuzzer_MAX_LEN 4096)
  endif ()
  set(corpus "${SOFTSHADOWS_FUZZ_DIR}/corpus/${fuzzer_CORPUS}")
  set(regressions "${SOFTSHADOWS_FUZZ_DIR}/regressions/${fuzzer_CORPUS}")
  set(dictionary "")
  if (fuzzer_DICTIONARY)
    set(dictionary "${SOFTSHADOWS_FUZZ_DIR}/${fuzzer_DICTIONARY}")
  endif ()
  # The regressions folder may not exist yet: a new target has none.
  if (NOT IS_DIRECTORY "${corpus}")
    message(FATAL_ERROR "softshadows_add_fuzzer(${name}): no corpus folder ${corpus}")
  endif ()

  if (SOFTSHADOWS_FUZZ)
    add_executable(${name} ${fuzzer_SOURCES})
    target_link_libraries(${name} PRIVATE ${fuzzer_LIBRARIES})
    target_compile_definitions(${name} PRIVATE ${fuzzer_DEFINITIONS})
    target_link_options(${name} PRIVATE -fsanitize=fuzzer)
    add_dependencies(fuzzers ${name})
    # key=value lines; fuzz.sh copies the corpus and regressions before
    # running, so the source tree is never written.
    file(GENERATE OUTPUT "${SOFTSHADOWS_FUZZ_MANIFESTS}/${name}.txt" CONTENT
"name=${name}
binary=$<TARGET_FILE:${name}>
corpus=${corpus}
regressions=${regressions}
dictionary=${dictionary}
max_len=${fuzzer_MAX_LEN}
")
  elseif (BUILD_TESTING)
    add_executable(${name}Regressions ${fuzzer_SOURCES}
      "${SOFTSHADOWS_FUZZ_DIR}/FuzzRegressionMain.cxx")
    target_link_libraries(${name}Regressions PRIVATE ${fuzzer_LIBRARIES})
    target_compile_definitions(${name}Regressions PRIVATE ${fuzzer_DEFINITIONS})
    add_test(NAME "Fuzz.${name}" COMMAND ${name}Regressions "${corpus}" "${regressions}")
    # A hang is a finding too.
    set_tests_properties("Fuzz.${name}" PROPERTIES TIMEOUT 120)
    softshadows_sanitizer_environment("Fuzz.${name}")
  endif ()
endfunction ()
