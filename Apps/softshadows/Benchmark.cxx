// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
#include "Benchmark.h"

#include "vtkSoftShadowPass.h"

#include "vtkShadowVTKVersion.h"
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMath.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <ostream>

namespace softshadows
{
namespace
{
/**
 * Moves a light around a small horizontal circle centred on its position.
 * The radius is 2% of the light's distance to its focal point, so the light
 * direction changes by about a degree, enough to invalidate every shadow map
 * but not to change the picture's character.
 */
class LightOrbit
{
public:
  explicit LightOrbit(vtkLight* light)
    : Light(light)
  {
    if (this->Light)
    {
      this->Light->GetPosition(this->Start);
      double focalPoint[3];
      this->Light->GetFocalPoint(focalPoint);
      this->Radius = 0.02 * std::sqrt(vtkMath::Distance2BetweenPoints(this->Start, focalPoint));
    }
  }

  ~LightOrbit()
  {
    if (this->Light)
    {
      this->Light->SetPosition(this->Start);
    }
  }

  void Step()
  {
    if (!this->Light)
    {
      return;
    }
    // 12 positions per turn: every frame a new one.
    this->Angle += 2.0 * vtkMath::Pi() / 12.0;
    this->Light->SetPosition(this->Start[0] + this->Radius * std::cos(this->Angle), this->Start[1],
      this->Start[2] + this->Radius * std::sin(this->Angle));
  }

  LightOrbit(const LightOrbit&) = delete;
  LightOrbit& operator=(const LightOrbit&) = delete;

private:
  vtkLight* Light;
  double Start[3] = { 0.0, 0.0, 0.0 };
  double Radius = 0.0;
  double Angle = 0.0;
};

vtkLight* FirstLight(vtkRenderer* renderer)
{
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal();
  return lights->GetNextItem();
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

// Thousandths, so that the JSON prints 12.3 rather than 12.300000000000001.
double Round3(double value)
{
  return std::round(value * 1000.0) / 1000.0;
}

// Timed frames a technique draws in a row.
constexpr int BlockFrames = 5;
}

//------------------------------------------------------------------------------
std::vector<Timing> RunBenchmark(vtkRenderWindow* window, vtkRenderer* renderer,
  std::vector<TechniqueInstance>& techniques, int frames, int warmUp, int mapSize,
  Progress* progress)
{
  using Clock = std::chrono::steady_clock;
  std::vector<std::vector<double>> times(techniques.size());
  std::vector<std::vector<double>> cpu(techniques.size());
  std::vector<std::vector<double>> pass(techniques.size());
  std::vector<std::array<std::vector<double>, 3>> steps(techniques.size());
  // Frames are timed in blocks of a technique, each after an untimed frame
  // of it, the techniques taking turns block by block. Interleaved frame by
  // frame, every frame would switch the mappers' render pass, and VTK's
  // mappers build their shader sources again whenever it changes: a cost no
  // application drawing with one technique pays. Taking turns spreads the
  // machine's drift over all of them.
  const int blocks = (frames + BlockFrames - 1) / BlockFrames;
  const int perTechnique = warmUp + blocks + frames;
  const double total = static_cast<double>(perTechnique * techniques.size());
  int drawn = 0;
  std::vector<int> counts(techniques.size(), 0); // frames each technique drew
  LightOrbit orbit(FirstLight(renderer));
  auto draw = [&](std::size_t t, bool timed)
  {
    orbit.Step();
    renderer->SetPass(techniques[t].Pass);
    // A frame of `reference` takes seconds: its samples count too.
    const double done = static_cast<double>(drawn++);
    const std::string what = "bench: frame " + std::to_string(++counts[t]) + "/" +
      std::to_string(perTechnique) + ", " + techniques[t].Spec;
    Progress::Observation samples;
    if (progress)
    {
      progress->Show(what, done / total);
      samples = progress->Observe(techniques[t].Shadows,
        [&](double fraction) { progress->Show(what, (done + fraction) / total); });
    }
    const auto start = Clock::now();
    window->Render();
    window->MakeCurrent();
    glFinish();
    const std::chrono::duration<double, std::milli> elapsed = Clock::now() - start;
    if (!timed)
    {
      return;
    }
    times[t].push_back(elapsed.count());
    if (const vtkSoftShadowPass* shadows = techniques[t].Shadows)
    {
      steps[t][0].push_back(shadows->GetLightSpaceTime());
      steps[t][1].push_back(shadows->GetScreenSpaceTime());
      steps[t][2].push_back(shadows->GetReceiversTime());
      // The technique's own work, where it times it.
      if (shadows->GetTechniqueCPUTime() >= 0.0)
      {
        cpu[t].push_back(shadows->GetTechniqueCPUTime());
      }
      if (shadows->GetTechniqueGPUTime() >= 0.0)
      {
        pass[t].push_back(shadows->GetTechniqueGPUTime());
      }
    }
  };
  for (int round = 0; round < warmUp; ++round)
  {
    for (std::size_t t = 0; t < techniques.size(); ++t)
    {
      draw(t, false);
    }
  }
  for (int first = 0; first < frames; first += BlockFrames)
  {
    for (std::size_t t = 0; t < techniques.size(); ++t)
    {
      draw(t, false);
      for (int frame = first; frame < std::min(first + BlockFrames, frames); ++frame)
      {
        draw(t, true);
      }
    }
  }

  std::vector<Timing> timings;
  double hardMean = 0.0;
  for (std::size_t t = 0; t < techniques.size(); ++t)
  {
    Timing timing;
    timing.Technique = techniques[t].Spec;
    timing.Frames = frames;
    timing.MeanMs = std::accumulate(times[t].begin(), times[t].end(), 0.0) / frames;
    timing.MedianMs = Median(times[t]);
    timing.CpuMedianMs = cpu[t].empty() ? -1.0 : Median(cpu[t]);
    timing.PassMedianMs = pass[t].empty() ? -1.0 : Median(pass[t]);
    timing.LightSpaceMedianMs = steps[t][0].empty() ? -1.0 : Median(steps[t][0]);
    timing.ScreenSpaceMedianMs = steps[t][1].empty() ? -1.0 : Median(steps[t][1]);
    timing.ReceiversMedianMs = steps[t][2].empty() ? -1.0 : Median(steps[t][2]);
    timing.MapSize = techniques[t].Shadows ? techniques[t].Shadows->GetMapSize() : mapSize;
    timing.Size = { window->GetSize()[0], window->GetSize()[1] };
    hardMean = timing.Technique == "hard" ? timing.MeanMs : hardMean;
    timings.push_back(timing);
  }
  for (Timing& timing : timings)
  {
    timing.RatioToHard = hardMean > 0.0 ? timing.MeanMs / hardMean : 0.0;
  }
  return timings;
}

//------------------------------------------------------------------------------
void PrintTimingTable(std::ostream& os, const std::vector<Timing>& timings)
{
  if (timings.empty())
  {
    return;
  }
  const Timing& first = timings.front();
  os << "Frame times, " << first.Size[0] << "x" << first.Size[1] << " pixels, shadow maps "
     << first.MapSize << "^2, " << first.Frames << " frames each (light moving):\n";
  os << std::left << std::setw(22) << "technique" << std::right << std::setw(11) << "mean ms"
     << std::setw(11) << "median ms" << std::setw(10) << "x hard";
  // The framework's steps on the GPU, then the techniques' own CPU work
  // (silhouette searches) and own light-space pass (the silhouette pass), as
  // columns where any technique reports them.
  std::vector<std::pair<double Timing::*, const char*>> columns;
  for (const auto& column : { std::make_pair(&Timing::LightSpaceMedianMs, "maps GPU ms"),
         std::make_pair(&Timing::ScreenSpaceMedianMs, "screen GPU ms"),
         std::make_pair(&Timing::ReceiversMedianMs, "scene GPU ms"),
         std::make_pair(&Timing::CpuMedianMs, "own CPU ms"),
         std::make_pair(&Timing::PassMedianMs, "own pass ms") })
  {
    if (std::any_of(timings.begin(), timings.end(),
          [&column](const Timing& timing) { return timing.*column.first >= 0.0; }))
    {
      columns.push_back(column);
      os << std::setw(16) << column.second;
    }
  }
  os << "\n";
  for (const Timing& timing : timings)
  {
    os << std::left << std::setw(22) << timing.Technique << std::right << std::fixed
       << std::setprecision(2) << std::setw(11) << timing.MeanMs << std::setw(11) << timing.MedianMs
       << std::setw(10) << timing.RatioToHard;
    for (const auto& column : columns)
    {
      os << std::setw(16);
      if (timing.*column.first >= 0.0)
      {
        os << timing.*column.first;
      }
      else
      {
        os << "";
      }
    }
    os << "\n";
  }
  os.unsetf(std::ios_base::floatfield);
}

//------------------------------------------------------------------------------
void PrintTimingJson(std::ostream& os, const std::vector<Timing>& timings)
{
  for (const Timing& timing : timings)
  {
    nlohmann::ordered_json line;
    line["technique"] = timing.Technique;
    line["frames"] = timing.Frames;
    line["mean_ms"] = Round3(timing.MeanMs);
    line["median_ms"] = Round3(timing.MedianMs);
    line["ratio_to_hard"] = Round3(timing.RatioToHard);
    line["map_size"] = timing.MapSize;
    line["size"] = timing.Size;
    if (timing.LightSpaceMedianMs >= 0.0)
    {
      line["light_space_median_ms"] = Round3(timing.LightSpaceMedianMs);
      line["screen_space_median_ms"] = Round3(timing.ScreenSpaceMedianMs);
      line["receivers_median_ms"] = Round3(timing.ReceiversMedianMs);
    }
    if (timing.CpuMedianMs >= 0.0)
    {
      line["cpu_median_ms"] = Round3(timing.CpuMedianMs);
    }
    if (timing.PassMedianMs >= 0.0)
    {
      line["pass_median_ms"] = Round3(timing.PassMedianMs);
    }
    os << line.dump() << "\n";
  }
  os.flush();
}
}
