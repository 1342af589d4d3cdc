// SPDX-License-Identifier: Apache-2.0
// bem2d element grid: the gap resampled at element centres over the potential contact area.
#include <algorithm>
#include <cmath>
#include <limits>

#include "bem2d_internal.hpp"
#include "ctab/contact/bem2d_options.hpp"

namespace ctab::gen::bem2d {

namespace {

struct GapSample {
  double h = 0.0, A = 0.0;
};

// h by the cubic spline through the samples with second derivatives h'' = 2B at both ends of the segment
// (exact for cubics; CONTACT-like datum), A linearly. y must lie inside the data.
GapSample sample_gap(const GapProfile& gap, double y) {
  const auto upper = std::upper_bound(gap.y_m.begin(), gap.y_m.end(), y);
  const std::size_t k =
      std::min<std::size_t>(static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - gap.y_m.begin() - 1, 0)),
                            gap.size() - 2);
  const double step = gap.y_m[k + 1] - gap.y_m[k], t = (y - gap.y_m[k]) / step;
  const double M0 = 2.0 * gap.B_per_m[k], M1 = 2.0 * gap.B_per_m[k + 1];
  GapSample s;
  s.h = (1 - t) * gap.h_m[k] + t * gap.h_m[k + 1] - step * step / 6.0 * t * (1 - t) * ((2 - t) * M0 + (1 + t) * M1);
  s.A = (1 - t) * gap.A_per_m[k] + t * gap.A_per_m[k + 1];
  return s;
}

// Row indices (centre y = (j + offset) dy) whose centres lie inside the gap data.
void data_rows(const GapProfile& gap, double dy, GridAlignment alignment, long& first, long& last) {
  first = static_cast<long>(std::ceil(gap.y_m.front() / dy - grid_centre_offset(alignment)));
  last = static_cast<long>(std::floor(gap.y_m.back() / dy - grid_centre_offset(alignment)));
}

double row_centre(long j, double dy, GridAlignment alignment) {
  return (static_cast<double>(j) + grid_centre_offset(alignment)) * dy;
}

}  // namespace

double deepest_separation(const GapProfile& gap, double dy, GridAlignment alignment) {
  long first = 0, last = 0;
  data_rows(gap, dy, alignment, first, last);
  double deepest = std::numeric_limits<double>::infinity();
  for (long j = first; j <= last; ++j) deepest = std::min(deepest, sample_gap(gap, row_centre(j, dy, alignment)).h);
  return deepest;
}

SolveStatus make_element_grid(const GapProfile& gap, double dx, double dy, GridAlignment alignment,
                              double covered_approach, ElementGrid& grid, std::string& why) {
  long first = 0, last = 0;
  data_rows(gap, dy, alignment, first, last);
  const double column_offset = grid_centre_offset(alignment);  // nearest element centres at x = -/+ offset dx
  if (last - first + 1 > static_cast<long>(16 * kBem2dMaxElementsPerSide) || last < first) {
    why = "element width dy does not suit the gap's y-range";
    return SolveStatus::InvalidInput;
  }
  // Rows that can touch and the widest half-extent along x.
  long lo = last + 1, hi = first - 1;
  double half_extent = 0.0;
  for (long j = first; j <= last; ++j) {
    const GapSample s = sample_gap(gap, row_centre(j, dy, alignment));
    if (s.h + s.A * column_offset * column_offset * dx * dx >= covered_approach) continue;
    lo = std::min(lo, j);
    hi = std::max(hi, j);
    half_extent = std::max(half_extent, std::sqrt((covered_approach - s.h) / s.A));
  }
  if (hi < lo) return SolveStatus::NoContact;
  // One free row and column on every side.
  lo = std::max(lo - 1, first);
  hi = std::min(hi + 1, last);
  // Columns: centres at (k + offset) dx for |centre| < (half_columns - offset + 1/2) dx, symmetric about x = 0.
  const double half_columns = std::ceil(half_extent / dx) + 1.0;
  const double ny = static_cast<double>(hi - lo + 1), nx = 2.0 * half_columns + (column_offset == 0.0 ? 1.0 : 0.0);
  if (!(nx <= static_cast<double>(kBem2dMaxElementsPerSide) && ny <= static_cast<double>(kBem2dMaxElementsPerSide))) {
    why = "grid of " + std::to_string(static_cast<long long>(nx)) + " x " + std::to_string(static_cast<long long>(ny)) +
          " elements (max " + std::to_string(kBem2dMaxElementsPerSide) + " per side): element size too small";
    return SolveStatus::InvalidInput;
  }
  grid.nx = static_cast<std::size_t>(nx);
  grid.ny = static_cast<std::size_t>(ny);
  grid.dx = dx;
  grid.dy = dy;
  grid.x0 = -(half_columns - column_offset) * dx;
  grid.y0 = row_centre(lo, dy, alignment);
  grid.covered_approach = covered_approach;
  grid.first_row_at_data_end = lo == first;
  grid.last_row_at_data_end = hi == last;
  grid.h.assign(grid.nx * grid.ny, 0.0);
  grid.potential.assign(grid.nx * grid.ny, 0);
  for (std::size_t j = 0; j < grid.ny; ++j) {
    const GapSample s = sample_gap(gap, grid.y0 + static_cast<double>(j) * dy);
    for (std::size_t i = 0; i < grid.nx; ++i) {
      const double x = grid.x0 + static_cast<double>(i) * dx;
      const std::size_t e = j * grid.nx + i;
      grid.h[e] = s.h + s.A * x * x;
      grid.potential[e] = grid.h[e] < covered_approach ? 1 : 0;
    }
  }
  return SolveStatus::Converged;
}

}  // namespace ctab::gen::bem2d
