// SPDX-License-Identifier: Apache-2.0
// MIM-1D solver (mim1d.hpp): the solves for a prescribed approach and a prescribed load (the combined iteration,
// and the paper's outer iteration on the approach as its fallback).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/mim1d.hpp"
#include "mim1d_constants.hpp"

namespace ctab::gen {

using namespace mim1d_detail;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

// Prescribed approach: Eqs. 4, 9 and A2 at the given delta (Figure 3 once).
NormalSolution Mim1dSolver::solve_for_approach(double approach_m) {
  const auto start = std::chrono::steady_clock::now();
  const double entries_before = matrix_entries_;
  if (!std::isfinite(approach_m)) {
    NormalSolution invalid = make_solution(SolveStatus::InvalidInput, approach_m);
    invalid.patches.clear();
    return invalid;
  }
  double approach = approach_m;
  const InnerResult inner = solve_inner(approach, false, nullptr);
  if (inner.status == SolveStatus::Converged) update_lengths();
  NormalSolution solution = make_solution(inner.status, approach_m);
  if (!is_success(inner.status)) solution.patches.clear(), solution.normal_load_N = 0.0;
  solution.iterations = inner.iterations;
  solution.residual = inner.residual;
  solution.solve_time_s = seconds_since(start);
  solution.matrix_entries = matrix_entries_ - entries_before;
  return solution;
}

// The paper's start (Section 2.5): the Hertz approach at the deepest strip for the load, from its curvatures
// (Eqs. 17-19), with B limited to A / kCurvatureRatioLimit.
double Mim1dSolver::hertz_start_approach(double normal_force_N) const {
  const auto deepest =
      static_cast<std::size_t>(std::min_element(grid_.h_m.begin(), grid_.h_m.end()) - grid_.h_m.begin());
  const double A0 = grid_.A_per_m[deepest];
  // With load weights the prescribed load is sum w_i N_i: the normal force about that over the deepest strip's w.
  const double force = load_weight_.empty() ? normal_force_N : normal_force_N / load_weight_[deepest];
  const HertzContact hertz =
      hertz_from_load(A0, std::max(grid_.B_per_m[deepest], A0 / kCurvatureRatioLimit), E_star_Pa_, force);
  return grid_.h_m[deepest] + (hertz.status == SolveStatus::Converged ? hertz.approach_m : kFallbackStartApproach_m);
}

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N) {
  return solve_for_load(normal_force_N, Mim1dWarmStart{});
}

// Restores the solver's own tolerance when a solve with a looser or an early-stopping one ends, also by an exception
// (a workspace's solver outlives a case that throws).
class Mim1dSolver::ToleranceScope {
 public:
  explicit ToleranceScope(Mim1dSolver& solver) : solver_(solver) {}
  ToleranceScope(const ToleranceScope&) = delete;
  ToleranceScope& operator=(const ToleranceScope&) = delete;
  ~ToleranceScope() {
    solver_.early_stop_.reset();
    solver_.tolerance_ = solver_.solve_tolerance_ = solver_.options_.tolerance;
  }

 private:
  Mim1dSolver& solver_;
};

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N, const Mim1dWarmStart& warm_start, double tolerance) {
  const ToleranceScope scope(*this);
  tolerance_ = std::max(tolerance, options_.tolerance);
  return solve_for_load(normal_force_N, warm_start);
}

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N, const Mim1dWarmStart& warm_start, double tolerance,
                                           const EarlyStop& early_stop) {
  const ToleranceScope scope(*this);
  solve_tolerance_ = std::max(tolerance, options_.tolerance);
  early_stop_ = early_stop;
  early_stop_->tolerance = std::max(early_stop.tolerance, solve_tolerance_);
  tolerance_ = solve_tolerance_;
  return solve_for_load(normal_force_N, warm_start);
}

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N, const Mim1dWarmStart& warm_start) {
  const auto start = std::chrono::steady_clock::now();
  const double entries_before = matrix_entries_;
  int iterations = 0;
  NormalSolution solution;
  if (std::isfinite(normal_force_N) && normal_force_N > 0.0) {
    // Combined iteration on loads and approach, from the neighbour's solution or from Hertz at the deepest point
    // (the paper's start); a warm start that fails is repeated cold.
    double approach = 0.0;
    const bool warm = load_warm_start(warm_start, approach);
    if (!warm) approach = hertz_start_approach(normal_force_N);
    InnerResult inner = solve_inner(approach, warm, &normal_force_N);
    iterations = inner.iterations;
    if (warm && inner.status != SolveStatus::Converged) {
      approach = hertz_start_approach(normal_force_N);
      inner = solve_inner(approach, false, &normal_force_N);
      iterations += inner.iterations;
    }
    if (inner.status == SolveStatus::Converged) {
      update_lengths();
      solution = make_solution(inner.status, approach);
      solution.iterations = iterations;
      solution.outer_iterations = 1;
      solution.residual = std::abs(prescribed_load() - normal_force_N) / normal_force_N;
    }
  }
  if (solution.status != SolveStatus::Converged && solution.status != SolveStatus::ZoneTruncated)
    solution = solve_for_load_nested(normal_force_N, iterations);
  solution.solve_time_s = seconds_since(start);
  solution.matrix_entries = matrix_entries_ - entries_before;
  return solution;
}

// The paper's outer iteration on delta for a prescribed load (Section 2.5): inner solves at fixed delta, the force
// of Eq. 15 compared with the load; the next delta by a safeguarded Newton step, Eq. 16 without a slope.
NormalSolution Mim1dSolver::solve_for_load_nested(double normal_force_N, int& iterations) {
  auto finish = [&](SolveStatus status, double approach, int outer, double residual) {
    NormalSolution solution = make_solution(status, approach);
    if (!is_success(status)) solution.patches.clear(), solution.normal_load_N = 0.0;
    solution.iterations = iterations;
    solution.outer_iterations = outer;
    solution.residual = residual;
    return solution;
  };
  const auto deepest =
      static_cast<std::size_t>(std::min_element(grid_.h_m.begin(), grid_.h_m.end()) - grid_.h_m.begin());
  const double h_min = grid_.h_m[deepest];
  if (!(std::isfinite(normal_force_N) && normal_force_N >= 0.0)) {
    active_.clear();
    return finish(SolveStatus::InvalidInput, h_min, 0, 0.0);
  }
  if (normal_force_N == 0.0) {
    active_.clear();
    return finish(SolveStatus::NoContact, h_min, 0, 0.0);
  }
  double approach = hertz_start_approach(normal_force_N);
  double lower = h_min, upper = std::numeric_limits<double>::infinity();
  bool warm = false;
  Eigen::VectorXd ones, slope_vector;
  auto eq16 = [&](double force) {  // paper Eq. 16, with delta measured from first contact
    return h_min + (approach - h_min) * std::cbrt((normal_force_N / force) * (normal_force_N / force));
  };
  for (int outer = 1; outer <= options_.max_outer_iterations; ++outer) {
    double solved_approach = approach;
    const InnerResult inner = solve_inner(solved_approach, warm, nullptr);
    iterations += inner.iterations;
    if (inner.status == SolveStatus::NoContact) {
      lower = approach;
      approach = std::isfinite(upper) ? 0.5 * (lower + upper)
                                      : h_min + kNoContactGrowth * (approach - h_min) + kNoContactNudge_m;
      warm = false;
      continue;
    }
    if (inner.status != SolveStatus::Converged) return finish(inner.status, approach, outer, inner.residual);
    update_lengths();
    const double force = prescribed_load();
    const double mismatch = force - normal_force_N;
    const double force_residual = std::abs(mismatch) / normal_force_N;
    if (force_residual <= tolerance_) return finish(SolveStatus::Converged, approach, outer, force_residual);
    (mismatch < 0.0 ? lower : upper) = approach;
    // Newton on delta with dN/d(delta) = w^T J^-1 1 from the last factorisation.
    const auto n = static_cast<Eigen::Index>(active_.size());
    ones.setOnes(n);
    slope_vector = factorisation_.rows() == n ? Eigen::VectorXd(factorisation_.solve(ones)) : Eigen::VectorXd();
    const double slope = slope_vector.size() == n ? load_sum(slope_vector) : 0.0;
    double next = (slope > 0.0 && std::isfinite(slope)) ? approach - mismatch / slope : eq16(force);
    if (!(next > lower && next < upper)) {
      next = std::isfinite(upper) ? 0.5 * (lower + upper) : eq16(force);
      if (!(next > lower)) next = h_min + kNoContactGrowth * (approach - h_min);
    }
    if (slope_vector.size() == n) {  // warm start along dN/d(delta)
      for (Eigen::Index r = 0; r < n; ++r) {
        const std::size_t i = active_[static_cast<std::size_t>(r)];
        const double predicted = load_[i] + slope_vector(r) * (next - approach);
        load_[i] = predicted > 0.0 ? predicted : kWarmStartShrink * load_[i];
      }
    }
    approach = next;
    warm = true;
  }
  return finish(SolveStatus::MaxIterations, approach, options_.max_outer_iterations, 1.0);
}

}  // namespace ctab::gen
