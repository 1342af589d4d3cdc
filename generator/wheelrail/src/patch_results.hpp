// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The case's result from its solved patches (internal to ctab::wheelrail): every loaded run of strips of every patch
//! becomes a ContactPatch with its contact point, forces, centre of pressure and strips; unloaded minima are near
//! misses.
#include <vector>

#include "ctab/contact/resolution.hpp"
#include "ctab/wheelrail/patch_extents.hpp"
#include "wheel_case.hpp"

namespace ctab::gen {

//! Fills c.result.patches; the status is the last failing patch's (c.detail says why), NoContact where no strip
//! centre is reached.
[[nodiscard]] SolveStatus collect_patches(WheelCase& c);

//! The gap minima that no patch holds and the approach does not close.
void collect_near_misses(WheelCase& c);

}  // namespace ctab::gen
