#pragma once
//! Uniform strips of width 2b along the lateral line, with edges at integer multiples of 2b from y = 0 of the
//! gap's coordinate (CONTACT's grid convention, so strips line up with its rows). The gap is resampled at the
//! strip centres: h by cubic Hermite interpolation with 3-point slopes (exact for piecewise quadratics),
//! A and B linearly.
#include <cstddef>
#include <vector>

#include "ctab/contact/gap_profile.hpp"

namespace ctab::gen {

struct StripGrid {
  double strip_width_m = 0.0;        //!< 2b [m]
  std::vector<double> y_m;           //!< strip centres [m] (n)
  std::vector<double> h_m;           //!< separation at the centres [m] (n)
  std::vector<double> A_per_m;       //!< rolling-direction relative curvature [1/m] (n)
  std::vector<double> B_per_m;       //!< lateral relative curvature [1/m] (n)

  [[nodiscard]] std::size_t size() const noexcept { return y_m.size(); }
  [[nodiscard]] double half_width_m() const noexcept { return 0.5 * strip_width_m; }
};

//! Resamples a validated gap onto strips. Throws InputError if the width is not positive and finite or if
//! fewer than 3 strips fit inside the gap's y-range.
[[nodiscard]] StripGrid make_strip_grid(const GapProfile& gap, double strip_width_m);
//! The same into an existing grid, reusing its storage.
void fill_strip_grid(const GapProfile& gap, double strip_width_m, StripGrid& grid);

}  // namespace ctab::gen
