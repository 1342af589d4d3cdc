#pragma once
//! Hertz theory applied to a strip problem: one elliptic patch from the curvatures at the deepest point of
//! the gap (the classical point-contact model of multibody codes; the cheap end of the speed/accuracy chart).
//! The patch is reported on the same strips as MIM-1D: a(y) = a0 sqrt(1 - (y/b0)^2), p0(y) = p0H sqrt(...).
//! A lateral curvature <= A/20 is raised to A/20 (CONTACT's R_y <= 20 R_x rule).
#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/normal_solution.hpp"

namespace ctab::gen {

//! Hertz patch for a prescribed approach [m] (same datum as the gap's h). Never throws for a validated gap.
[[nodiscard]] NormalSolution solve_hertz_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                                      double approach_m);
//! Hertz patch for a prescribed normal force [N].
[[nodiscard]] NormalSolution solve_hertz_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                                  double normal_force_N);

}  // namespace ctab::gen
