// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/strip_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "ctab/core/error.hpp"

namespace ctab::gen {

namespace {

// Slope at node k from the parabola through k-1, k, k+1 (one-sided at the ends): exact for quadratics.
double node_slope(const std::vector<double>& y, const std::vector<double>& h, std::size_t k) {
  const std::size_t n = y.size();
  const std::size_t i0 = (k == 0) ? 0 : (k == n - 1 ? n - 3 : k - 1);
  const double x0 = y[i0], x1 = y[i0 + 1], x2 = y[i0 + 2];
  const double f0 = h[i0], f1 = h[i0 + 1], f2 = h[i0 + 2];
  const double x = y[k];
  // derivative of the Lagrange interpolant at x
  return f0 * ((x - x1) + (x - x2)) / ((x0 - x1) * (x0 - x2)) + f1 * ((x - x0) + (x - x2)) / ((x1 - x0) * (x1 - x2)) +
         f2 * ((x - x0) + (x - x1)) / ((x2 - x0) * (x2 - x1));
}

}  // namespace

double strip_count(const GapProfile& gap, double strip_width_m) noexcept {
  if (gap.y_m.empty()) return 0.0;
  // Centres (k + offset) w for k in [first, last].
  const double first = std::ceil(gap.y_m.front() / strip_width_m - grid_centre_offset(gap.strip_alignment));
  const double last = std::floor(gap.y_m.back() / strip_width_m - grid_centre_offset(gap.strip_alignment));
  return last - first + 1.0;
}

StripGrid make_strip_grid(const GapProfile& gap, double strip_width_m) {
  StripGrid grid;
  fill_strip_grid(gap, strip_width_m, grid);
  return grid;
}

void fill_strip_grid(const GapProfile& gap, double strip_width_m, StripGrid& grid) {
  if (!(std::isfinite(strip_width_m) && strip_width_m > 0.0))
    throw InputError("--strip-width", 0,
                     "strip width must be positive and finite, got " + std::to_string(strip_width_m));
  validate(gap);
  const double strips = strip_count(gap, strip_width_m);
  if (strips > static_cast<double>(kMaxStripsPerPatch))
    throw InputError("--strip-width", 0,
                     "the gap needs " + std::to_string(static_cast<long long>(strips)) + " strips of width " +
                         std::to_string(strip_width_m) + " m (max " + std::to_string(kMaxStripsPerPatch) +
                         "): increase the strip width");
  const double y_first = gap.y_m.front(), y_last = gap.y_m.back();
  const double offset = grid_centre_offset(gap.strip_alignment);
  const auto first = static_cast<long>(std::ceil(y_first / strip_width_m - offset));
  const auto last = static_cast<long>(std::floor(y_last / strip_width_m - offset));
  if (last - first + 1 < 3)
    throw InputError(gap.source, 0,
                     "the gap's y-range holds fewer than 3 strips of width " + std::to_string(strip_width_m) + " m");
  grid.strip_width_m = strip_width_m;
  grid.centre_offset = offset;
  const auto count = static_cast<std::size_t>(last - first + 1);
  grid.y_m.resize(count);
  grid.h_m.resize(count);
  grid.A_per_m.resize(count);
  grid.B_per_m.resize(count);
  std::size_t segment = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const double y = (static_cast<double>(first + static_cast<long>(i)) + offset) * strip_width_m;
    while (segment + 2 < gap.size() && gap.y_m[segment + 1] < y) ++segment;
    const double y0 = gap.y_m[segment], y1 = gap.y_m[segment + 1];
    const double width = y1 - y0;
    const double s = std::clamp((y - y0) / width, 0.0, 1.0);
    const double d0 = node_slope(gap.y_m, gap.h_m, segment) * width;
    const double d1 = node_slope(gap.y_m, gap.h_m, segment + 1) * width;
    const double s2 = s * s, s3 = s2 * s;
    grid.y_m[i] = y;
    grid.h_m[i] = (2 * s3 - 3 * s2 + 1) * gap.h_m[segment] + (s3 - 2 * s2 + s) * d0 +
                  (-2 * s3 + 3 * s2) * gap.h_m[segment + 1] + (s3 - s2) * d1;
    grid.A_per_m[i] = (1 - s) * gap.A_per_m[segment] + s * gap.A_per_m[segment + 1];
    grid.B_per_m[i] = (1 - s) * gap.B_per_m[segment] + s * gap.B_per_m[segment + 1];
  }
}

}  // namespace ctab::gen
