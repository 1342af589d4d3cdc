// SPDX-License-Identifier: Apache-2.0
#include "ctab/profiles/point_noise.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ctab::gen {

namespace {
constexpr std::size_t kMinRunningSurfaceRuns = 20;  // fewer flat runs: estimate over the whole profile
}  // namespace

double estimate_point_noise_m(const std::vector<double>& y, const std::vector<double>& z) {
  const std::size_t n = y.size();
  if (n < 4 || z.size() != n) throw std::invalid_argument("estimate_point_noise_m: needs at least 4 points");
  std::vector<double> s(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
  std::vector<double> normal_residual, running_surface;  // all runs; runs flatter than 45 degrees
  normal_residual.reserve(n - 3);
  for (std::size_t i = 0; i + 3 < n; ++i) {
    double c[4], norm2 = 0.0;
    for (std::size_t j = 0; j < 4; ++j) {
      double product = 1.0;
      for (std::size_t k = 0; k < 4; ++k)
        if (k != j) product *= s[i + j] - s[i + k];
      c[j] = 1.0 / product;
      norm2 += c[j] * c[j];
    }
    double dy = 0.0, dz = 0.0;
    for (std::size_t j = 0; j < 4; ++j) {
      dy += c[j] * y[i + j];
      dz += c[j] * z[i + j];
    }
    const double ty = y[i + 3] - y[i], tz = z[i + 3] - z[i], chord = std::hypot(ty, tz);
    normal_residual.push_back(std::abs(dz * ty - dy * tz) / (chord * std::sqrt(norm2)));
    if (std::abs(tz) < std::abs(ty)) running_surface.push_back(normal_residual.back());
  }
  if (running_surface.size() >= kMinRunningSurfaceRuns) normal_residual.swap(running_surface);
  const auto middle = normal_residual.begin() + static_cast<std::ptrdiff_t>(normal_residual.size() / 2);
  std::nth_element(normal_residual.begin(), middle, normal_residual.end());
  constexpr double kGaussianMedianAbs = 0.6744897501960817;  // median |X| of a standard normal X
  return *middle / kGaussianMedianAbs;
}

}  // namespace ctab::gen
