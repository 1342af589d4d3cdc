// SPDX-License-Identifier: Apache-2.0
// Stability where methods fail: random (seeded) non-Hertzian gaps, negative curvature, no contact, extreme
// loads and degenerate inputs always return a status, and never a NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "ctab/core/error.hpp"
#include "ctab/contact/hertz_strip.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"

using namespace ctab::gen;

namespace {

const double kEStar = effective_modulus(kSteel, kSteel);

void expect_finite(const NormalSolution& s) {
  EXPECT_TRUE(std::isfinite(s.approach_m));
  EXPECT_TRUE(std::isfinite(s.normal_load_N));
  for (const auto& p : s.patches) {
    EXPECT_TRUE(std::isfinite(p.area_m2) && std::isfinite(p.max_pressure_Pa) && std::isfinite(p.normal_force_N));
    for (const auto& strip : p.strips) EXPECT_TRUE(std::isfinite(strip.half_length_m) && std::isfinite(strip.p0_Pa));
  }
}

// A wavy gap: base parabola plus random harmonics (non-convex in places), curvature consistent with h.
GapProfile random_gap(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double base = 1.0 + 40.0 * u(rng);  // B0 [1/m]
  const double amplitude = 2e-6 * u(rng), wavelength = 1e-3 + 8e-3 * u(rng), phase = 6.283 * u(rng);
  const double A = 0.5 + 3.0 * u(rng);
  const double k = 6.283185307179586 / wavelength;
  return sample_gap(
      -0.025, 0.025, 0.05e-3, [=](double y) { return base * y * y + amplitude * std::sin(k * y + phase); },
      [=](double) { return A; }, [=](double y) { return base - 0.5 * amplitude * k * k * std::sin(k * y + phase); },
      "random");
}

int case_count() {
  const char* env = std::getenv("CTAB_RANDOM_CASES");
  return env ? std::max(1, std::atoi(env)) : 40;
}

}  // namespace

TEST(Mim1dRobustness, RandomGapsAlwaysReturnAStatusAndNoNaN) {
  std::mt19937 rng(20221);
  int converged = 0;
  const int cases = case_count();
  for (int c = 0; c < cases; ++c) {
    const GapProfile gap = random_gap(rng);
    Mim1dSolver solver(gap, kEStar, {});
    const double force = std::pow(10.0, 3.0 + 3.0 * std::uniform_real_distribution<double>(0, 1)(rng));
    const NormalSolution s = solver.solve_for_load(force);
    expect_finite(s);
    if (s.status == SolveStatus::Converged) {
      ++converged;
      EXPECT_NEAR(s.normal_load_N, force, 1e-6 * force);
    }
  }
  EXPECT_EQ(converged, cases);  // these gaps are all solvable: a failure here is a solver defect
}

TEST(Mim1dRobustness, EdgeCasesAreStatuses) {
  Mim1dSolver solver(sphere_on_flat_gap(0.04, 0.01, 0.05e-3), kEStar, {});
  EXPECT_EQ(solver.solve_for_approach(-1e-4).status, SolveStatus::NoContact);
  EXPECT_EQ(solver.solve_for_approach(0.0).status, SolveStatus::NoContact);
  EXPECT_EQ(solver.solve_for_approach(NAN).status, SolveStatus::InvalidInput);
  EXPECT_EQ(solver.solve_for_load(0.0).status, SolveStatus::NoContact);
  EXPECT_EQ(solver.solve_for_load(-5.0).status, SolveStatus::InvalidInput);
  EXPECT_EQ(solver.solve_for_load(INFINITY).status, SolveStatus::InvalidInput);
  // A contact wider than the gap data is flagged, not silently truncated.
  const NormalSolution wide = solver.solve_for_approach(3e-3);
  EXPECT_EQ(wide.status, SolveStatus::ZoneTruncated);
  expect_finite(wide);
  // Tiny and huge loads.
  for (const double force : {1e-3, 1.0, 1e8}) expect_finite(solver.solve_for_load(force));
  EXPECT_EQ(solve_hertz_for_approach(sphere_on_flat_gap(0.04, 0.01, 0.05e-3), kEStar, 2e-4, -1.0).status,
            SolveStatus::NoContact);
}

TEST(Mim1dRobustness, ConcaveGapUsesTheCurvatureFloor) {
  // Lateral curvature negative at the first contact point (conformal-like), convex further out.
  const GapProfile gap = sample_gap(
      -0.02, 0.02, 0.05e-3, [](double y) { return 2e4 * y * y * y * y - 2.0 * y * y + 5e-5; },
      [](double) { return 1.1; }, [](double y) { return 12e4 * y * y - 2.0; }, "w-shaped");
  Mim1dSolver solver(gap, kEStar, {});
  const NormalSolution s = solver.solve_for_load(50e3);
  EXPECT_EQ(s.status, SolveStatus::Converged);
  expect_finite(s);
}

TEST(Mim1dRobustness, InvalidSetupThrowsAtTheBoundary) {
  const GapProfile gap = sphere_on_flat_gap(0.04, 0.01, 0.05e-3);
  Mim1dOptions options;
  options.strip_width_m = -1.0;
  EXPECT_THROW(Mim1dSolver(gap, kEStar, options), InputError);
  options.strip_width_m = 0.05;  // fewer than 3 strips in the data
  EXPECT_THROW(Mim1dSolver(gap, kEStar, options), InputError);
  EXPECT_THROW(Mim1dSolver(gap, -1.0, Mim1dOptions{}), InputError);
}
