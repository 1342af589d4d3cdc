// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The prescribed-load fixed point of the main patch (internal to ctab::wheelrail). The gap is sampled with the wheel
//! lowered by a vertical approach x (PatchProblem::gap_dz): a vertical shift of the wheel is seen along a normal of
//! inclination alpha at a wheel surface of inclination delta_w as x cos(delta_w) / cos(delta_w - alpha), not
//! x cos(alpha), because it also slides the wheel along the surface; on a curved patch (flange root) that tilts h(s).
//! So a prescribed load repeats the strip solve with h re-sampled at the solved approach dz until dz moves by less
//! than tuning::kGapApproachTolerance_m and, under a vertical load, sum N_i cos(alpha_i) matches it:
//! x = dz(x, F), secant steps on x - dz(x), with the normal force F rescaled to the vertical load once x has settled.
#include "wheel_case.hpp"

namespace ctab::gen {

//! Prescribed normal or vertical load on the main patch: Converged also when the strip solve failed (main.solution
//! holds why), else InvalidInput or MaxIterations with c.detail.
[[nodiscard]] SolveStatus solve_main_for_load(WheelCase& c, PatchProblem& main, double depth);

}  // namespace ctab::gen
