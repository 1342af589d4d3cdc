// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Shape of a solved patch, from its strips' geometry alone (no pressure): the candidate indicators of where
//! MIM-1D's strip model departs from the 2-D half-space solution (`ctab bench knee`, docs/design/knee-indicator.md)
//! and the least model's escalation rule (least_model.hpp).
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::gen {

struct PatchShape {
  //! Largest minus smallest surface inclination over the patch's strips [rad]: conformal patches, where each strip
  //! has its own normal (from the strips' surface points: cos(alpha) = d y_rail / d s); 0 on a plane.
  double angle_spread_rad = 0.0;
  //! Largest change of that inclination from one strip to the next [rad].
  double max_turn_per_strip_rad = 0.0;
  //! Lateral width over the longest strip's length, (s_max - s_min) / (2 max a) [-].
  double aspect_ratio = 0.0;
  int strips = 0;  //!< loaded strips [-]
};

//! The shape of `patch` (strips in order of s). A patch of fewer than two strips has spread and turn 0.
[[nodiscard]] PatchShape patch_shape(const ContactPatch& patch) noexcept;

}  // namespace ctab::gen
