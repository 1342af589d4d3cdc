// SPDX-License-Identifier: Apache-2.0
#pragma once
// Rail-profile geometry of a stored patch: where its s coordinate starts on the rail. Private to the sweep library.
#include "ctab/profiles/profile.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::gen::detail {

// Lateral rail coordinate of s = 0: the point where the contact plane touches the rail (its slope there is
// tan(plane_angle); wheelrail_contact.cpp builds the plane at the reference minimum). A conformal patch carries its
// surface's origin; a patch that holds s = 0 has it as its contact point; otherwise (a run split off the reference
// window) the tangent point is found by secant steps on the rail slope from the strips' linear extrapolation to
// s = 0, and that extrapolation is kept where the secant steps find no tangent point.
[[nodiscard]] double s_origin_y_rail(const ContactPatch& patch, const ProfileTable& rail);

}  // namespace ctab::gen::detail
