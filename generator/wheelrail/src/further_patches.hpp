// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Patches beyond the main one (internal to ctab::wheelrail): a gap minimum outside every window whose gap the
//! approach closes opens a patch of its own; with several patches a prescribed force is shared through one vertical
//! approach, found by a safeguarded root finder.
#include "wheel_case.hpp"

namespace ctab::gen {

//! Solves patch p at vertical approach dz [m], its gap re-sampled there first.
void solve_patch_at(WheelCase& c, PatchProblem& p, double vertical_approach);

//! Opens a patch at every further minimum that the main patch's approach closes (windows of this depth beyond it).
void open_further_patches(WheelCase& c, double depth);

//! Shares the prescribed load among the patches (nothing to do for one patch): Converged, or MaxIterations with
//! c.detail.
[[nodiscard]] SolveStatus solve_further_patches(WheelCase& c);

//! Whether a gap minimum lies in one of the case's patch windows (rail y).
[[nodiscard]] bool inside_window(const WheelCase& c, const GapMinimum& m);

}  // namespace ctab::gen
