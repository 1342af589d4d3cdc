// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The main patch's strip problem and solves (internal to ctab::wheelrail): sampling it, one strip solve with its
//! warm start, the first-order sensitivities that the gap passes step with, and the vertical-load weights.
#include <limits>
#include <optional>

#include "ctab/contact/mim1d.hpp"
#include "ctab/contact/normal_contact.hpp"
#include "wheel_case.hpp"

namespace ctab::gen {

//! Creates or re-targets the patch's MIM-1D solver (only MIM-1D keeps a solver per patch, reused from case to case;
//! the other rungs are one-shot); false with c.detail saying why.
[[nodiscard]] bool prepare(WheelCase& c, PatchProblem& p);

//! Samples the main patch in a window of this depth and prepares its solver; false with c.detail saying why.
[[nodiscard]] bool build_main(WheelCase& c, PatchProblem& main, double depth);

//! A rung other than MIM-1D on a patch's strip problem (normal_contact.hpp); bem2d takes the optional start and
//! field of MethodOptions.
[[nodiscard]] NormalSolution solve_other_rung(const WheelCase& c, const PatchProblem& p, Loading loading,
                                              const Bem2dPressureField* bem2d_start = nullptr,
                                              Bem2dPressureField* bem2d_field = nullptr);

//! One strip solve of the main patch at this normal force: warm-started from the neighbour (pass 0, when given) or
//! from the last successful pass of this case (kept through a failed pass, so that a retry starts from it), else
//! cold; MIM-1D to the relative tolerance given, stopping early where early_stop says so.
void solve_main_once(WheelCase& c, PatchProblem& main, double force, bool from_previous_pass, double tolerance,
                     const Mim1dSolver::EarlyStop* early_stop = nullptr);

//! d dz / d x of the solved approach dz on the sampling approach x at this force, to first order: every strip's h
//! (sampled at x, plus x c) moves by c - w_i (w_i = PatchProblem::approach_weight at the strip), and the strip
//! solver turns that into d delta = c d dz (Mim1dSolver::approach_sensitivity). Empty for the other rungs.
[[nodiscard]] std::optional<double> gap_slope(const WheelCase& c, PatchProblem& p);

//! d dz / d F of the main patch's last strip solve at the same sampling approach [m/N]; empty for the other rungs.
[[nodiscard]] std::optional<double> load_rate(const WheelCase& c, PatchProblem& p);

//! The next pass's warm start: the last solve moved to first order to the next sampling approach (x + dx) and normal
//! force (F + dF), so that the confirming pass starts next to its solution (Mim1dSolver::shift_warm_start). With a
//! grid origin that moves to rail y next_origin_y (the conformal grid following the centre), strip k then lies where
//! this pass's s was s_k + ds, ds the new origin's s: its separation changes by h(s_k + ds) - h(s_k) and its load
//! stays by index. A move beyond tuning::kPredictedGridMove of a strip, or a failed prediction, leaves the loads to
//! be moved onto the new grid by position (start_on_grid) at the next solve.
void shift_pass_start(WheelCase& c, PatchProblem& p, double dx, double dF,
                      double next_origin_y = std::numeric_limits<double>::quiet_NaN());

//! MIM-1D on a conformal surface under a vertical load prescribes the vertical load itself (the strips' loads
//! weighted by the cosines of their normals): a conformal patch does not know beforehand which share of a normal
//! force it carries vertically.
[[nodiscard]] bool weighted_vertical_load(const WheelCase& c);

//! The main patch's solver prescribes sum N_i cos(alpha_i), alpha_i each strip's normal as run_force takes it;
//! false (nothing set) where a normal leans beyond tuning::kCosineFloor.
[[nodiscard]] bool set_vertical_load_weights(PatchProblem& main);

}  // namespace ctab::gen
