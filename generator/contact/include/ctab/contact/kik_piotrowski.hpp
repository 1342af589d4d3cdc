// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Kik-Piotrowski (KP) virtual-penetration method: J. Piotrowski, W. Kik, "A simplified model of wheel/rail
//! contact mechanics for non-Hertzian problems and its application in rail vehicle dynamic simulations",
//! VSD 46(1-2):27-48, 2008. Non-iterative; the `kp` rung of the method ladder.
//!
//! On strips of width 2b (strip_grid.hpp), for a rigid approach delta [m]:
//!  1. Basins: maximal runs where the rigid interpenetration delta - h > 0; in basin k with deepest separation
//!     h_k the local approach is delta_k = delta - h_k.
//!  2. Virtual penetration (KP's central idea): the contact area is the region where the bodies would
//!     interpenetrate at the reduced approach eps delta_k, eps = 0.55 (KP's compromise between 0.5, exact for a
//!     circular Hertz contact, and the larger values of elongated ones):
//!       g(y) = eps delta_k - (h(y) - h_k),  contact where g > 0;  each run of g > 0 is a patch.
//!  3. Strip half-length from the rolling-direction curvature: x_l(y) = sqrt(g(y) / A(y)) (x_l^2 = 2 R g).
//!  4. Pressure semi-elliptic along x with amplitude proportional to x_l (KP Eq. for p(x, y)):
//!       p(x, y) = p0 sqrt(1 - x^2 / x_l(y)^2) x_l(y) / x_l0 = (p0 / x_l0) sqrt(x_l(y)^2 - x^2),
//!     x_l0 = x_l at the patch's deepest strip m (the point of maximum virtual penetration).
//!  5. p0 from the one compatibility condition at that point: the elastic displacement there equals the true
//!     local approach delta - h_m (half-space, Boussinesq):
//!       delta - h_m = (1/(pi E*)) iint p(x, y) / sqrt(x^2 + (y - y_m)^2) dx dy = (p0/x_l0) sum_j x_l,j C_mj,
//!     C_mj the closed-form strip kernel (strip_kernel.hpp, per unit peak pressure). The load is then
//!     N = sum_j pi x_l,j b p0_j.
//! Approach prescribed: delta is the true rigid approach; the virtual penetration is eps x delta.
//! Load prescribed: delta by root search on N(delta) (semi_analytic.hpp).
//! Negative lateral curvature: KP needs no lateral curvature at all (only h(y) and A(y)), so a concave or
//! conformal gap needs no special treatment: the virtual interpenetration region follows h. (This is why KP was
//! proposed for non-Hertzian contact.) Per-basin reduction (step 1) is this implementation's reading for
//! multi-point contact: a second patch that just starts to touch behaves like a small Hertz contact instead of
//! appearing with a finite width and an unbounded peak pressure.
//! Validity: half-space, frictionless, identical materials, no yaw (symmetric in x).
#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/normal_solution.hpp"

namespace ctab::gen {

//! KP's penetration reduction factor eps [-] (Piotrowski & Kik 2008; CONTACT user guide "eps_kp = 0.55").
inline constexpr double kKikPiotrowskiEpsilon = 0.55;

//! KP for a prescribed rigid approach [m]. Never throws; InvalidInput on a bad gap, width or approach.
[[nodiscard]] NormalSolution solve_kp_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                                   double approach_m);
//! KP for a prescribed normal force [N].
[[nodiscard]] NormalSolution solve_kp_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                               double normal_force_N);

}  // namespace ctab::gen
