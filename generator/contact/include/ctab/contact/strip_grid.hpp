// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Uniform strips of width 2b along the lateral line, centred at (k + offset) 2b from y = 0 of the gap's
//! coordinate, k integer, placed as the gap's strip_alignment says (grid_alignment.hpp: CONTACT's conventions, so
//! that strips line up with its rows). The gap is resampled at the strip centres: h by cubic Hermite interpolation
//! with 3-point slopes (exact for piecewise quadratics), A and B linearly.
#include <cstddef>
#include <vector>

#include "ctab/contact/gap_profile.hpp"

namespace ctab::gen {

struct StripGrid {
  double strip_width_m = 0.0;   //!< 2b [m]
  double centre_offset = 0.5;   //!< strip k's centre is (k + centre_offset) 2b (GapProfile::strip_alignment)
  std::vector<double> y_m;      //!< strip centres [m] (n)
  std::vector<double> h_m;      //!< separation at the centres [m] (n)
  std::vector<double> A_per_m;  //!< rolling-direction relative curvature [1/m] (n)
  std::vector<double> B_per_m;  //!< lateral relative curvature [1/m] (n)

  [[nodiscard]] std::size_t size() const noexcept { return y_m.size(); }
  [[nodiscard]] double half_width_m() const noexcept { return 0.5 * strip_width_m; }
};

//! Most strips of one strip problem. MIM-1D holds up to three dense n x n matrices (G, the Jacobian, its LU):
//! at 4000 strips 3 x 128 MB = 384 MB per solver and seconds per factorisation. The smallest config strip width
//! (10 um) still fits a tread patch (S1002/UIC60, dy = 2 mm: converged, 8.5 s); 1 um strips would need ~10 GB.
inline constexpr std::size_t kMaxStripsPerPatch = 4000;

//! Number of strips fill_strip_grid makes for a validated gap, computed in double (no allocation, no overflow:
//! a tiny width gives a huge count, a bad width NaN).
[[nodiscard]] double strip_count(const GapProfile& gap, double strip_width_m) noexcept;

//! Resamples a validated gap onto strips. Throws InputError if the width is not positive and finite, if
//! fewer than 3 strips fit inside the gap's y-range, or if more than kMaxStripsPerPatch would be needed.
[[nodiscard]] StripGrid make_strip_grid(const GapProfile& gap, double strip_width_m);
//! The same into an existing grid, reusing its storage.
void fill_strip_grid(const GapProfile& gap, double strip_width_m, StripGrid& grid);

}  // namespace ctab::gen
