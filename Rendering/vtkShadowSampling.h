/**
 * @file   vtkShadowSampling.h
 * @brief  Deterministic sample sets shared by the techniques (private).
 *
 * Every set comes from a fixed seed and maps the generator's raw output by
 * hand, since std distributions differ between standard libraries: the same
 * images on every machine.
 */

#ifndef vtkShadowSampling_h
#define vtkShadowSampling_h

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace vtkShadowSampling
{
/// Uniform in [0, 1) from a 32-bit generator: 24 bits, the same everywhere.
inline double Uniform(std::mt19937& generator)
{
  return (generator() >> 8) * (1.0 / 16777216.0);
}

/**
 * `count` Poisson-disk points in [-1,1]^2 (or, `inDisc`, in the unit disc),
 * the first at the origin when `originFirst`. Dart throwing with a minimum
 * distance that shrinks when darts keep missing, so any prefix of the set is
 * well spread.
 */
inline std::vector<glm::vec2> PoissonDisk(
  int count, unsigned int seed, bool inDisc, bool originFirst)
{
  std::vector<glm::vec2> points;
  if (originFirst)
  {
    points.emplace_back(0.0f);
  }
  std::mt19937 generator(seed);
  float spacing = inDisc ? 0.5f : 0.6f;
  int misses = 0;
  while (static_cast<int>(points.size()) < count)
  {
    const glm::vec2 candidate(2.0 * Uniform(generator) - 1.0, 2.0 * Uniform(generator) - 1.0);
    const bool free = (!inDisc || glm::length(candidate) <= 1.0f) &&
      std::all_of(points.begin(), points.end(),
        [&](const glm::vec2& p) { return glm::distance(p, candidate) >= spacing; });
    if (free)
    {
      points.push_back(candidate);
      misses = 0;
    }
    else if (++misses > 2000)
    {
      spacing *= 0.9f;
      misses = 0;
    }
  }
  return points;
}

/// Shirley & Chiu's concentric mapping: uniform square to uniform disc with
/// low distortion, so stratification survives.
inline glm::dvec2 ConcentricDisc(double u, double v)
{
  const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
  if (a == 0.0 && b == 0.0)
  {
    return glm::dvec2(0.0);
  }
  const double quarterPi = 0.25 * glm::pi<double>();
  if (std::abs(a) > std::abs(b))
  {
    return a * glm::dvec2(std::cos(quarterPi * b / a), std::sin(quarterPi * b / a));
  }
  return b * glm::dvec2(std::sin(quarterPi * a / b), std::cos(quarterPi * a / b));
}

/// Jittered k x k stratification of the unit disc, k = floor(sqrt(count));
/// one sample at the centre when k is 1.
inline std::vector<glm::dvec2> StratifiedDisc(int count, unsigned int seed)
{
  const int k = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(count))));
  if (k == 1)
  {
    return { glm::dvec2(0.0) };
  }
  std::mt19937 generator(seed);
  std::vector<glm::dvec2> samples;
  samples.reserve(static_cast<size_t>(k) * k);
  for (int j = 0; j < k; ++j)
  {
    for (int i = 0; i < k; ++i)
    {
      const double u = (i + Uniform(generator)) / k;
      const double v = (j + Uniform(generator)) / k;
      samples.push_back(ConcentricDisc(u, v));
    }
  }
  return samples;
}
}

#endif
