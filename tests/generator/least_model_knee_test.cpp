// SPDX-License-Identifier: Apache-2.0
// The least model at the root-to-flank knee (least_model.hpp step 4, docs/design/knee-indicator.md): `--method auto`
// (tolerance 0.02) per patch against converged bem2d over a dense sweep of the knee, and against CONTACT's conformal
// flange cases (../shared/reference/contact/wheelrail/flange). Targets per patch carrying >= 5 % of the normal force:
// area 3 %, max pressure 5 %, force direction 0.3 deg, lateral force 2 % of F_z, contact point 0.3 mm.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "ctab/contact/material.hpp"
#include "ctab/contact/resolution.hpp"
#include "ctab/validation/knee_sweep.hpp"
#include "ctab/wheelrail/least_model.hpp"
#include "flange_reference.hpp"
#include "manchester_side.hpp"

using namespace ctab::gen;

namespace {

constexpr double kTolerance = 0.02;

// S1002 on UIC60 (1/40), single right wheel, 78.5 kN vertical load, dy 6.3 ... 7.5 mm every 0.05 mm: auto against
// bem2d on rows of 0.05 mm (elements 0.4 mm long: within 0.1 % of squares there), half the escalation's row width.
TEST(LeastModelKnee, HoldsTheTargetsPerPatchAgainstBem2dAcrossTheKnee) {
  KneeSweepOptions options;
  options.vertical_loads_N = {78.5e3};
  for (int i = 0; i <= 24; ++i) options.shifts_m.push_back(6.3e-3 + 0.05e-3 * i);
  options.candidate_tolerance = kTolerance;
  options.reference_width_m = 0.05e-3;
  options.reference_length_m = 0.4e-3;
  const std::vector<KneeRow> rows = run_knee_sweep(options);
  const KneeTargets targets;
  int bounded = 0, escalated = 0;
  for (const KneeRow& r : rows) {
    ASSERT_TRUE(is_success(r.reference_status)) << "dy " << r.dy_m;
    ASSERT_TRUE(is_success(r.candidate_status)) << "dy " << r.dy_m;
    escalated += r.choice.method == ContactMethod::Bem2d ? 1 : 0;
    if (r.load_share < kResolvedForceShare || r.candidate_status != SolveStatus::Converged) continue;
    ++bounded;
    EXPECT_FALSE(r.errors.exceeds(targets))
        << "dy " << r.dy_m * 1e3 << " mm patch " << r.patch << ": area " << r.errors.area_rel << ", pmax "
        << r.errors.max_pressure_rel << ", direction " << r.errors.direction_rad << " rad, lateral "
        << r.errors.lateral_of_fz << " of F_z, point " << r.errors.contact_point_m << " m (chose "
        << method_name(r.choice.method) << " at " << r.choice.strip_width_m << " m)";
  }
  std::printf("[ knee ] %zu patches, %d bounded, %d escalated to bem2d\n", rows.size(), bounded, escalated);
  EXPECT_GE(bounded, 20);
}

class LeastModelFlange : public ctab::test::ManchesterSuite<ctab::test::flange::Case> {};

// auto against CONTACT's conformal results at its flange cases (both loadings; the flank's area against the
// ellipse of CONTACT's rows, as conformal_reference_test).
TEST_P(LeastModelFlange, MatchesContact) {
  CTAB_REQUIRE_SHARED();
  using namespace ctab::test::flange;
  const Case c = GetParam();
  const Reference ref = read_reference("conformal", c);
  const bool vertical = std::string(c.loading) == "vertical_load";
  WheelContactWorkspace workspace;
  AutoChoice choice;
  const WheelContact contact = solve_wheel_contact_auto(
      *side_, c.dy_mm * 1e-3, 0.0, effective_modulus(kSteel, kSteel),
      vertical ? LoadKind::VerticalForce : LoadKind::NormalForce, kLoad_N, WheelRailOptions{}, kTolerance, workspace,
      &choice);
  ASSERT_TRUE(is_success(contact.status)) << contact.detail;
  const Deviation e =
      deviation(contact, ref, reference_path(std::string("strips/conformal_") + c.loading + "_" + c.tag + ".csv"));
  report(std::string("auto (") + method_name(choice.method) + ")", c, e);
  expect_within_limits(e, c.guard, c.dy_mm > 7.0);
}

INSTANTIATE_TEST_SUITE_P(
    Conformal, LeastModelFlange,
    ::testing::Values(ctab::test::flange::Case{"vertical_load", 5.5, "p5p50", {}},
                      ctab::test::flange::Case{"vertical_load", 6.5, "p6p50", {}},
                      ctab::test::flange::Case{"vertical_load", 7.5, "p7p50", {}},
                      ctab::test::flange::Case{"normal_force", 5.5, "p5p50", {}},
                      ctab::test::flange::Case{"normal_force", 6.5, "p6p50", {}},
                      ctab::test::flange::Case{"normal_force", 7.5, "p7p50", {}}),
    ctab::test::flange::case_name);

}  // namespace
