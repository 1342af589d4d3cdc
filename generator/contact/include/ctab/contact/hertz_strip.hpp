// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Hertz theory applied to a strip problem: one elliptic patch from the curvatures at the deepest point of
//! the gap (the classical point-contact model of multibody codes; the cheap end of the speed/accuracy chart).
//! The patch is reported on the same strips as MIM-1D: a(y) = a0 sqrt(1 - (y/b0)^2), p0(y) = p0H sqrt(...).
//! Lateral curvature: the local B at the deepest point where B >= A/20. Where it is negative or below A/20 (a
//! hollow tread, a flange root), the field's practice: the patch-mean lateral curvature over the interpenetration
//! run around the point, B = [h'(y_e) - h'(y_s)] / (2 (y_e - y_s)) (CONTACT estimate_curvatures_v2, kappa ~
//! Delta(alpha)/Delta(s)), floored at A/20 (CONTACT's R_y <= 20 R_x rule). For a prescribed load the run follows
//! the Hertz approach (a fixed point on delta and B).
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
