// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: any bytes as the text of a scene file, through the parser and
// checks of Apps/softshadows/SceneFile.cxx. A malformed scene must end in an
// InputError (the program's exit code 2 with one message); anything else
// escaping, a crash, a hang or a sanitizer report is a bug.

#include "JsonValues.h"
#include "SceneFile.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  // In data/, whose mesh.obj lets `"file": "mesh.obj"` pass the existence check.
  static const std::filesystem::path file =
    std::filesystem::path(SOFTSHADOWS_FUZZ_DATA) / "scene.json";
  try
  {
    softshadows::ParseScene(std::string(reinterpret_cast<const char*>(data), size), file);
  }
  catch (const softshadows::InputError&)
  {
    // The parser's own answer to a bad scene.
  }
  return 0;
}
