// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * Frame timing of several techniques in one window, as `bench` and `gallery`
 * report it.
 */

#ifndef softshadows_Benchmark_h
#define softshadows_Benchmark_h

#include "Progress.h"
#include "Techniques.h"

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

class vtkRenderWindow;
class vtkRenderer;

namespace softshadows
{
struct Timing
{
  std::string Technique;
  int Frames = 0;
  double MeanMs = 0.0;
  double MedianMs = 0.0;
  double RatioToHard = 0.0;   ///< 0 when `hard` was not timed
  double CpuMedianMs = -1.0;  ///< the technique's own CPU work a frame; < 0: not reported
  double PassMedianMs = -1.0; ///< its own light-space pass a frame; < 0: not reported
  /// GPU time of the framework's steps a frame (vtkSoftShadowPass's timer
  /// queries): light-space maps, screen-space passes, the scene with its
  /// receivers; < 0 for VTK's own pass.
  double LightSpaceMedianMs = -1.0;
  double ScreenSpaceMedianMs = -1.0;
  double ReceiversMedianMs = -1.0;
  int MapSize = 0;
  std::array<int, 2> Size{ 0, 0 };
};

/**
 * Draws `frames` timed frames of every technique after `warmUp` untimed
 * rounds of all, in blocks of up to 5 frames a technique, each block after
 * an untimed frame of it (the mappers rebuild their shaders when the render
 * pass changes), the techniques taking turns; moves the first light a
 * little along a small orbit before each frame so every technique redraws
 * its shadow maps. A frame's time runs from the start of Render() to
 * glFinish() returning. Leaves the light where it started. Shows its
 * progress on `progress`.
 */
std::vector<Timing> RunBenchmark(vtkRenderWindow* window, vtkRenderer* renderer,
  std::vector<TechniqueInstance>& techniques, int frames, int warmUp, int mapSize,
  Progress* progress = nullptr);

/// A table for people.
void PrintTimingTable(std::ostream& os, const std::vector<Timing>& timings);

/// One compact JSON object per line, keys as SPEC.md fixes them.
void PrintTimingJson(std::ostream& os, const std::vector<Timing>& timings);
}

#endif
