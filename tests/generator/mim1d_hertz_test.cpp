// SPDX-License-Identifier: Apache-2.0
// MIM-1D on the paper's Hertzian case (3.1.1) against analytic Hertz: sphere R = 40 mm on a flat, steel,
// strips 0.2 mm. Acceptance bar of the foundation issue.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/fixtures/paper_cases.hpp"

using namespace ctab::gen;

namespace {
const double kEStar = effective_modulus(kSteel, kSteel);
const double kCurvature = 1.0 / (2.0 * paper::kSphereRadius_m);
}  // namespace

TEST(Mim1dHertz, PrescribedApproach) {
  Mim1dSolver solver(paper::hertz_sphere_gap(), kEStar, {});
  const NormalSolution s = solver.solve_for_approach(1e-3);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  ASSERT_EQ(s.patches.size(), 1u);
  const HertzContact exact = hertz_from_approach(kCurvature, kCurvature, kEStar, 1e-3);
  EXPECT_NEAR(exact.normal_force_N, 963.74e3, 0.01e3);
  EXPECT_NEAR(s.normal_load_N / exact.normal_force_N - 1.0, 0.0, 0.002);
  EXPECT_NEAR(s.patches[0].area_m2 / exact.area_m2 - 1.0, 0.0, 0.003);
  EXPECT_NEAR(s.patches[0].max_pressure_Pa / exact.max_pressure_Pa - 1.0, 0.0, 0.003);
  EXPECT_LT(s.residual, 1e-10);
  // Strip half-lengths follow the circle a(y) = sqrt(a0^2 - y^2) to 1 % of a0 on every strip that lies wholly
  // inside the Hertz contact. The two boundary strips (centre 6.3 mm, edge of contact at 6.3246 mm) straddle
  // the edge; they deviate by 1.13 % of a0 (0.485 vs 0.557 mm) and are checked at 1.2 %.
  const double a0 = exact.semi_axis_x_m, half_width = 0.1e-3;
  int boundary_strips = 0;
  for (const StripSolution& strip : s.patches[0].strips) {
    const double circle = std::sqrt(std::max(0.0, a0 * a0 - strip.y_m * strip.y_m));
    const bool straddles_edge = std::abs(strip.y_m) + half_width > a0;
    boundary_strips += straddles_edge;
    EXPECT_NEAR(strip.half_length_m, circle, (straddles_edge ? 0.012 : 0.01) * a0) << "y = " << strip.y_m;
  }
  EXPECT_EQ(boundary_strips, 2);
  EXPECT_NEAR(s.patches[0].centre_of_pressure_y_m, 0.0, 1e-9);
}

TEST(Mim1dHertz, PrescribedLoad) {
  Mim1dSolver solver(paper::hertz_sphere_gap(), kEStar, {});
  const NormalSolution s = solver.solve_for_load(963e3);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  const HertzContact exact = hertz_from_load(kCurvature, kCurvature, kEStar, 963e3);
  EXPECT_NEAR(s.approach_m / exact.approach_m - 1.0, 0.0, 0.001);
  EXPECT_NEAR(s.normal_load_N, 963e3, 1e-6 * 963e3);
}

TEST(Mim1dHertz, FixedPointIterationAgreesWithNewton) {
  Mim1dOptions options;
  options.update = Mim1dUpdate::FixedPoint;
  Mim1dSolver fixed_point(paper::hertz_sphere_gap(), kEStar, options);
  Mim1dSolver newton(paper::hertz_sphere_gap(), kEStar, {});
  const NormalSolution a = fixed_point.solve_for_load(963e3), b = newton.solve_for_load(963e3);
  ASSERT_EQ(a.status, SolveStatus::Converged);
  ASSERT_EQ(b.status, SolveStatus::Converged);
  EXPECT_GT(a.iterations, b.iterations);
  EXPECT_NEAR(a.approach_m / b.approach_m - 1.0, 0.0, 1e-8);
  EXPECT_NEAR(a.patches[0].area_m2 / b.patches[0].area_m2 - 1.0, 0.0, 1e-8);
}

TEST(Mim1dHertz, FinerStripsConvergeToHertz) {
  const HertzContact exact = hertz_from_approach(kCurvature, kCurvature, kEStar, 1e-3);
  double previous_error = 1.0;
  for (const double width : {0.4e-3, 0.2e-3, 0.1e-3}) {
    Mim1dOptions options;
    options.strip_width_m = width;
    Mim1dSolver solver(paper::hertz_sphere_gap(), kEStar, options);
    const NormalSolution s = solver.solve_for_approach(1e-3);
    ASSERT_EQ(s.status, SolveStatus::Converged);
    const double error = std::abs(s.patches[0].area_m2 / exact.area_m2 - 1.0);
    EXPECT_LT(error, 0.01) << "width " << width;
    previous_error = std::min(previous_error, error);
  }
  EXPECT_LT(previous_error, 0.003);
}
