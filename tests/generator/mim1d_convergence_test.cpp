// SPDX-License-Identifier: Apache-2.0
// Robust convergence (paper Figure 7): from 10 different starting potential zones the solve converges to the
// same answer (1e-6 relative), for both theoretical cases with the paper's prescribed forces.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/fixtures/paper_cases.hpp"

using namespace ctab::gen;

namespace {

void expect_same_answer_from_ten_zones(const GapProfile& gap, double force, double centre, double half_width) {
  const double E_star = effective_modulus(kSteel, kSteel);
  Mim1dSolver reference_solver(gap, E_star, {});
  const NormalSolution reference = reference_solver.solve_for_load(force);
  ASSERT_EQ(reference.status, SolveStatus::Converged);
  // Zones: shrunk, widened, shifted to either side, one-sided, a single strip.
  const std::vector<std::pair<double, double>> zones = {{centre - 0.2 * half_width, centre + 0.2 * half_width},
                                                        {centre - 0.5 * half_width, centre + 0.5 * half_width},
                                                        {centre - 2.0 * half_width, centre + 2.0 * half_width},
                                                        {centre - 5.0 * half_width, centre + 5.0 * half_width},
                                                        {centre - 1.0 * half_width, centre},
                                                        {centre, centre + 1.0 * half_width},
                                                        {centre - 0.3 * half_width, centre + 1.5 * half_width},
                                                        {centre - 1.5 * half_width, centre + 0.3 * half_width},
                                                        {centre + 0.5 * half_width, centre + 0.9 * half_width},
                                                        {centre - 1e-4, centre + 1e-4}};
  ASSERT_EQ(zones.size(), 10u);
  for (const auto& zone : zones) {
    Mim1dOptions options;
    options.starting_zone_m = zone;
    Mim1dSolver solver(gap, E_star, options);
    const NormalSolution s = solver.solve_for_load(force);
    ASSERT_EQ(s.status, SolveStatus::Converged) << "zone " << zone.first << " .. " << zone.second;
    EXPECT_NEAR(s.approach_m / reference.approach_m - 1.0, 0.0, 1e-6);
    ASSERT_EQ(s.patches.size(), reference.patches.size());
    EXPECT_NEAR(s.patches[0].area_m2 / reference.patches[0].area_m2 - 1.0, 0.0, 1e-6);
    EXPECT_NEAR(s.patches[0].max_pressure_Pa / reference.patches[0].max_pressure_Pa - 1.0, 0.0, 1e-6);
    ASSERT_EQ(s.patches[0].strips.size(), reference.patches[0].strips.size());
    for (std::size_t i = 0; i < s.patches[0].strips.size(); ++i)
      EXPECT_NEAR(s.patches[0].strips[i].p0_Pa, reference.patches[0].strips[i].p0_Pa,
                  1e-6 * reference.patches[0].max_pressure_Pa);
  }
}

}  // namespace

TEST(Mim1dConvergence, HertzianFromTenStartingZones) {
  expect_same_answer_from_ten_zones(paper::hertz_sphere_gap(), 963e3, 0.0, 6.3e-3);
}

TEST(Mim1dConvergence, NonHertzianFromTenStartingZones) {
  expect_same_answer_from_ten_zones(paper::nonhertz_gap(), 2645e3, 9.0e-3, 14e-3);
}
