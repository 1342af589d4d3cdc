// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Summed-chord arc length of a point profile, the parameter of its smoothing (smoothing_spline.hpp,
//! adaptive_smoothing.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

namespace ctab::gen {

//! Arc length s_i = s_{i-1} + |p_i - p_{i-1}| [m] and trapezoid weights w_i = (s_{i+1} - s_{i-1}) / 2 [m] (one-sided
//! at the ends) of points (y, z) [m].
inline void summed_chord_arc_length(const std::vector<double>& y, const std::vector<double>& z, std::vector<double>& s,
                                    std::vector<double>& w) {
  const std::size_t n = y.size();
  s.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
  w.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) w[i] = 0.5 * (s[std::min(i + 1, n - 1)] - s[i == 0 ? 0 : i - 1]);
}

}  // namespace ctab::gen
