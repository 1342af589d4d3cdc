// SPDX-License-Identifier: Apache-2.0
#pragma once
//! CONTACT's contact reference point (internal to ctab::wheelrail; CONTACT's m_wr_locatecp, step 5): the centre of
//! the interpenetration region at a vertical approach, weighted by the squared gap integrated along x (~ pen^(5/2)
//! for gap(x) = -pen + A x^2), with CONTACT's reference angle, the mean of the rail's inclination over the region with
//! the same weights. It meets CONTACT's planar reference points within 0.013 mm and its reference angle within
//! 0.012 deg in all six planar flange cases (flange_reference_test); docs/method.md "Reference point".
#include "ctab/wheelrail/wheelrail_geometry.hpp"

namespace ctab::gen {

//! One side at one lateral shift and roll, its wheel touching the rail at first_contact_z_m (WheelContact's).
struct ShiftedSide {
  const SideGeometry& side;
  double dy_m = 0.0, roll_rad = 0.0;
  double first_contact_z_m = 0.0;  // [m]
};

//! The weighted centre (on the wheel parameter S) of the contiguous interpenetration region around point.wheel_s_m
//! at vertical approach approach_m, with its rail point, radius and CONTACT's reference angle written to `point`.
//! False when the region holds fewer than three samples at the finest step (tuning::kFinestCentreStep_m).
[[nodiscard]] bool interpenetration_centre(const ShiftedSide& at, GapMinimum& point, double approach_m);

//! from + step (centre - from) on the wheel parameter and the plane angle, the rail point and radius from the wheel
//! point there (a secant step on the fixed point centre = C(centre)); false when it leaves the profiles.
[[nodiscard]] bool secant_centre(const ShiftedSide& at, const GapMinimum& from, const GapMinimum& centre, double step,
                                 GapMinimum& out);

}  // namespace ctab::gen
