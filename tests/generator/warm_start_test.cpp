// SPDX-License-Identifier: Apache-2.0
// Warm start of a sweep (table_generator.hpp, warm_start_previous_rows; Mim1dSolver::solve_for_load with a
// Mim1dWarmStart): each MIM-1D solve starts from its neighbour in dy inside fixed chains. The table must agree with
// the cold-start table within the solver tolerance, be bit-identical at 1 and 2 threads, and take fewer iterations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ctab/contact/mim1d.hpp"
#include "ctab/contact/mim1d_options.hpp"
#include "ctab/sweep/case_partition.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"

namespace {

using namespace ctab::gen;
using ctab::tables::Table;

// Fine steps over the tread, the flange root (two contacts, dy 4.5-5.5 mm) and the flange; not symmetric, so both
// wheels are solved.
const char* const kFineConfig = R"(
[solver]
mode = "wheelset"
[axes]
lateral_displacement_m = { start = -1e-3, stop = 6e-3, step = 0.05e-3 }
vertical_load_N = [50e3, 100e3]
[output]
strip_samples = 16
)";

const double kTolerance = Mim1dOptions{}.tolerance;  // the solver's relative tolerance [-]

// The fine config with [solver] warm_start set (true) or left at its default (false), and further [solver] lines.
TableConfig fine_config(bool warm_start, const std::string& solver_lines = "") {
  std::string text = kFineConfig;
  if (warm_start) text.insert(text.find("[solver]\n") + 9, "warm_start = true\n");
  text.insert(text.find("[solver]\n") + 9, solver_lines);
  return parse_table_config(text, "fine.toml");
}

Table fine_table(int threads, bool warm_start, const std::string& solver_lines = "") {
  GeneratorInfo info;
  info.threads = threads;
  return generate_table(fine_config(warm_start, solver_lines), info);
}

const Table& warm_table(int threads) {
  static const Table one = fine_table(1, true), two = fine_table(2, true);
  return threads == 1 ? one : two;
}

double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

TEST(WarmStart, ConfigKeyDefaultsToColdAndRejectsNonBooleans) {
  EXPECT_FALSE(fine_config(false).warm_start);
  EXPECT_TRUE(fine_config(true).warm_start);
  try {
    (void)
        parse_table_config("[solver]\nwarm_start = \"yes\"\n[axes]\nlateral_displacement_m = { start = 0, stop = 1e-3, "
                           "step = 1e-3 }\nvertical_load_N = 78.5e3\n",
                           "bad.toml");
    FAIL() << "a string accepted for solver.warm_start";
  } catch (const ctab::gen::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bad.toml:2"), std::string::npos) << what;
    EXPECT_NE(what.find("solver.warm_start"), std::string::npos) << what;
    EXPECT_NE(what.find("true or false"), std::string::npos) << what;
  }
}

TEST(WarmStart, PreviousRowsFollowTheWorkUnits) {
  // Not mirrored: units of 8 rows from row 0; the first row of each unit starts cold.
  const std::vector<std::size_t> plain = warm_start_previous_rows(20, false);
  for (std::size_t i = 0; i < 20; ++i) EXPECT_EQ(plain[i], i % kRowsPerUnit == 0 ? kColdStart : i - 1) << i;
  // Mirrored: every chain stays inside its (mirror-closed) unit, so any union of units holds whole chains.
  const std::size_t n = 41;
  const std::vector<std::size_t> mirrored = warm_start_previous_rows(n, true);
  const std::vector<std::vector<std::size_t>> units = sweep_units(n, true);
  std::vector<std::size_t> unit_of(n);
  for (std::size_t u = 0; u < units.size(); ++u)
    for (const std::size_t row : units[u]) unit_of[row] = u;
  std::size_t cold = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (mirrored[i] == kColdStart) {
      ++cold;
      continue;
    }
    EXPECT_EQ(mirrored[i], i - 1) << i;
    EXPECT_EQ(unit_of[mirrored[i]], unit_of[i]) << i;
  }
  EXPECT_GE(cold, units.size());
  EXPECT_LE(cold, 2 * units.size());
}

TEST(WarmStart, TableIsBitIdenticalAtOneAndTwoThreads) {
  const Table& one = warm_table(1);
  const Table& two = warm_table(2);
  EXPECT_TRUE(one.status == two.status);
  EXPECT_TRUE(one.roll_rad == two.roll_rad);
  EXPECT_TRUE(one.patch.present == two.patch.present);
  for (auto field : {&ctab::tables::PatchQuantities::normal_force_N, &ctab::tables::PatchQuantities::max_pressure_Pa,
                     &ctab::tables::PatchQuantities::approach_m, &ctab::tables::PatchQuantities::area_m2,
                     &ctab::tables::PatchQuantities::y_rail_m, &ctab::tables::PatchQuantities::strip_half_length_m,
                     &ctab::tables::PatchQuantities::strip_peak_pressure_Pa})
    EXPECT_TRUE(one.patch.*field == two.patch.*field);  // bit for bit (== on doubles, no tolerance)
}

void expect_warm_agrees_with_cold(const Table& warm, const Table& cold) {
  ASSERT_TRUE(warm.status == cold.status);
  ASSERT_TRUE(warm.patch.present == cold.patch.present);  // the same patches in the same slots
  const std::size_t n_second = warm.second_axis.size(), slots = warm.n_slots;
  double worst_force = 0.0;
  for (std::size_t k = 0; k < warm.patch.present.size(); ++k) {
    const double load = warm.second_axis[(k / (slots * ctab::tables::kWheels)) % n_second];
    const double force = std::abs(warm.patch.normal_force_N[k] - cold.patch.normal_force_N[k]) / load;
    worst_force = std::max(worst_force, force);
    // Each solve meets its load to the tolerance, a shared approach to 10x (wheelrail_contact.cpp): 2 x 10 x tol.
    EXPECT_LE(force, 20.0 * kTolerance) << "entry " << k;
  }
  std::printf("warm vs cold: worst normal force difference %.2e of the load\n", worst_force);
  // Geometry and pressure fields: within 1000 x tol of the field's largest value (strip lengths of the lightly
  // loaded edge strips carry the loads' tolerance as sqrt; measured 2.5e-11 on the default table).
  for (auto field :
       {&ctab::tables::PatchQuantities::max_pressure_Pa, &ctab::tables::PatchQuantities::approach_m,
        &ctab::tables::PatchQuantities::area_m2, &ctab::tables::PatchQuantities::y_rail_m,
        &ctab::tables::PatchQuantities::y_cop_rail_m, &ctab::tables::PatchQuantities::contact_angle_rad,
        &ctab::tables::PatchQuantities::strip_half_length_m, &ctab::tables::PatchQuantities::strip_peak_pressure_Pa}) {
    const std::vector<double>& w = warm.patch.*field;
    const std::vector<double>& c = cold.patch.*field;
    const double scale = largest(c);
    double worst = 0.0;
    for (std::size_t k = 0; k < w.size(); ++k) worst = std::max(worst, std::abs(w[k] - c[k]) / scale);
    EXPECT_LE(worst, 1000.0 * kTolerance);
    std::printf("  field worst difference %.2e of its largest value\n", worst);
  }
}

TEST(WarmStart, TableAgreesWithColdStartWithinTheSolverTolerance) {
  expect_warm_agrees_with_cold(warm_table(2), fine_table(2, false));
}

// With CONTACT's reference angle at the deepest point the plane's inclination follows each gap pass's sampling
// approach, which starts where a cold start does: the same agreement.
TEST(WarmStart, TableAgreesWithColdStartWithContactsReferenceAngle) {
  const std::string mean = "reference_angle = \"interpenetration-mean\"\n";
  expect_warm_agrees_with_cold(fine_table(2, true, mean), fine_table(2, false, mean));
}

// Along one chain of 0.01 mm steps the warm solves agree with cold ones within the tolerance and need fewer
// MIM-1D iterations (the point of the warm start).
TEST(WarmStart, ChainNeedsFewerIterationsThanColdStarts) {
  const SweepSetup setup = make_sweep_setup(fine_config(true));
  WheelContactWorkspace workspace;
  int warm_iterations = 0, cold_iterations = 0;
  double warm_s = 0.0, cold_s = 0.0;  // wheel-rail solve times [s] (printed only: timings are not tested)
  for (const double start_m : {-0.5e-3, 1.0e-3, 3.0e-3, 4.6e-3, 5.5e-3}) {
    Mim1dWarmStart warm;
    for (int step = 0; step < 8; ++step) {
      const double dy = start_m + 1e-5 * step;
      const CaseRoll roll = solve_case_roll(setup, dy);
      const CaseWheel cold_case = solve_case_wheel(setup, 0, dy, roll, 78.5e3, workspace);
      const CaseWheel warm_case = solve_case_wheel(setup, 0, dy, roll, 78.5e3, workspace, &warm);
      ASSERT_EQ(warm_case.contact.status, cold_case.contact.status) << "dy " << dy;
      ASSERT_EQ(warm_case.contact.patches.size(), cold_case.contact.patches.size()) << "dy " << dy;
      for (std::size_t p = 0; p < cold_case.contact.patches.size(); ++p)
        EXPECT_NEAR(warm_case.contact.patches[p].normal_force_N, cold_case.contact.patches[p].normal_force_N,
                    20.0 * kTolerance * 78.5e3)
            << "dy " << dy;
      EXPECT_FALSE(warm.empty()) << "a converged case leaves its solution for the next";
      if (step > 0) {  // the first of a chain is cold either way
        warm_iterations += warm_case.contact.iterations;
        cold_iterations += cold_case.contact.iterations;
        warm_s += warm_case.contact.solve_time_s;
        cold_s += cold_case.contact.solve_time_s;
      }
    }
  }
  std::printf("35 warm-startable cases: MIM-1D iterations warm %d, cold %d; solve time warm %.2f ms, cold %.2f ms\n",
              warm_iterations, cold_iterations, 1e3 * warm_s, 1e3 * cold_s);
  EXPECT_LT(warm_iterations, cold_iterations * 9 / 10);
}

// extrapolate_warm_start: the last two solves of an equally spaced chain extrapolated linearly, strip by strip.
TEST(WarmStart, ExtrapolationIsLinearByStripIndex) {
  Mim1dWarmStart start;
  start.first_strip = 3;
  start.loads_N = {0.0, 10.0, 20.0, 5.0};  // strips 3..6
  start.depth_m = 50e-6;
  start.sampling_approach_m = 80e-6;
  start.origin_y_m = 0.01;
  Mim1dWarmStart alone;
  extrapolate_warm_start(start, alone);  // no earlier solve: the start itself
  EXPECT_EQ(alone.loads_N, start.loads_N);
  EXPECT_EQ(alone.depth_m, start.depth_m);
  EXPECT_EQ(alone.sampling_approach_m, start.sampling_approach_m);
  start.earlier.first_strip = 4;
  start.earlier.loads_N = {8.0, 30.0, 4.0, 2.0};  // strips 4..7
  start.earlier.depth_m = 49e-6;
  start.earlier.sampling_approach_m = 79e-6;
  start.same_contact = true;
  Mim1dWarmStart next;
  extrapolate_warm_start(start, next);
  EXPECT_EQ(next.first_strip, 3);
  ASSERT_EQ(next.loads_N.size(), 4u);
  EXPECT_EQ(next.loads_N[0], 0.0);   // out of the last solve: stays out
  EXPECT_EQ(next.loads_N[1], 12.0);  // 2 x 10 - 8
  EXPECT_EQ(next.loads_N[2], 10.0);  // 2 x 20 - 30 = 10
  EXPECT_EQ(next.loads_N[3], 6.0);   // 2 x 5 - 4
  start.loads_N[2] = 14.0;           // 2 x 14 - 30 < 0: half the last load
  extrapolate_warm_start(start, next);
  EXPECT_EQ(next.loads_N[2], 7.0);
  EXPECT_NEAR(next.depth_m, 51e-6, 1e-18);
  EXPECT_NEAR(next.sampling_approach_m, 81e-6, 1e-18);
  EXPECT_EQ(next.origin_y_m, 0.01);
  EXPECT_FALSE(next.same_contact);  // a neighbour's start, never the same contact
  EXPECT_TRUE(next.earlier.loads_N.empty());
  start.earlier.depth_m = 120e-6;  // an extrapolated depth <= 0 keeps the last one
  extrapolate_warm_start(start, next);
  EXPECT_EQ(next.depth_m, start.depth_m);
}

// With CONTACT's reference rule the chain's first sampling approach comes from the neighbours: extrapolated from the
// last two (with their strip loads) the 0.01 mm chains need fewer MIM-1D iterations than from the last one alone.
TEST(WarmStart, ExtrapolatedChainNeedsFewerIterationsWithTheCentreRule) {
  TableConfig config = fine_config(true);
  config.reference = ReferenceRule::InterpenetrationCentre;
  const SweepSetup setup = make_sweep_setup(config);
  WheelContactWorkspace workspace;
  int extrapolated = 0, last_only = 0;
  for (const double start_m : {-0.5e-3, 1.0e-3, 3.0e-3}) {
    Mim1dWarmStart two, one;
    for (int step = 0; step < 8; ++step) {
      const double dy = start_m + 1e-5 * step;
      const CaseRoll roll = solve_case_roll(setup, dy);
      one.earlier.loads_N.clear();  // the last solve alone
      const CaseWheel a = solve_case_wheel(setup, 0, dy, roll, 78.5e3, workspace, &two);
      const CaseWheel b = solve_case_wheel(setup, 0, dy, roll, 78.5e3, workspace, &one);
      ASSERT_EQ(a.contact.status, SolveStatus::Converged) << "dy " << dy;
      ASSERT_EQ(b.contact.status, SolveStatus::Converged) << "dy " << dy;
      if (step < 2) continue;  // the first two of a chain have no earlier solve
      extrapolated += a.contact.iterations;
      last_only += b.contact.iterations;
    }
  }
  std::printf("18 cases, CONTACT's rule: MIM-1D iterations extrapolated %d, last solve only %d\n", extrapolated,
              last_only);
  EXPECT_LT(extrapolated, last_only * 9 / 10);
}

TEST(WarmStart, SolveTableCaseReproducesWarmEntries) {
  const Table& table = warm_table(1);
  const SweepSetup setup = make_sweep_setup(fine_config(true));
  for (const std::size_t i_dy : {std::size_t{5}, std::size_t{7}, std::size_t{8}, std::size_t{115}}) {
    const CaseSolution solution = solve_table_case(setup, table.lateral_displacement_m[i_dy], 100e3);
    for (std::size_t wheel = 0; wheel < ctab::tables::kWheels; ++wheel) {
      Table one = table;
      store_case_wheel(one, setup, i_dy, 1, wheel, solution.wheels[wheel]);
      for (std::size_t slot = 0; slot < table.n_slots; ++slot) {
        const std::size_t k = table.patch_index(i_dy, 1, wheel, slot);
        EXPECT_EQ(one.patch.normal_force_N[k], table.patch.normal_force_N[k]) << i_dy << " wheel " << wheel;
        EXPECT_EQ(one.patch.max_pressure_Pa[k], table.patch.max_pressure_Pa[k]) << i_dy << " wheel " << wheel;
      }
    }
  }
}

}  // namespace

namespace {

// Shards (`ctab generate --shard K/N`) and MPI work units are unions of whole units, so they solve the same chains
// as one run: their rows, solved separately into one table, equal the single run bit for bit (mirrored or not).
TEST(WarmStart, ShardsGiveTheSingleRunsTableBitForBit) {
  for (const char* axis :
       {"{ start = -1e-3, stop = 6e-3, step = 0.05e-3 }", "{ start = -2e-3, stop = 2e-3, step = 0.05e-3 }"}) {
    const TableConfig config =
        parse_table_config(std::string("[solver]\nwarm_start = true\n[axes]\nlateral_displacement_m = ") + axis +
                               "\nvertical_load_N = 78.5e3\n[output]\nstrip_samples = 16\n",
                           "shards.toml");
    GeneratorInfo info;
    info.threads = 2;
    const Table single = generate_table(config, info);
    const TableSweep sweep(config, info);
    Table parts = sweep.empty_table();
    const std::vector<std::vector<std::size_t>> units = sweep_units(sweep.n_dy(), sweep.mirrored());
    for (std::size_t shard = 1; shard <= 3; ++shard) sweep.solve_rows(shard_rows(units, shard, 3), parts, nullptr);
    sweep.finish(parts);
    EXPECT_TRUE(parts.status == single.status) << axis;
    EXPECT_TRUE(parts.roll_rad == single.roll_rad) << axis;
    EXPECT_TRUE(parts.patch.normal_force_N == single.patch.normal_force_N) << axis;
    EXPECT_TRUE(parts.patch.max_pressure_Pa == single.patch.max_pressure_Pa) << axis;
    EXPECT_TRUE(parts.patch.strip_half_length_m == single.patch.strip_half_length_m) << axis;
  }
}

}  // namespace
