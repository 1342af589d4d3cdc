// SPDX-License-Identifier: Apache-2.0
// MIM-1D solver (mim1d.hpp): the inner iteration of Figure 3 on a fixed or a prescribed-load approach: residual,
// active-set check, then a Newton or the paper's fixed-point step, damped when it stalls.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "ctab/contact/mim1d.hpp"
#include "mim1d_constants.hpp"

namespace ctab::gen {

using namespace mim1d_detail;

bool Mim1dSolver::active_compliances_valid() const {
  for (const std::size_t i : active_)
    if (!(compliance_[i].compliance_m_per_Pa > 0.0 && std::isfinite(compliance_[i].compliance_m_per_Pa))) return false;
  return true;
}

bool Mim1dSolver::newton_step(const InnerState& state, double force_mismatch, double& next_approach) {
  factorisation_.compute(jacobian_);
  next_loads_ = active_loads_ - factorisation_.solve(residual_);
  if (state.target_load_N) {  // bordered system: J dN - d(delta) v = -R,  w^T dN = -F (v: approach_column_)
    slope_ = factorisation_.solve(approach_column_);
    const double d_approach = (-force_mismatch - load_sum(next_loads_ - active_loads_)) / load_sum(slope_);
    next_loads_ += d_approach * slope_;
    next_approach = state.approach_m + d_approach;
  }
  return !(next_loads_.array() <= 0.0).any();  // Newton overshoots at a patch edge
}

// The paper's step: G(a) N = delta - h with the lengths of the previous iterate (Eqs. 9 and A2), with a prescribed
// load the force balance w^T N = target (Eqs. 6 and 15) as one more equation.
void Mim1dSolver::fixed_point_step(const InnerState& state, double& next_approach) {
  factorisation_.compute(influence_);  // G, built with the Jacobian in this iteration (build_matrices)
  if (state.target_load_N) {           // G N - delta 1 = -h,  w^T N = target
    next_loads_ = factorisation_.solve(rhs_ - state.approach_m * ones_);  // G^-1 (-h)
    slope_ = factorisation_.solve(ones_);
    next_approach = (*state.target_load_N - load_sum(next_loads_)) / load_sum(slope_);
    next_loads_ += next_approach * slope_;
  } else {
    next_loads_ = factorisation_.solve(rhs_);
  }
}

void Mim1dSolver::track_progress(InnerState& state, double merit) {
  if (merit <= kFullStepLevel) state.damping = 1.0;
  if (merit < kProgressFactor * state.best_merit) {
    state.best_merit = merit;
    state.steps_without_progress = 0;
    return;
  }
  if (++state.steps_without_progress < kStallSteps) return;
  state.damping = std::max(kDampingFactor * state.damping, kMinimumDamping);
  state.best_merit = merit;
  state.steps_without_progress = 0;
}

bool Mim1dSolver::take_step(InnerState& state, double next_approach) {
  if (!next_loads_.allFinite() || !std::isfinite(next_approach)) return false;
  if (state.damping < 1.0) {  // a damped step; strips the full step unloads still leave
    for (Eigen::Index r = 0; r < next_loads_.size(); ++r)
      if (next_loads_(r) > 0.0) next_loads_(r) = active_loads_(r) + state.damping * (next_loads_(r) - active_loads_(r));
    next_approach = state.approach_m + state.damping * (next_approach - state.approach_m);
  }
  const double largest = next_loads_.maxCoeff();
  if (!(largest > 0.0)) return false;
  state.approach_m = next_approach;
  // Strips with non-positive load leave the contact (paper Figure 3).
  bool removed = false;
  for (Eigen::Index r = 0; r < next_loads_.size(); ++r) {
    const std::size_t i = active_[static_cast<std::size_t>(r)];
    load_[i] = std::max(next_loads_(r), 0.0);
    removed = removed || next_loads_(r) <= 0.0;
  }
  if (removed) {
    std::erase_if(active_, [&](std::size_t i) { return load_[i] <= 0.0; });
    state.last_change = std::numeric_limits<double>::infinity();
    state.set_checked = false;
    state.best_merit = std::numeric_limits<double>::infinity();
  } else {
    state.last_change = (next_loads_ - active_loads_).cwiseAbs().maxCoeff() / largest;
  }
  return true;
}

// One pass of Figure 3: lengths (Eq. A4), G and u = G N (Eq. A2), the residual of Eq. 9, the Eq. 4 check with its
// admissions, then a step whose non-positive loads leave the set.
Mim1dSolver::IterationOutcome Mim1dSolver::iterate(InnerState& state, InnerResult& result) {
  if (active_.empty() || !(state.approach_m - state.h_min > 0.0)) return IterationOutcome::Failed;
  refresh_compliances(state.approach_m);
  if (!active_compliances_valid()) return result.status = SolveStatus::InvalidInput, IterationOutcome::Failed;
  const double depth = state.approach_m - state.h_min;
  update_lengths();
  const bool newton = options_.update == Mim1dUpdate::Newton;
  build_matrices(newton ? MatrixKind::Jacobian : MatrixKind::Influence, true);
  gather_active_system(state.approach_m);
  const double force_mismatch = state.target_load_N ? load_sum(active_loads_) - *state.target_load_N : 0.0;
  residual_ = displacement_ - rhs_;
  result.residual = residual_.cwiseAbs().maxCoeff() / depth;
  if (!std::isfinite(result.residual)) return IterationOutcome::Failed;
  if (early_stop_)
    tolerance_ = state.approach_m < early_stop_->approach_low_m || state.approach_m > early_stop_->approach_high_m
                     ? early_stop_->tolerance
                     : solve_tolerance_;
  const SetCheck check = check_active_set(state, result.residual, force_mismatch);
  if (check != SetCheck::Iterate) {
    state.set_checked = true;
    find_violators(state.approach_m, depth);
    if (!violators_.empty() && active_set_seen_before()) {
      // The admissions cycle: back to a set already checked. Admit the violators alone from now on, and only
      // once the set has fully converged (so that the check sees accurate displacements).
      ++state.cycles;
      state.growth = 0;
    }
    if (admit_violators(state.approach_m, state.growth)) {
      if (state.cycles > 0) state.growth = 0;
      state.set_checked = false;
      state.last_change = std::numeric_limits<double>::infinity();
      state.best_merit = std::numeric_limits<double>::infinity();
      return IterationOutcome::Continue;
    }
    if (check == SetCheck::CheckAndFinish) return result.status = SolveStatus::Converged, IterationOutcome::Converged;
  }
  track_progress(state, state.target_load_N ? std::max(result.residual, std::abs(force_mismatch) / *state.target_load_N)
                                            : result.residual);
  // The approach column only for a step: an iteration that converges or admits strips needs the residual alone, and
  // the column's compliances at a shifted approach are its cost.
  if (newton && state.target_load_N) fill_approach_column(state.approach_m, state.h_min);
  else approach_column_ = ones_;
  double next_approach = state.approach_m;
  const bool fixed_point = !newton || std::exchange(state.fixed_point_first, false);
  if (fixed_point || !newton_step(state, force_mismatch, next_approach)) fixed_point_step(state, next_approach);
  return take_step(state, next_approach) ? IterationOutcome::Continue : IterationOutcome::Failed;
}

Mim1dSolver::InnerResult Mim1dSolver::solve_inner(double& approach_m, bool warm_start, const double* target_load_N) {
  InnerResult result;
  const double h_min = *std::min_element(grid_.h_m.begin(), grid_.h_m.end());
  if (!(approach_m - h_min > 0.0)) {
    active_.clear();
    std::fill(load_.begin(), load_.end(), 0.0);
    result.status = SolveStatus::NoContact;
    return result;
  }
  (void)start_loads(approach_m, warm_start);
  checked_sets_.clear();
  InnerState state{approach_m, target_load_N, h_min};
  // From ANALYN's estimate (a cold start) the first Newton step often overshoots at a patch edge and falls back to
  // the fixed-point step after its factorisation: a cold start takes that step at once.
  state.fixed_point_first = !warm_start;
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    result.iterations = iteration;
    const IterationOutcome outcome = iterate(state, result);
    approach_m = state.approach_m;
    if (outcome != IterationOutcome::Continue) return result;  // Converged, or the failure in result.status
  }
  result.status = SolveStatus::MaxIterations;
  return result;
}

}  // namespace ctab::gen
