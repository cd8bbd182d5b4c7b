// SPDX-FileCopyrightText: Copyright (c) 2026 the SoftShadows authors
// SPDX-License-Identifier: BSD-3-Clause
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

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

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

/// Jittered columns x rows stratification of the unit disc (the concentric
/// map of the square's strata).
inline std::vector<glm::dvec2> StratifiedDisc(int columns, int rows, unsigned int seed)
{
  std::mt19937 generator(seed);
  std::vector<glm::dvec2> samples;
  samples.reserve(static_cast<size_t>(columns) * rows);
  for (int j = 0; j < rows; ++j)
  {
    for (int i = 0; i < columns; ++i)
    {
      const double u = (i + Uniform(generator)) / columns;
      const double v = (j + Uniform(generator)) / rows;
      samples.push_back(ConcentricDisc(u, v));
    }
  }
  return samples;
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
  return StratifiedDisc(k, k, seed);
}

/// The radical inverse of i in `base`: Halton's sequence.
inline double RadicalInverse(unsigned int i, unsigned int base)
{
  const double inverse = 1.0 / base;
  double value = 0.0;
  for (double scale = inverse; i > 0; i /= base, scale *= inverse)
  {
    value += (i % base) * scale;
  }
  return value;
}

/**
 * `count` points in the unit ball whose projection along any direction is
 * uniform on the unit disc, as a spherical light's is from every receiver:
 * the first three coordinates of points uniform on the 3-sphere in 4D (a
 * plane projection of which is uniform on the disc: Archimedes' theorem one
 * dimension up), x, y = ConcentricDisc(u, v) and
 * z = sqrt(1 - x^2 - y^2) cos(2 pi w). (u, v, w): Halton's sequence in bases
 * 2, 3, 5, shifted by a random offset (Cranley-Patterson), so that the
 * points are well spread seen from every side, not only along z. One point,
 * at the centre, when `count` is 1.
 */
inline std::vector<glm::dvec3> HaltonBall(int count, unsigned int seed)
{
  if (count <= 1)
  {
    return { glm::dvec3(0.0) };
  }
  std::mt19937 generator(seed);
  const glm::dvec3 shift(Uniform(generator), Uniform(generator), Uniform(generator));
  std::vector<glm::dvec3> samples;
  samples.reserve(static_cast<size_t>(count));
  for (int i = 1; i <= count; ++i)
  {
    const glm::dvec3 u = glm::fract(
      glm::dvec3(RadicalInverse(i, 2), RadicalInverse(i, 3), RadicalInverse(i, 5)) + shift);
    const glm::dvec2 d = ConcentricDisc(u.x, u.y);
    const double z =
      std::sqrt(std::max(0.0, 1.0 - glm::dot(d, d))) * std::cos(2.0 * glm::pi<double>() * u.z);
    samples.emplace_back(d.x, d.y, z);
  }
  return samples;
}
}

#endif
