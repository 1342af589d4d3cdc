// SPDX-License-Identifier: Apache-2.0
#pragma once
//! ANALYN: analytical surface-deformation correction of the interpenetration (M. Sh. Sichani, R. Enblom,
//! M. Berg, "A novel method to model wheel-rail normal contact in vehicle dynamics simulation",
//! VSD 52(12):1752-1764, 2014), in the strip form of CONTACT's "modified ANALYN" (CONTACT m_snorm.f90,
//! snorm_analyn_method). Non-iterative; the `analyn` rung of the method ladder.
//!
//! On strips of width 2b (strip_grid.hpp), for a rigid approach delta [m]:
//!  1. Basins: maximal runs where delta - h > 0; in basin k (deepest separation h_k) the local approach is
//!     delta_k = delta - h_k and the undeformed distance g(y) = h(y) - h_k >= 0.
//!  2. Local curvatures A(y), B(y) of the strip, each clamped to >= 1e-4 1/mm = 0.1 1/m (CONTACT's treatment
//!     of negative or vanishing curvature; Hertz needs A, B > 0).
//!  3. Hertz with (A(y), B(y)) gives the surface-deformation factors (Sichani's 1 + alpha, 1 + beta)
//!       alpha1 = delta/(A a^2) = r (1 + B/A)/m^2,   beta1 = delta/(B b^2) = r (1 + A/B)/n^2
//!     (m, n, r the Hertz coefficients of hertz.hpp; independent of delta). For Hertz 1/alpha1 + 1/beta1 = 1.
//!  4. Local penetration pen(y) = delta_k - beta1 g(y); no contact where pen <= 0.
//!  5. Strip half-length x_l(y) = sqrt(pen / (alpha1 A)).
//!  6. Peak pressure of the strip: Hertz with (A(y), B(y)) at the approach pen(y),
//!       p0(y) = (2 E* / (pi m n)) sqrt(pen (A + B) / r).
//!  7. p(x, y) = p0(y) sqrt(1 - x^2 / x_l(y)^2); strip load pi x_l b p0.
//! Exact for a Hertzian gap h = B y^2 (then x_l = a sqrt(1 - y^2/b^2), p0(y) = p0 sqrt(1 - y^2/b^2)).
//! Load prescribed: delta by root search on N(delta) (semi_analytic.hpp).
//! Validity: half-space, frictionless, identical materials, no yaw (CONTACT's version also handles the
//! contact locus of a yawed wheel; here the locus is x = 0).
#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/normal_solution.hpp"

namespace ctab::gen {

//! ANALYN's curvature floor [1/m] (CONTACT: 1e-4 1/mm).
inline constexpr double kAnalynMinCurvature_per_m = 0.1;

//! ANALYN for a prescribed rigid approach [m]. Never throws; InvalidInput on a bad gap, width or approach.
[[nodiscard]] NormalSolution solve_analyn_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                                       double approach_m);
//! ANALYN for a prescribed normal force [N].
[[nodiscard]] NormalSolution solve_analyn_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                                   double normal_force_N);

}  // namespace ctab::gen
