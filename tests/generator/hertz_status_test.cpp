// SPDX-License-Identifier: Apache-2.0
// Hertz statuses (issue 8): a Hertz patch that runs past the gap data is zone-truncated, and over- or underflow
// on finite input is a numerical failure, never `converged` with an infinite pressure: what MIM-1D reports.
#include <gtest/gtest.h>

#include <cmath>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/hertz_strip.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/io/gap_csv.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

const double kEStar = effective_modulus(kSteel, kSteel);

GapProfile sphere_gap() { return read_gap_csv(ctab::test::source_path("examples/gaps/hertz_sphere_r40.csv")); }

}  // namespace

TEST(HertzStatus, PatchPastTheDataIsZoneTruncatedLikeMim1d) {
  const GapProfile gap = sphere_gap();  // y spans +-12 mm; at 5 mm approach the Hertz circle has radius 14.1 mm
  const NormalSolution hertz = solve_hertz_for_approach(gap, kEStar, 0.2e-3, 5e-3);
  EXPECT_EQ(hertz.status, SolveStatus::ZoneTruncated);
  Mim1dSolver mim1d(gap, kEStar, Mim1dOptions{});
  EXPECT_EQ(mim1d.solve_for_approach(5e-3).status, SolveStatus::ZoneTruncated);
  // Inside the data it stays converged.
  EXPECT_EQ(solve_hertz_for_approach(gap, kEStar, 0.2e-3, 1e-3).status, SolveStatus::Converged);
  const double load_past_the_data = hertz.normal_load_N;
  EXPECT_EQ(solve_hertz_for_load(gap, kEStar, 0.2e-3, load_past_the_data).status, SolveStatus::ZoneTruncated);
}

TEST(HertzStatus, OverflowOnFiniteInputIsANumericalFailure) {
  GapProfile gap = sphere_gap();
  for (std::size_t i = 0; i < gap.size(); ++i) {  // the whole gap scaled by 1e300
    gap.h_m[i] *= 1e300;
    gap.A_per_m[i] *= 1e300;
    gap.B_per_m[i] *= 1e300;
  }
  const NormalSolution solution = solve_hertz_for_load(gap, kEStar, 0.2e-3, 1e3);
  EXPECT_EQ(solution.status, SolveStatus::NumericalFailure);
  EXPECT_TRUE(solution.patches.empty());
  const HertzContact contact = hertz_from_load(1.25e301, 1.25e301, kEStar, 1e3);
  EXPECT_EQ(contact.status, SolveStatus::NumericalFailure);
  EXPECT_FALSE(std::isinf(contact.max_pressure_Pa));
  // Non-finite input stays invalid input.
  EXPECT_EQ(hertz_from_load(INFINITY, 1.0, kEStar, 1e3).status, SolveStatus::InvalidInput);
}

TEST(HertzStatus, WheelRailAtTenMillimetresApproachIsZoneTruncated) {
  const SweepSetup setup = make_sweep_setup(parse_table_config(R"(
[solver]
mode = "wheel"
method = "hertz"
[axes]
lateral_displacement_m = { start = 0.0, stop = 1e-3, step = 1e-3 }
approach_m = 10e-3
)",
                                                               "hertz.toml"));
  EXPECT_EQ(solve_table_case(setup, 0.0, 10e-3).wheels[0].contact.status, SolveStatus::ZoneTruncated);
  EXPECT_EQ(solve_table_case(setup, 0.0, 0.1e-3).wheels[0].contact.status, SolveStatus::Converged);
}
