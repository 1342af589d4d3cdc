// SPDX-License-Identifier: Apache-2.0
#pragma once
//! CONTACT's reference point during the gap passes (internal to ctab::wheelrail). With CONTACT's reference rule every
//! gap pass samples in the plane at the interpenetration centre of its own sampling approach, so the passes settle the
//! approach and the reference point together (one fixed point). With CONTACT's reference angle at the deepest point
//! only the plane's inclination follows (a plane's gap is the same through any of its points; the point places the
//! strip grid). The conformal surface at the deepest point centres its strip grid on the centre at each pass's
//! sampling approach (CONTACT's grid: its strip k is CONTACT's row k) and keeps the deepest point as the contact
//! point: its surface does not depend on the point it is marched from. Following the centre at every pass (not once)
//! keeps the result independent of the path: a load solve and an approach solve at its settled approach agree.
#include "interpenetration_centre.hpp"
#include "wheel_case.hpp"

namespace ctab::gen {

//! The case's side at its shift, for interpenetration_centre.
[[nodiscard]] ShiftedSide shifted_side(const WheelCase& c);

//! Whether the gap passes follow the centre (not with a prescribed point, nor during recentre_main_patch's re-solve).
[[nodiscard]] bool follows_centre(const WheelCase& c);

//! The conformal surface at the deepest point centres its strips on CONTACT's reference point (the grid's origin).
[[nodiscard]] bool centres_conformal_grid(const WheelRailOptions& options);

//! interpenetration_centre at approach x from the deepest minimum, kept for the next call at the same x (a pass
//! predicts the next pass's grid at the approach that pass then samples at).
[[nodiscard]] bool centre_at(WheelCase& c, double x, GapMinimum& centre);

//! Moves the main patch's reference point, plane angle or grid origin to the centre at its sampling approach, as the
//! options ask.
void follow_interpenetration_centre(WheelCase& c, PatchProblem& main);

//! The grid origin (rail y) of a pass at sampling approach x: the centre there where the conformal grid follows it,
//! else the present one.
[[nodiscard]] double next_grid_origin(WheelCase& c, const PatchProblem& p, double x);

}  // namespace ctab::gen
