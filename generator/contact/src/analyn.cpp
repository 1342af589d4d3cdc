// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/analyn.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/semi_analytic.hpp"
#include "ctab/contact/strip_grid.hpp"

namespace ctab::gen {

namespace {

constexpr const char* kMethod = "analyn";

NormalSolution analyn_on_grid(const StripGrid& grid, double E_star_Pa, double approach_m) {
  const std::size_t n = grid.size();
  std::vector<double> depth(n), half_length(n, 0.0), p0(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) depth[i] = approach_m - grid.h_m[i];
  for (const StripRun basin : positive_runs(depth)) {
    const double h_k = grid.h_m[deepest_strip(grid, basin)];  // step 1
    for (std::size_t i = basin.begin; i < basin.end; ++i) {
      const double A = std::max(grid.A_per_m[i], kAnalynMinCurvature_per_m);  // step 2
      const double B = std::max(grid.B_per_m[i], kAnalynMinCurvature_per_m);
      HertzCoefficients c;
      if (!hertz_coefficients_tabulated(A, B, c))
        return status_solution(SolveStatus::NumericalFailure, kMethod, approach_m);
      const double alpha1 = c.r * (1.0 + B / A) / (c.m * c.m), beta1 = c.r * (1.0 + A / B) / (c.n * c.n);  // step 3
      const double penetration = (approach_m - h_k) - beta1 * (grid.h_m[i] - h_k);                         // step 4
      if (!(penetration > 0.0)) continue;
      half_length[i] = std::sqrt(penetration / (alpha1 * A));                                             // step 5
      p0[i] = 2.0 * E_star_Pa / (std::numbers::pi * c.m * c.n) * std::sqrt(penetration * (A + B) / c.r);  // step 6
    }
  }
  return solution_from_strips(grid, half_length, p0, kMethod, approach_m);
}

}  // namespace

NormalSolution solve_analyn_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                         double approach_m) {
  return solve_on_strips_for_approach(gap, E_star_Pa, strip_width_m, approach_m, kMethod,
                                      [E_star_Pa](const StripGrid& grid, double approach) {
                                        return analyn_on_grid(grid, E_star_Pa, approach);
                                      });
}

NormalSolution solve_analyn_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                     double normal_force_N) {
  return solve_on_strips_for_load(gap, E_star_Pa, strip_width_m, normal_force_N, kMethod,
                                  [E_star_Pa](const StripGrid& grid, double approach) {
                                    return analyn_on_grid(grid, E_star_Pa, approach);
                                  });
}

}  // namespace ctab::gen
