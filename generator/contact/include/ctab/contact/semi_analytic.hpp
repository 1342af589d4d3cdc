// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Shared machinery of the non-iterative strip rungs (Kik-Piotrowski, ANALYN): runs of interpenetrating
//! strips, patches from per-strip half-lengths and peak pressures, and the prescribed-load solve as a root
//! search on the approach.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/normal_solution.hpp"
#include "ctab/contact/strip_grid.hpp"

namespace ctab::gen {

//! Strips [begin, end) of a grid.
struct StripRun {
  std::size_t begin = 0, end = 0;
};

//! Maximal runs of strips with depth[i] > 0, in increasing order.
[[nodiscard]] std::vector<StripRun> positive_runs(const std::vector<double>& depth);

//! Index of the smallest h_m[i] in the run (the run's deepest rigid point).
[[nodiscard]] std::size_t deepest_strip(const StripGrid& grid, StripRun run);

//! A solution from per-strip half-lengths a_i [m] and peak pressures p0_i [Pa] (a_i = 0: not in contact).
//! Strip load N_i = pi a_i b p0_i (semi-elliptic along x, width 2b); patches are the maximal runs of loaded
//! strips. Status Converged (NoContact without a loaded strip; ZoneTruncated when a loaded strip is the first or
//! last of the grid: the contact may reach beyond the gap data).
[[nodiscard]] NormalSolution solution_from_strips(const StripGrid& grid, const std::vector<double>& half_length_m,
                                                  const std::vector<double>& p0_Pa, const char* method,
                                                  double approach_m);

//! A solution carrying only a status (no patches).
[[nodiscard]] NormalSolution status_solution(SolveStatus status, const char* method, double approach_m = 0.0);

//! Solves for a prescribed normal force [N] with a solver for a prescribed approach: the Illinois root finder
//! on N(delta) - F, bracketed from [h_min, h_min + start_approach_m] (doubled until N exceeds F). The force
//! tolerance is kLoadTolerance x F. outer_iterations counts the approach solves.
inline constexpr double kLoadTolerance = 1e-10;
[[nodiscard]] NormalSolution solve_load_by_approach(const std::function<NormalSolution(double)>& at_approach,
                                                    double h_min_m, double start_approach_m, double normal_force_N,
                                                    const char* method);

//! A rung's solver on a strip grid for a prescribed approach [m] (E* fixed by the caller).
using GridSolver = std::function<NormalSolution(const StripGrid& grid, double approach_m)>;

//! Builds the strip grid and runs `solve` for a prescribed approach [m]; InvalidInput (no exception) for a gap
//! that fails validate(), a bad strip width, E* or approach. Sets solve_time_s.
[[nodiscard]] NormalSolution solve_on_strips_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                                          double approach_m, const char* method,
                                                          const GridSolver& solve);
//! The same for a prescribed normal force [N] (solve_load_by_approach from hertz_start_approach).
[[nodiscard]] NormalSolution solve_on_strips_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                                      double normal_force_N, const char* method,
                                                      const GridSolver& solve);

//! Approach beyond the deepest point that Hertz predicts for the force, with the curvatures of the deepest
//! strip (B raised to A/20); a start value for solve_load_by_approach [m]. 0.1 mm if Hertz fails.
[[nodiscard]] double hertz_start_approach(const StripGrid& grid, double E_star_Pa, double normal_force_N);

}  // namespace ctab::gen
