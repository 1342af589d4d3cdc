// SPDX-License-Identifier: Apache-2.0
// First-order predictions from a converged MIM-1D solve (used by the wheel-rail gap passes):
// Mim1dSolver::approach_sensitivity against finite differences of full solves, and shift_warm_start, which must
// start a perturbed solve closer to its solution and converge to the cold solve's result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"

using namespace ctab::gen;

namespace {

const double kEStar = effective_modulus(kSteel, kSteel);
constexpr double kForce_N = 80e3;
constexpr double kBendLength_m = 0.002;  // the perturbation dh = eps (1 + (y / L)^2): a shift and a bend

// A non-Hertzian tread-like gap: parabola with a quartic term and a slight tilt [m].
double base_gap(double y) { return 8.0 * y * y + 2e4 * y * y * y * y + 1e-4 * y; }

double perturbation_shape(double y) { return 1.0 + (y / kBendLength_m) * (y / kBendLength_m); }

GapProfile gap_plus(double eps_m) {
  return sample_gap(
      -0.02, 0.02, 0.1e-3, [=](double y) { return base_gap(y) + eps_m * perturbation_shape(y); },
      [](double) { return 2.0; }, [](double y) { return 8.0 + 12.0 * 2e4 * y * y; }, "sensitivity");
}

// dh at every strip of the solver's grid for the perturbation of size eps_m.
std::vector<double> strip_perturbation(const Mim1dSolver& solver, double eps_m) {
  std::vector<double> dh;
  for (const double y : solver.grid().y_m) dh.push_back(eps_m * perturbation_shape(y));
  return dh;
}

}  // namespace

TEST(Mim1dSensitivity, UniformShiftMovesTheApproachByTheShift) {
  Mim1dSolver solver(gap_plus(0.0), kEStar, {});
  ASSERT_EQ(solver.solve_for_load(kForce_N).status, SolveStatus::Converged);
  const std::vector<double> uniform(solver.grid().size(), 1e-9);
  const std::optional<double> d_approach = solver.approach_sensitivity(uniform);
  ASSERT_TRUE(d_approach.has_value());
  EXPECT_NEAR(*d_approach, 1e-9, 1e-9 * 1e-10);  // 1^T J^-1 1 / 1^T J^-1 1
}

TEST(Mim1dSensitivity, ApproachChangeMatchesFiniteDifferences) {
  constexpr double eps = 1e-8;  // 1e-4 of the ~0.1 mm approach
  constexpr double dF = 80.0;   // 1e-3 of the load
  Mim1dSolver solver(gap_plus(0.0), kEStar, {});
  const NormalSolution base = solver.solve_for_load(kForce_N);
  ASSERT_EQ(base.status, SolveStatus::Converged);
  const std::optional<double> by_gap = solver.approach_sensitivity(strip_perturbation(solver, eps));
  const std::optional<double> by_load = solver.approach_sensitivity(strip_perturbation(solver, 0.0), dF);
  ASSERT_TRUE(by_gap && by_load);

  Mim1dSolver perturbed(gap_plus(eps), kEStar, {});
  const NormalSolution moved_gap = perturbed.solve_for_load(kForce_N);
  Mim1dSolver loaded(gap_plus(0.0), kEStar, {});
  const NormalSolution moved_load = loaded.solve_for_load(kForce_N + dF);
  ASSERT_EQ(moved_gap.status, SolveStatus::Converged);
  ASSERT_EQ(moved_load.status, SolveStatus::Converged);
  const double fd_gap = moved_gap.approach_m - base.approach_m;
  const double fd_load = moved_load.approach_m - base.approach_m;
  // First order (the factorisation of the step before convergence, a discrete active set): measured 3e-3 (gap)
  // and 6e-4 (load) relative.
  EXPECT_NEAR(*by_gap, fd_gap, 1e-2 * std::abs(fd_gap));
  EXPECT_NEAR(*by_load, fd_load, 1e-2 * std::abs(fd_load));
  // The bend matters: the uniform part alone (eps) is off by far more than the tolerance above.
  EXPECT_GT(std::abs(fd_gap - eps), 5e-2 * std::abs(fd_gap));
}

TEST(Mim1dSensitivity, ShiftedWarmStartConvergesToTheColdResultInFewerIterations) {
  constexpr double eps = 2e-6;  // a pass-sized move (a few % of the approach)
  constexpr double dF = 2e3;
  Mim1dSolver solver(gap_plus(0.0), kEStar, {});
  const NormalSolution base = solver.solve_for_load(kForce_N);
  ASSERT_EQ(base.status, SolveStatus::Converged);
  Mim1dWarmStart plain, shifted;
  solver.save_warm_start(base, plain);
  shifted = plain;
  ASSERT_TRUE(solver.shift_warm_start(strip_perturbation(solver, eps), dF, shifted));

  Mim1dSolver cold(gap_plus(eps), kEStar, {}), from_plain(gap_plus(eps), kEStar, {}),
      from_shifted(gap_plus(eps), kEStar, {});
  const NormalSolution reference = cold.solve_for_load(kForce_N + dF);
  const NormalSolution a = from_plain.solve_for_load(kForce_N + dF, plain);
  const NormalSolution b = from_shifted.solve_for_load(kForce_N + dF, shifted);
  ASSERT_EQ(reference.status, SolveStatus::Converged);
  ASSERT_EQ(a.status, SolveStatus::Converged);
  ASSERT_EQ(b.status, SolveStatus::Converged);
  EXPECT_LT(b.iterations, a.iterations);
  EXPECT_NEAR(b.approach_m, reference.approach_m, 1e-9 * reference.approach_m);
  EXPECT_NEAR(b.normal_load_N, reference.normal_load_N, 1e-9 * reference.normal_load_N);
  ASSERT_EQ(b.patches.size(), reference.patches.size());
  EXPECT_NEAR(b.patches[0].area_m2, reference.patches[0].area_m2, 1e-8 * reference.patches[0].area_m2);
}

TEST(Mim1dSensitivity, NoPredictionWithoutANewtonFactorisation) {
  Mim1dOptions fixed_point;
  fixed_point.update = Mim1dUpdate::FixedPoint;
  Mim1dSolver solver(gap_plus(0.0), kEStar, fixed_point);
  const NormalSolution solved = solver.solve_for_load(kForce_N);
  ASSERT_TRUE(is_success(solved.status));
  EXPECT_FALSE(solver.approach_sensitivity(strip_perturbation(solver, 1e-9)).has_value());
  Mim1dWarmStart start;
  solver.save_warm_start(solved, start);
  const Mim1dWarmStart before = start;
  EXPECT_FALSE(solver.shift_warm_start(strip_perturbation(solver, 1e-9), 1.0, start));
  EXPECT_EQ(start.loads_N, before.loads_N);
  EXPECT_EQ(start.depth_m, before.depth_m);

  Mim1dSolver unsolved(gap_plus(0.0), kEStar, {});  // no solve yet: nothing to predict from
  EXPECT_FALSE(unsolved.approach_sensitivity(strip_perturbation(unsolved, 1e-9)).has_value());
}

// Two interpenetrating basins (tread and flange root in one window): a neighbour's solution starts such a gap cold
// (the discrete problem may hold more than one self-consistent set), an earlier solve of the same contact
// (same_contact, the wheel-rail gap passes) warm, converging to the cold result in fewer iterations.
TEST(Mim1dSensitivity, SameContactWarmStartAppliesWithTwoBasins) {
  constexpr double kBasinOffset_m = 4e-3;  // the second basin's centre [m]
  constexpr double kBasinLift_m = 5e-6;    // and how much shallower it is [m]
  auto two_basins = [](double eps_m) {
    auto h = [=](double y) {
      const double u = y - kBasinOffset_m;
      return std::min(8.0 * y * y, 30.0 * u * u + kBasinLift_m) + eps_m * perturbation_shape(y);
    };
    return sample_gap(
        -0.01, 0.012, 0.05e-3, h, [](double) { return 2.0; },
        [=](double y) { return 8.0 * y * y < 30.0 * (y - kBasinOffset_m) * (y - kBasinOffset_m) ? 8.0 : 30.0; },
        "two basins");
  };
  constexpr double eps = 2e-7;
  Mim1dSolver solver(two_basins(0.0), kEStar, {});
  const NormalSolution base = solver.solve_for_load(kForce_N);
  ASSERT_EQ(base.status, SolveStatus::Converged);
  ASSERT_EQ(base.patches.size(), 2u);  // both basins carry load
  Mim1dWarmStart neighbour, same;
  solver.save_warm_start(base, neighbour);
  same = neighbour;
  same.same_contact = true;

  Mim1dSolver cold(two_basins(eps), kEStar, {}), from_neighbour(two_basins(eps), kEStar, {}),
      from_same(two_basins(eps), kEStar, {});
  const NormalSolution reference = cold.solve_for_load(kForce_N);
  const NormalSolution a = from_neighbour.solve_for_load(kForce_N, neighbour);
  const NormalSolution b = from_same.solve_for_load(kForce_N, same);
  ASSERT_EQ(reference.status, SolveStatus::Converged);
  ASSERT_EQ(a.status, SolveStatus::Converged);
  ASSERT_EQ(b.status, SolveStatus::Converged);
  EXPECT_EQ(a.iterations, reference.iterations);  // started cold
  EXPECT_LT(b.iterations, reference.iterations);
  EXPECT_NEAR(b.approach_m, reference.approach_m, 1e-9 * reference.approach_m);
  ASSERT_EQ(b.patches.size(), reference.patches.size());
  for (std::size_t k = 0; k < b.patches.size(); ++k)
    EXPECT_NEAR(b.patches[k].normal_force_N, reference.patches[k].normal_force_N, 1e-8 * kForce_N) << "patch " << k;
}
