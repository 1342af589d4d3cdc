// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The general strip problem's geometry: undeformed separation and relative curvatures along the lateral
//! line of the contact plane.
//!
//! h(x, y) ~ h(y) + A(y) x^2 near the line x = 0; B(y) = h''(y)/2 is the lateral relative curvature.
//! All in SI: y [m], h [m], A and B [1/m] (half the summed principal curvatures, as hertz.hpp).
#include <string>
#include <vector>

#include "ctab/contact/grid_alignment.hpp"

namespace ctab::gen {

struct GapProfile {
  std::vector<double> y_m;      //!< lateral coordinate, strictly increasing [m]
  std::vector<double> h_m;      //!< undeformed separation [m]
  std::vector<double> A_per_m;  //!< relative curvature in the rolling direction, > 0 [1/m]
  std::vector<double> B_per_m;  //!< relative curvature in the lateral direction [1/m] (may be <= 0)
  std::string source = "gap";   //!< where it came from, for error messages
  //! Where the strips sit (strip_grid.hpp): edges at multiples of 2b from y = 0 (CONTACT's grids of the paper's
  //! cases, the default), or a strip centred on y = 0 (CONTACT's wheel-rail grid, a row on its reference point).
  GridAlignment strip_alignment = GridAlignment::EdgesAtOrigin;

  [[nodiscard]] std::size_t size() const noexcept { return y_m.size(); }
};

//! Throws InputError (naming source and the offending row, 1-based) unless the profile has >= 3 rows, equal
//! column lengths, finite values, strictly increasing y and A > 0.
void validate(const GapProfile& gap);

//! A profile sampled from analytic functions on [y_begin, y_end] with the given step (tests, examples).
template <class SeparationFn, class RollingCurvatureFn, class LateralCurvatureFn>
GapProfile sample_gap(double y_begin, double y_end, double step, SeparationFn&& h, RollingCurvatureFn&& A,
                      LateralCurvatureFn&& B, std::string source) {
  GapProfile gap;
  gap.source = std::move(source);
  const auto count = static_cast<std::size_t>((y_end - y_begin) / step + 0.5) + 1;
  for (std::size_t i = 0; i < count; ++i) {
    const double y = y_begin + static_cast<double>(i) * step;
    gap.y_m.push_back(y);
    gap.h_m.push_back(h(y));
    gap.A_per_m.push_back(A(y));
    gap.B_per_m.push_back(B(y));
  }
  return gap;
}

//! The paper's Hertzian case (section 3.1.1): sphere of radius R on a flat, h = y^2/(2R), A = B = 1/(2R).
[[nodiscard]] GapProfile sphere_on_flat_gap(double radius_m, double half_range_m, double step_m);
//! The paper's non-Hertzian case (section 3.1.2): body of revolution (rolling radius R_roll) with lateral
//! radius R_neg for y < 0 and R_pos for y >= 0, on a flat: h = y^2/(2 R(y)), A = 1/(2 R_roll), B = 1/(2 R(y)).
[[nodiscard]] GapProfile two_radius_gap(double rolling_radius_m, double radius_negative_m, double radius_positive_m,
                                        double y_min_m, double y_max_m, double step_m);

}  // namespace ctab::gen
