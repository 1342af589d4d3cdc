// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Synthetic measured profiles: points taken from a profile table at a fixed spacing, with a change (a worn
//! hollow, seeded measurement noise) added to z. Used by the stability matrix and the smoothing tests.
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "ctab/profiles/profile.hpp"

namespace ctab::gen {

//! Point data (y, z) [m], increasing y.
struct SampledPoints {
  std::vector<double> y_m, z_m;
};

//! How the points are spaced: equal lateral steps, or equal steps along the profile (steep flanks keep their
//! density, as a profilometer's points do).
enum class PointSpacing : std::int8_t { Lateral = 0, ArcLength = 1 };

//! Points of `table` every `step_m` over its y-range, z + change(y).
[[nodiscard]] SampledPoints sample_points(const ProfileTable& table, double step_m, PointSpacing spacing,
                                          const std::function<double(double)>& change);

//! Seeded measurement noise in z [m], the same sequence on every run: uniform in [-amplitude, amplitude] or
//! Gaussian with standard deviation `amplitude`.
class SeededNoise {
 public:
  enum class Shape : std::int8_t { Uniform = 0, Gaussian = 1 };
  SeededNoise(Shape shape, double amplitude_m, std::uint32_t seed)
      : shape_(shape), amplitude_(amplitude_m), rng_(seed) {}
  double operator()(double /*y_m*/) {
    return shape_ == Shape::Uniform ? std::uniform_real_distribution<double>(-amplitude_, amplitude_)(rng_)
                                    : std::normal_distribution<double>(0.0, amplitude_)(rng_);
  }

 private:
  Shape shape_;
  double amplitude_;
  std::mt19937 rng_;
};

}  // namespace ctab::gen
