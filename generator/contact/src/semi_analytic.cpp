// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/semi_analytic.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "ctab/core/error.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/contact/root_finding.hpp"

namespace ctab::gen {

namespace {

constexpr double kCurvatureRatioLimit = 20.0;      // B >= A/20 (CONTACT's R_y <= 20 R_x rule), start value only
constexpr double kFallbackStartApproach_m = 1e-4;  // start value when Hertz fails
constexpr int kBracketDoublings = 60;              // 2^60 x the start: far beyond any elastic approach
constexpr int kLoadSearchIterations = 200;         // Illinois converges superlinearly; a hopeless case stops here
constexpr double kApproachTolerance_m = 1e-16;     // bracket width at which the search stops [m]

// The strip grid of a rung; false (no exception) when the gap, width or E* is unusable.
bool try_strip_grid(const GapProfile& gap, double E_star_Pa, double strip_width_m, StripGrid& grid) {
  if (!(std::isfinite(E_star_Pa) && E_star_Pa > 0.0)) return false;
  try {
    fill_strip_grid(gap, strip_width_m, grid);
  } catch (const InputError&) {
    return false;
  }
  return true;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<StripRun> positive_runs(const std::vector<double>& depth) {
  std::vector<StripRun> runs;
  for (std::size_t i = 0; i < depth.size();) {
    if (!(depth[i] > 0.0)) {
      ++i;
      continue;
    }
    StripRun run{i, i};
    while (run.end < depth.size() && depth[run.end] > 0.0) ++run.end;
    runs.push_back(run);
    i = run.end;
  }
  return runs;
}

std::size_t deepest_strip(const StripGrid& grid, StripRun run) {
  const auto first = grid.h_m.begin() + static_cast<std::ptrdiff_t>(run.begin);
  return static_cast<std::size_t>(std::min_element(first, grid.h_m.begin() + static_cast<std::ptrdiff_t>(run.end)) -
                                  grid.h_m.begin());
}

NormalSolution status_solution(SolveStatus status, const char* method, double approach_m) {
  NormalSolution solution;
  solution.status = status;
  solution.method = method;
  solution.approach_m = approach_m;
  return solution;
}

NormalSolution solution_from_strips(const StripGrid& grid, const std::vector<double>& half_length_m,
                                    const std::vector<double>& p0_Pa, const char* method, double approach_m) {
  NormalSolution solution = status_solution(SolveStatus::Converged, method, approach_m);
  const double b = grid.half_width_m();
  PatchSolution* patch = nullptr;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!(half_length_m[i] > 0.0 && p0_Pa[i] > 0.0)) {
      patch = nullptr;
      continue;
    }
    if (i == 0 || i + 1 == grid.size()) solution.status = SolveStatus::ZoneTruncated;
    if (patch == nullptr) {
      patch = &solution.patches.emplace_back();
      patch->y_min_m = grid.y_m[i] - b;
    }
    const StripSolution strip{grid.y_m[i], half_length_m[i], p0_Pa[i],
                              std::numbers::pi * half_length_m[i] * b * p0_Pa[i]};
    patch->strips.push_back(strip);
    patch->normal_force_N += strip.load_N;
    patch->area_m2 += 4.0 * strip.half_length_m * b;
    patch->max_pressure_Pa = std::max(patch->max_pressure_Pa, strip.p0_Pa);
    patch->centre_of_pressure_y_m += strip.load_N * strip.y_m;
    patch->y_max_m = grid.y_m[i] + b;
  }
  for (PatchSolution& p : solution.patches) {
    p.centre_of_pressure_y_m /= p.normal_force_N;
    solution.normal_load_N += p.normal_force_N;
  }
  if (solution.patches.empty()) solution.status = SolveStatus::NoContact;
  return solution;
}

double hertz_start_approach(const StripGrid& grid, double E_star_Pa, double normal_force_N) {
  const std::size_t k = deepest_strip(grid, {0, grid.size()});
  const double A = grid.A_per_m[k];
  const HertzContact hertz =
      hertz_from_load(A, std::max(grid.B_per_m[k], A / kCurvatureRatioLimit), E_star_Pa, normal_force_N);
  return hertz.status == SolveStatus::Converged ? hertz.approach_m : kFallbackStartApproach_m;
}

NormalSolution solve_load_by_approach(const std::function<NormalSolution(double)>& at_approach, double h_min_m,
                                      double start_approach_m, double normal_force_N, const char* method) {
  if (!(std::isfinite(normal_force_N) && normal_force_N >= 0.0))
    return status_solution(SolveStatus::InvalidInput, method);
  if (normal_force_N == 0.0) return status_solution(SolveStatus::NoContact, method, h_min_m);
  int solves = 0;
  NormalSolution last;
  auto mismatch = [&](double approach) {
    ++solves;
    last = at_approach(approach);
    return last.normal_load_N - normal_force_N;
  };
  double lo = h_min_m, f_lo = -normal_force_N;
  double hi = h_min_m + start_approach_m, f_hi = mismatch(hi);
  for (int k = 0; k < kBracketDoublings && f_hi < 0.0 && std::isfinite(f_hi); ++k) {
    lo = hi;
    f_lo = f_hi;
    hi = h_min_m + 2.0 * (hi - h_min_m);
    f_hi = mismatch(hi);
  }
  if (!std::isfinite(f_hi)) return status_solution(SolveStatus::NumericalFailure, method, hi);
  if (f_hi < 0.0) return status_solution(SolveStatus::MaxIterations, method, hi);
  const RootResult root = find_root_bracketed(mismatch, lo, f_lo, hi, f_hi, kApproachTolerance_m,
                                              kLoadTolerance * normal_force_N, kLoadSearchIterations);
  if (!std::isfinite(root.residual)) return status_solution(SolveStatus::NumericalFailure, method, root.x);
  if (last.approach_m != root.x) (void)mismatch(root.x);  // the root finder's last evaluation is its result
  last.outer_iterations = solves;
  last.iterations = solves;
  last.residual = std::abs(last.normal_load_N - normal_force_N) / normal_force_N;
  if (!root.converged && is_success(last.status)) last.status = SolveStatus::MaxIterations;
  return last;
}

NormalSolution solve_on_strips_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                            double approach_m, const char* method, const GridSolver& solve) {
  const auto start = std::chrono::steady_clock::now();
  StripGrid grid;
  if (!std::isfinite(approach_m) || !try_strip_grid(gap, E_star_Pa, strip_width_m, grid))
    return status_solution(SolveStatus::InvalidInput, method, approach_m);
  NormalSolution solution = solve(grid, approach_m);
  solution.solve_time_s = seconds_since(start);
  return solution;
}

NormalSolution solve_on_strips_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                        double normal_force_N, const char* method, const GridSolver& solve) {
  const auto start = std::chrono::steady_clock::now();
  StripGrid grid;
  if (!try_strip_grid(gap, E_star_Pa, strip_width_m, grid)) return status_solution(SolveStatus::InvalidInput, method);
  const double h_min = grid.h_m[deepest_strip(grid, {0, grid.size()})];
  NormalSolution solution =
      solve_load_by_approach([&](double approach) { return solve(grid, approach); }, h_min,
                             hertz_start_approach(grid, E_star_Pa, normal_force_N), normal_force_N, method);
  solution.solve_time_s = seconds_since(start);
  return solution;
}

}  // namespace ctab::gen
