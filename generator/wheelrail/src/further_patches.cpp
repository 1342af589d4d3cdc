// SPDX-License-Identifier: Apache-2.0
#include "further_patches.hpp"

#include "ctab/contact/root_finding.hpp"
#include "main_patch_strips.hpp"
#include "patch_forces.hpp"
#include "wheelrail_tuning.hpp"

namespace ctab::gen {

namespace {

// Total normal or vertical load of all patches at vertical approach dz [N].
double load_at(WheelCase& c, double dz) {
  double sum = 0.0;
  for (std::size_t k = 0; k < c.ws.used; ++k) {
    PatchProblem& p = c.ws.pool[k];
    solve_patch_at(c, p, dz);
    if (!is_success(p.solution.status)) continue;
    if (c.load != LoadKind::VerticalForce) sum += p.solution.normal_load_N;
    else
      for (const PatchSolution& run : p.solution.patches) sum += run_force(p, run).vertical_N;
  }
  return sum;
}

}  // namespace

void solve_patch_at(WheelCase& c, PatchProblem& p, double vertical_approach) {
  if (p.gap_dz != vertical_approach) {
    p.gap_dz = vertical_approach;
    if (!c.builder.build(p, p.window_depth, c.options.sample_step_m) || !prepare(c, p)) {
      p.solution = NormalSolution{};
      p.solution.status = SolveStatus::InvalidInput;
      return;
    }
  }
  const double approach = vertical_approach * p.c;
  p.solution = c.mim1d() ? p.solver->solve_for_approach(approach) : solve_other_rung(c, p, Loading::approach(approach));
  c.result.iterations += p.solution.iterations;
  c.result.matrix_entries += p.solution.matrix_entries;
}

void open_further_patches(WheelCase& c, double depth) {
  for (std::size_t k = 1; k < c.ws.minima.size(); ++k) {
    const GapMinimum& m = c.ws.minima[k];
    if (m.gap_m >= c.result.vertical_approach_m || inside_window(c, m)) continue;
    PatchProblem& extra = c.ws.acquire();
    extra.reference = m;
    extra.gap_dz = c.result.vertical_approach_m;
    if (!c.builder.build(extra, m.gap_m + depth, c.options.sample_step_m) || !prepare(c, extra))
      --c.ws.used;  // give the slot back
  }
  c.detail.clear();  // a minimum that could not open a patch stays a near miss
}

SolveStatus solve_further_patches(WheelCase& c) {
  if (c.ws.used < 2) return SolveStatus::Converged;
  if (c.load == LoadKind::Approach) {
    for (std::size_t k = 1; k < c.ws.used; ++k) solve_patch_at(c, c.ws.pool[k], c.load_value);
    return SolveStatus::Converged;
  }
  auto mismatch = [&](double dz) { return load_at(c, dz) - c.load_value; };
  const double hi = c.result.vertical_approach_m;
  const RootResult root =
      find_root_bracketed(mismatch, 0.0, -c.load_value, hi, mismatch(hi), tuning::kSharedApproachTolerance_m,
                          c.options.mim1d.tolerance * c.load_value * tuning::kSharedForceToleranceFactor,
                          tuning::kSharedApproachIterations);
  if (!root.converged) {
    c.detail = "the vertical approach shared by " + std::to_string(c.ws.used) + " patches did not converge in " +
               std::to_string(tuning::kSharedApproachIterations) + " root-finding steps";
    return SolveStatus::MaxIterations;
  }
  c.result.vertical_approach_m = root.x;
  (void)load_at(c, root.x);
  return SolveStatus::Converged;
}

bool inside_window(const WheelCase& c, const GapMinimum& m) {
  for (std::size_t k = 0; k < c.ws.used; ++k) {
    const PatchProblem& p = c.ws.pool[k];
    if (!p.rail_y.empty() && m.rail_y_m >= p.rail_y.front() && m.rail_y_m <= p.rail_y.back()) return true;
  }
  return false;
}

}  // namespace ctab::gen
