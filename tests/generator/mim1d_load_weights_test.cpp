// SPDX-License-Identifier: Apache-2.0
// Load weights in MIM-1D (Mim1dSolver::set_load_weights): the prescribed load becomes sum_i w_i N_i, as a
// wheel-rail conformal patch prescribes its vertical load (w_i the cosine of each strip's normal inclination).
// Checked against the unweighted solver: the same gap carrying the same normal force must give the same solution,
// whichever of the two loads was prescribed.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "ctab/core/error.hpp"
#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"

using namespace ctab::gen;

namespace {

const double kEStar = effective_modulus(kSteel, kSteel);
constexpr double kVertical_N = 60e3;

// A flange-root-like gap: lateral curvature rising across the patch (B = h''/2 from 3 to 9 1/m), slightly
// tilted [m].
GapProfile root_gap() {
  return sample_gap(
      -0.015, 0.015, 0.1e-3, [](double y) { return 6.0 * y * y + 200.0 / 3.0 * y * y * y + 5e-5 * y; },
      [](double) { return 2.0; }, [](double y) { return 6.0 + 200.0 * y; }, "load weights");
}

// The normal's inclination turning by 0.4 rad across the window (a conformal patch on the flange root) [rad].
double normal_angle(double y) { return -0.5 + 27.0 * y; }

std::vector<double> cosine_weights(const Mim1dSolver& solver) {
  std::vector<double> w;
  for (const double y : solver.grid().y_m) w.push_back(std::cos(normal_angle(y)));
  return w;
}

// sum_i w(y_i) N_i over the solution's strips, summed here from the strips (not the solver's own sum).
double weighted_load(const NormalSolution& solution) {
  double sum = 0.0;
  for (const PatchSolution& patch : solution.patches)
    for (const StripSolution& strip : patch.strips) sum += std::cos(normal_angle(strip.y_m)) * strip.load_N;
  return sum;
}

}  // namespace

TEST(Mim1dLoadWeights, PrescribedWeightedLoadIsMet) {
  for (const Mim1dUpdate update : {Mim1dUpdate::Newton, Mim1dUpdate::FixedPoint}) {
    Mim1dOptions options;
    options.update = update;
    Mim1dSolver solver(root_gap(), kEStar, options);
    solver.set_load_weights(cosine_weights(solver));
    const NormalSolution solved = solver.solve_for_load(kVertical_N);
    ASSERT_EQ(solved.status, SolveStatus::Converged) << static_cast<int>(update);
    EXPECT_NEAR(weighted_load(solved), kVertical_N, 1e-10 * kVertical_N) << static_cast<int>(update);
    // The normal force exceeds the vertical one: every weight is below 1.
    EXPECT_GT(solved.normal_load_N, 1.05 * kVertical_N);
  }
}

TEST(Mim1dLoadWeights, SameSolutionAsTheUnweightedSolveAtItsNormalForce) {
  Mim1dSolver weighted(root_gap(), kEStar, {});
  weighted.set_load_weights(cosine_weights(weighted));
  const NormalSolution by_vertical = weighted.solve_for_load(kVertical_N);
  ASSERT_EQ(by_vertical.status, SolveStatus::Converged);

  Mim1dSolver plain(root_gap(), kEStar, {});
  const NormalSolution by_normal = plain.solve_for_load(by_vertical.normal_load_N);
  ASSERT_EQ(by_normal.status, SolveStatus::Converged);
  EXPECT_NEAR(by_vertical.approach_m, by_normal.approach_m, 1e-9 * by_normal.approach_m);
  ASSERT_EQ(by_vertical.patches.size(), by_normal.patches.size());
  const auto& a = by_vertical.patches.front().strips;
  const auto& b = by_normal.patches.front().strips;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i].load_N, b[i].load_N, 1e-8 * by_normal.normal_load_N);
}

TEST(Mim1dLoadWeights, UniformWeightsScaleTheLoad) {
  constexpr double c = 0.8;
  Mim1dSolver weighted(root_gap(), kEStar, {});
  weighted.set_load_weights(std::vector<double>(weighted.grid().size(), c));
  const NormalSolution scaled = weighted.solve_for_load(c * 75e3);
  Mim1dSolver plain(root_gap(), kEStar, {});
  const NormalSolution direct = plain.solve_for_load(75e3);
  ASSERT_EQ(scaled.status, SolveStatus::Converged);
  ASSERT_EQ(direct.status, SolveStatus::Converged);
  EXPECT_NEAR(scaled.normal_load_N, 75e3, 1e-10 * 75e3);
  EXPECT_NEAR(scaled.approach_m, direct.approach_m, 1e-9 * direct.approach_m);
}

TEST(Mim1dLoadWeights, SensitivityToTheWeightedLoadMatchesFiniteDifferences) {
  constexpr double dV = 60.0;  // 1e-3 of the load
  Mim1dSolver solver(root_gap(), kEStar, {});
  solver.set_load_weights(cosine_weights(solver));
  const NormalSolution base = solver.solve_for_load(kVertical_N);
  ASSERT_EQ(base.status, SolveStatus::Converged);
  const std::optional<double> predicted =
      solver.approach_sensitivity(std::vector<double>(solver.grid().size(), 0.0), dV);
  ASSERT_TRUE(predicted.has_value());
  Mim1dSolver loaded(root_gap(), kEStar, {});
  loaded.set_load_weights(cosine_weights(loaded));
  const NormalSolution moved = loaded.solve_for_load(kVertical_N + dV);
  ASSERT_EQ(moved.status, SolveStatus::Converged);
  const double fd = moved.approach_m - base.approach_m;
  EXPECT_NEAR(*predicted, fd, 1e-2 * std::abs(fd));  // first order, as Mim1dSensitivity
}

TEST(Mim1dLoadWeights, ResetClearsTheWeights) {
  Mim1dSolver solver(root_gap(), kEStar, {});
  solver.set_load_weights(std::vector<double>(solver.grid().size(), 0.5));
  solver.reset(root_gap());
  const NormalSolution solved = solver.solve_for_load(kVertical_N);
  ASSERT_EQ(solved.status, SolveStatus::Converged);
  EXPECT_NEAR(solved.normal_load_N, kVertical_N, 1e-10 * kVertical_N);
}

TEST(Mim1dLoadWeights, BadWeightsAreRejected) {
  Mim1dSolver solver(root_gap(), kEStar, {});
  const std::size_t n = solver.grid().size();
  EXPECT_THROW(solver.set_load_weights(std::vector<double>(n - 1, 1.0)), InputError);
  std::vector<double> w(n, 1.0);
  w[n / 2] = 0.0;
  EXPECT_THROW(solver.set_load_weights(w), InputError);
  w[n / 2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(solver.set_load_weights(w), InputError);
  EXPECT_NO_THROW(solver.set_load_weights({}));
}
