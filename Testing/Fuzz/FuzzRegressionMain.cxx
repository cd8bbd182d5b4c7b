// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
// Runs a fuzz target's LLVMFuzzerTestOneInput once on each file given, or on
// each file of each folder given, without libFuzzer: the regression test of
// every build (cmake/SoftShadowsFuzz.cmake). A crash or a sanitizer report
// fails the test; an input that returns is a pass.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);
// Optional, as in libFuzzer.
extern "C" __attribute__((weak)) int LLVMFuzzerInitialize(int* argc, char*** argv);

int main(int argc, char* argv[])
{
  if (LLVMFuzzerInitialize)
  {
    LLVMFuzzerInitialize(&argc, &argv);
  }
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i)
  {
    const std::filesystem::path argument(argv[i]);
    if (!std::filesystem::exists(argument))
    {
      // A target's regressions folder appears with its first regression.
      std::cout << "no " << argument.string() << " (no inputs there yet)\n";
    }
    else if (std::filesystem::is_directory(argument))
    {
      for (const auto& entry : std::filesystem::directory_iterator(argument))
      {
        // Hidden files (.gitkeep and the like) are not inputs.
        if (entry.is_regular_file() && entry.path().filename().string()[0] != '.')
        {
          inputs.push_back(entry.path());
        }
      }
    }
    else
    {
      inputs.push_back(argument);
    }
  }
  // One order on every machine, so a failure names the same input.
  std::sort(inputs.begin(), inputs.end());
  for (const auto& input : inputs)
  {
    std::ifstream stream(input, std::ios::binary);
    if (!stream)
    {
      std::cerr << "cannot read " << input.string() << "\n";
      return 1;
    }
    const std::vector<char> bytes(
      (std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
    // Printed first: a crash leaves the input's name as the last line.
    std::cout << "running " << input.string() << " (" << bytes.size() << " bytes)" << std::endl;
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << inputs.size() << " inputs passed\n";
  return inputs.empty() ? 1 : 0;
}
