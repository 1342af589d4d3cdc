// SPDX-License-Identifier: Apache-2.0
// The under-resolved status (ctab/contact/resolution.hpp) and the least model (ctab/wheelrail/least_model.hpp,
// `--method auto --tolerance T`): the status fires below 8 strips across the smallest loaded patch of a
// discretised rung; the least model meets T against MIM-1D at 0.05 mm on a small S1002/UIC60 sweep with fewer
// influence-matrix entries than MIM-1D at 0.2 mm (a count, not a timing), and its choice is recorded in the table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/normal_contact.hpp"
#include "ctab/contact/resolution.hpp"
#include "ctab/validation/accuracy_metrics.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/wheelrail/least_model.hpp"

using namespace ctab::gen;

namespace {

const double kEStar = effective_modulus(kSteel, kSteel);
constexpr double kForce_N = 78.5e3;
constexpr double kTolerance = 0.02;

// An ellipsoid gap h = A x^2 + B y^2 (R = 0.46 m and 0.3 m), |y| <= 10 mm every 0.01 mm.
GapProfile ellipsoid() {
  const double A = 1.0 / (2 * 0.46), B = 1.0 / (2 * 0.3);
  return sample_gap(
      -10e-3, 10e-3, 0.01e-3, [B](double y) { return B * y * y; }, [A](double) { return A; }, [B](double) { return B; },
      "ellipsoid");
}

SolveStatus solve_status(ContactMethod method, double force_N, double width_m) {
  MethodOptions options;
  options.method = method;
  options.E_star_Pa = kEStar;
  options.strip_width_m = width_m;
  return solve_normal_contact(ellipsoid(), options, Loading::normal_force(force_N)).status;
}

TableConfig sweep_config(const std::string& solver) {
  return parse_table_config("[solver]\nmode = \"wheel\"\n" + solver +
                                "\n[axes]\nlateral_displacement_m = { start = -3e-3, stop = 7.5e-3, step = 1.5e-3 "
                                "}\nnormal_load_N = 78.5e3\n",
                            "least_model_test.toml");
}

}  // namespace

TEST(UnderResolved, FewerThanEightStripsAcrossTheSmallestCountedPatch) {
  const std::vector<PatchExtent> wide{{1.6e-3, 3e-3, 1000.0}}, narrow{{1.4e-3, 3e-3, 1000.0}};
  EXPECT_EQ(resolution_status(SolveStatus::Converged, ContactMethod::Mim1d, wide, 0.2e-3), SolveStatus::Converged);
  EXPECT_EQ(resolution_status(SolveStatus::Converged, ContactMethod::Mim1d, narrow, 0.2e-3),
            SolveStatus::UnderResolved);
  EXPECT_EQ(resolution_status(SolveStatus::Converged, ContactMethod::Hertz, narrow, 0.2e-3), SolveStatus::Converged)
      << "one ellipse is not discretised";
  for (const ContactMethod m : {ContactMethod::Kp, ContactMethod::Analyn, ContactMethod::Bem2d})
    EXPECT_EQ(resolution_status(SolveStatus::Converged, m, narrow, 0.2e-3), SolveStatus::UnderResolved);
  // bem2d's square elements also count along x; strips do not
  const std::vector<PatchExtent> short_patch{{4e-3, 1e-3, 1000.0}};
  EXPECT_EQ(resolution_status(SolveStatus::Converged, ContactMethod::Mim1d, short_patch, 0.2e-3),
            SolveStatus::Converged);
  EXPECT_EQ(resolution_status(SolveStatus::Converged, ContactMethod::Bem2d, short_patch, 0.2e-3),
            SolveStatus::UnderResolved);
  // a patch below 5 % of the force does not count; failures and no-contact keep their status
  const std::vector<PatchExtent> small_second{{4e-3, 3e-3, 1000.0}, {0.4e-3, 1e-3, 40.0}};
  EXPECT_EQ(resolution_status(SolveStatus::Converged, ContactMethod::Mim1d, small_second, 0.2e-3),
            SolveStatus::Converged);
  EXPECT_EQ(resolution_status(SolveStatus::MaxIterations, ContactMethod::Mim1d, narrow, 0.2e-3),
            SolveStatus::MaxIterations);
  EXPECT_EQ(resolution_status(SolveStatus::NoContact, ContactMethod::Mim1d, {}, 0.2e-3), SolveStatus::NoContact);
  EXPECT_TRUE(is_success(SolveStatus::UnderResolved)) << "a quality warning, not a failure";
  EXPECT_STREQ(status_name(SolveStatus::UnderResolved), "under-resolved");
}

TEST(UnderResolved, LadderReportsItOnASmallHertzPatch) {
  // 10 N on R 0.46/0.3 m: a patch about 0.5 mm wide, 2-3 strips of 0.2 mm; 78.5 kN: about 13 mm, 60 strips.
  for (const ContactMethod m : {ContactMethod::Kp, ContactMethod::Analyn, ContactMethod::Mim1d}) {
    EXPECT_EQ(solve_status(m, 10.0, 0.2e-3), SolveStatus::UnderResolved) << method_name(m);
    EXPECT_EQ(solve_status(m, 10.0, 0.02e-3), SolveStatus::Converged) << method_name(m) << " at 0.02 mm";
    EXPECT_EQ(solve_status(m, kForce_N, 0.2e-3), SolveStatus::Converged) << method_name(m);
  }
  EXPECT_EQ(solve_status(ContactMethod::Hertz, 10.0, 0.2e-3), SolveStatus::Converged);
}

TEST(LeastModel, EstimatorPieces) {
  // start: the coarsest width with >= 8 strips across W, never the 0.8 mm that only checks 0.4 mm
  EXPECT_EQ(auto_start_rung(20e-3), 1u);    // 0.4 mm: 50 strips
  EXPECT_EQ(auto_start_rung(3.1e-3), 2u);   // 0.2 mm: 15 strips (0.4 mm: 7.75)
  EXPECT_EQ(auto_start_rung(1.6e-3), 2u);   // 0.2 mm: 8 strips
  EXPECT_EQ(auto_start_rung(1.0e-3), 3u);   // 0.1 mm: 10 strips
  EXPECT_EQ(auto_start_rung(0.01e-3), 4u);  // the finest
  WheelContact fine;
  fine.patches.resize(1);
  fine.patches[0].area_m2 = 100e-6, fine.patches[0].max_pressure_Pa = 1.0e9;
  StripWidthTotals coarse;
  coarse.area_m2 = 101e-6, coarse.max_pressure_Pa = 0.97e9, coarse.solved = true;
  EXPECT_NEAR(richardson_error(fine, coarse), 0.03, 1e-12);  // the larger of 1 % (area) and 3 % (pressure)
  EXPECT_TRUE(std::isinf(richardson_error(fine, StripWidthTotals{})));
  coarse.solved = false;
  EXPECT_TRUE(std::isinf(richardson_error(fine, coarse))) << "a failed check is no estimate";
}

// Every case of a small sweep (tread, two-point, flange root, flank) within T of MIM-1D at 0.05 mm, with fewer
// influence-matrix entries built (n^2 per MIM-1D iteration, every solve and check of the least model counted) than
// MIM-1D at 0.2 mm: the "faster than always using MIM-1D at 0.2 mm" as a count (0.87x on these 8 cases, 3
// of them two-point or flange; the 141-case sweep's wall time is in the README).
TEST(LeastModel, MeetsTheToleranceWithFewerStripsThanMim1dAtTwoTenths) {
  const SweepSetup auto_setup = make_sweep_setup(sweep_config("method = \"auto\"\ntolerance = 0.02"));
  const SweepSetup plain = make_sweep_setup(sweep_config("strip_width_m = 0.2e-3"));
  const SweepSetup reference = make_sweep_setup(sweep_config("strip_width_m = 0.05e-3"));
  ASSERT_DOUBLE_EQ(auto_setup.auto_tolerance, kTolerance);
  double auto_entries = 0.0, plain_entries = 0.0;
  int coarser = 0, escalated = 0;
  for (const double dy : {-3e-3, -1e-3, 0.5e-3, 2e-3, 3.5e-3, 5.5e-3, 6.5e-3, 7.5e-3}) {
    const CaseWheel a = solve_table_case(auto_setup, dy, kForce_N, {true, false}).wheels[0];
    const CaseWheel p = solve_table_case(plain, dy, kForce_N, {true, false}).wheels[0];
    const CaseWheel r = solve_table_case(reference, dy, kForce_N, {true, false}).wheels[0];
    const std::string at = "dy " + std::to_string(dy * 1e3) + " mm, chosen " + std::to_string(a.choice.strip_width_m);
    ASSERT_TRUE(is_success(a.contact.status)) << at;
    ASSERT_EQ(r.contact.status, SolveStatus::Converged) << at;
    EXPECT_GE(a.choice.solves, 1) << at;
    auto_entries += a.choice.matrix_entries;
    plain_entries += p.contact.matrix_entries;
    if (a.choice.method == ContactMethod::Bem2d) {  // escalated (step 4): held against bem2d in least_model_knee_test
      EXPECT_TRUE(strip_model_at_risk(r.contact)) << at;
      ++escalated;
      continue;
    }
    const ContactSummary got = summarise(a.contact), want = summarise(r.contact);
    EXPECT_LE(std::abs(got.area_m2 / want.area_m2 - 1.0), kTolerance) << at;
    EXPECT_LE(std::abs(got.max_pressure_Pa / want.max_pressure_Pa - 1.0), kTolerance) << at;
    EXPECT_EQ(a.choice.method, ContactMethod::Mim1d);
    EXPECT_TRUE(std::find(kAutoStripWidths_m.begin(), kAutoStripWidths_m.end(), a.choice.strip_width_m) !=
                kAutoStripWidths_m.end())
        << at;
    EXPECT_TRUE(std::isfinite(a.choice.estimated_error) || a.choice.strip_width_m == kAutoStripWidths_m.back())
        << at << ": every answer above the finest width was checked";
    coarser += a.choice.strip_width_m > 0.2e-3 ? 1 : 0;
  }
  std::printf("[ least model ] influence-matrix entries built: auto %.0f, mim1d 0.2 mm %.0f (%.2fx)\n", auto_entries,
              plain_entries, auto_entries / plain_entries);
  EXPECT_LT(auto_entries, plain_entries) << "influence-matrix entries built, summed over every solve";
  EXPECT_GE(coarser, 4) << "the tread cases take 0.4 mm";
  EXPECT_LE(escalated, 2) << "only the knee escalates";
}

// The choice per case lands in the table (/wheels/method, /wheels/strip_width_m) and the method attribute says auto.
TEST(LeastModel, ChoiceIsRecordedInTheTable) {
  const TableConfig config = sweep_config("method = \"auto\"\ntolerance = 0.02");
  EXPECT_TRUE(config.least_model);
  EXPECT_DOUBLE_EQ(config.tolerance, kTolerance);
  const ctab::tables::Table table = generate_table(config, GeneratorInfo{});
  EXPECT_EQ(table.text_attributes.at("method"), "auto");
  EXPECT_DOUBLE_EQ(table.number_attributes.at("tolerance"), kTolerance);
  ASSERT_EQ(table.method.size(), table.status.size());
  bool coarse = false, fine = false, escalated = false;
  for (std::size_t i = 0; i < table.n_dy(); ++i) {
    const std::size_t w = table.wheel_index(i, 0, 0);
    if (table.method[w] == static_cast<std::int8_t>(ContactMethod::Bem2d)) {  // escalated (step 4)
      EXPECT_LE(table.strip_width_m[w], kEscalationRowWidth_m);
      escalated = true;
      continue;
    }
    EXPECT_EQ(table.method[w], static_cast<std::int8_t>(ContactMethod::Mim1d));
    EXPECT_TRUE(std::find(kAutoStripWidths_m.begin(), kAutoStripWidths_m.end(), table.strip_width_m[w]) !=
                kAutoStripWidths_m.end());
    coarse |= table.strip_width_m[w] > 0.2e-3;
    fine |= table.strip_width_m[w] <= 0.2e-3;
  }
  EXPECT_TRUE(coarse && fine) << "tread coarse, flange fine";
  EXPECT_TRUE(escalated) << "the knee escalates to bem2d";
  // a plain table records its one method and width
  const ctab::tables::Table plain = generate_table(sweep_config("method = \"kp\""), GeneratorInfo{});
  EXPECT_EQ(plain.method[0], static_cast<std::int8_t>(ContactMethod::Kp));
  EXPECT_DOUBLE_EQ(plain.strip_width_m[0], 0.2e-3);
}

TEST(LeastModel, ConfigRejectsABadTolerance) {
  for (const char* bad : {"0", "-0.1", "0.9", "\"2%\""}) {
    EXPECT_THROW((void)sweep_config(std::string("method = \"auto\"\ntolerance = ") + bad), InputError) << bad;
  }
}
