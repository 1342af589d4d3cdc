// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Piecewise-linear interpolation of sampled columns (internal to ctab::wheelrail): a patch's samples in s, rail y,
//! normal angle and separation.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace ctab::gen {

//! y between x[upper - 1] and x[upper] (upper clamped to [1, size - 1]), linear.
inline double interpolate_in(const std::vector<double>& x, const std::vector<double>& y, std::size_t upper, double at) {
  const std::size_t i = std::clamp<std::size_t>(upper, 1, x.size() - 1);
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return (1 - t) * y[i - 1] + t * y[i];
}

//! y at `at`, linear in the increasing x (extrapolated from the end segments).
inline double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  return interpolate_in(x, y, static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin()), at);
}

//! interpolate() at non-decreasing positions (a strip grid's centres), its segment search walked on from the last
//! query instead of a binary search per query: the same values.
class ForwardInterpolation {
 public:
  ForwardInterpolation(const std::vector<double>& x, const std::vector<double>& y) : x_(x), y_(y) {}
  double operator()(double at) {
    if (upper_ > 0 && x_[upper_ - 1] > at)
      upper_ = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), at) - x_.begin());
    while (upper_ < x_.size() && x_[upper_] <= at) ++upper_;
    return interpolate_in(x_, y_, upper_, at);
  }

 private:
  const std::vector<double>& x_;
  const std::vector<double>& y_;
  std::size_t upper_ = 0;  // the first x beyond the last query
};

}  // namespace ctab::gen
