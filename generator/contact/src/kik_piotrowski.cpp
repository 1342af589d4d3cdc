// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/kik_piotrowski.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "ctab/contact/semi_analytic.hpp"
#include "ctab/contact/strip_grid.hpp"
#include "ctab/contact/strip_kernel.hpp"

namespace ctab::gen {

namespace {

constexpr const char* kMethod = "kp";

// Displacement at the centre of strip m per unit peak pressure of strip j (half-length a_j) [m/Pa].
double strip_influence(const StripGrid& grid, double E_star_Pa, std::size_t m, std::size_t j, double a_j) {
  const StripKernel& kernel = StripKernel::instance();
  const double d = grid.y_m[m] - grid.y_m[j], b = grid.half_width_m();
  return 2.0 * a_j / (std::numbers::pi * E_star_Pa) * (kernel.value((d + b) / a_j) - kernel.value((d - b) / a_j));
}

// One virtual patch: p0_j = (delta - h_m) x_l,j / sum_j x_l,j C_mj (step 5).
void load_patch(const StripGrid& grid, double E_star_Pa, double approach_m, StripRun patch,
                const std::vector<double>& half_length, std::vector<double>& p0) {
  const std::size_t m = deepest_strip(grid, patch);
  double displacement_per_unit = 0.0;  // sum_j x_l,j C_mj [m^2/Pa]
  for (std::size_t j = patch.begin; j < patch.end; ++j)
    displacement_per_unit += half_length[j] * strip_influence(grid, E_star_Pa, m, j, half_length[j]);
  const double scale = (approach_m - grid.h_m[m]) / displacement_per_unit;  // p0 / x_l0 [Pa/m]
  for (std::size_t j = patch.begin; j < patch.end; ++j) p0[j] = scale * half_length[j];
}

NormalSolution kp_on_grid(const StripGrid& grid, double E_star_Pa, double approach_m) {
  const std::size_t n = grid.size();
  std::vector<double> depth(n), virtual_depth(n, 0.0), half_length(n, 0.0), p0(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) depth[i] = approach_m - grid.h_m[i];
  for (const StripRun basin : positive_runs(depth)) {
    const double h_k = grid.h_m[deepest_strip(grid, basin)];
    for (std::size_t i = basin.begin; i < basin.end; ++i)
      virtual_depth[i] = kKikPiotrowskiEpsilon * (approach_m - h_k) - (grid.h_m[i] - h_k);  // step 2
  }
  for (std::size_t i = 0; i < n; ++i)
    if (virtual_depth[i] > 0.0) half_length[i] = std::sqrt(virtual_depth[i] / grid.A_per_m[i]);  // step 3
  for (const StripRun patch : positive_runs(virtual_depth))
    load_patch(grid, E_star_Pa, approach_m, patch, half_length, p0);
  return solution_from_strips(grid, half_length, p0, kMethod, approach_m);
}

}  // namespace

NormalSolution solve_kp_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m, double approach_m) {
  return solve_on_strips_for_approach(gap, E_star_Pa, strip_width_m, approach_m, kMethod,
                                      [E_star_Pa](const StripGrid& grid, double approach) {
                                        return kp_on_grid(grid, E_star_Pa, approach);
                                      });
}

NormalSolution solve_kp_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m, double normal_force_N) {
  return solve_on_strips_for_load(gap, E_star_Pa, strip_width_m, normal_force_N, kMethod,
                                  [E_star_Pa](const StripGrid& grid, double approach) {
                                    return kp_on_grid(grid, E_star_Pa, approach);
                                  });
}

}  // namespace ctab::gen
