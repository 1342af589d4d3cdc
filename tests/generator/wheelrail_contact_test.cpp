// SPDX-License-Identifier: Apache-2.0
// MIM-1D on S1002/UIC60 (Manchester profiles, right wheel, single-wheel mode, N = 78.5 kN, steel, strips 0.2 mm)
// against CONTACT (../shared/reference/contact/wheelrail): paper section 3.2, Figures 8-9.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "ctab/contact/material.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/validation/reference_csv.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "manchester_side.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

struct Case {
  double dy_mm;
  const char* tag;
};

class WheelRailContact : public ctab::test::ManchesterSuite<Case> {};

// CONTACT's strip file of a case.
std::string strip_file(const std::string& tag) {
  return ctab::test::shared_path("reference/contact/wheelrail/strips_" + tag + ".csv");
}

// CONTACT's summary row of a case (reference/contact/wheelrail/summary.csv).
struct SummaryRow {
  double cop_mm = 0.0, angle_rad = 0.0, area_mm2 = 0.0, pmax_MPa = 0.0;
  bool found = false;
};

SummaryRow summary_row(double dy_mm) {
  const auto summary = ctab::gen::read_csv(ctab::test::shared_path("reference/contact/wheelrail/summary.csv"));
  const auto dys = summary.numbers("dy_mm");
  const auto row = static_cast<std::size_t>(std::find(dys.begin(), dys.end(), dy_mm) - dys.begin());
  if (row >= dys.size()) return {};
  return {summary.numbers("y_cop_rail_mm")[row], summary.numbers("contact_angle_rad")[row],
          summary.numbers("area_mm2")[row], summary.numbers("pmax_MPa")[row], true};
}

}  // namespace

TEST_P(WheelRailContact, MatchesContact) {
  CTAB_REQUIRE_SHARED();
  const Case c = GetParam();
  const SummaryRow ref = summary_row(c.dy_mm);
  ASSERT_TRUE(ref.found);
  const double ref_cop = ref.cop_mm, ref_angle = ref.angle_rad, ref_area = ref.area_mm2, ref_pmax = ref.pmax_MPa;

  const WheelContact contact = solve_wheel_contact(*side_, c.dy_mm * 1e-3, 0.0, effective_modulus(kSteel, kSteel),
                                                   LoadKind::NormalForce, 78.5e3, WheelRailOptions{});
  ASSERT_EQ(contact.status, SolveStatus::Converged);
  ASSERT_FALSE(contact.patches.empty());
  // Sums over the patches (at dy = 5 mm tread and flange root touch at once; CONTACT reports them merged).
  double force = 0, area = 0, pmax = 0, cop = 0, angle = 0;
  for (const auto& p : contact.patches) {
    force += p.normal_force_N;
    area += p.area_m2;
    pmax = std::max(pmax, p.max_pressure_Pa);
    cop += p.normal_force_N * p.y_cop_rail_m;
    angle += p.normal_force_N * p.contact_angle_rad;
  }
  cop /= force;
  angle /= force;
  EXPECT_NEAR(force, 78.5e3, 1e-6 * 78.5e3);
  EXPECT_NEAR(cop * 1e3, ref_cop, 0.3);
  EXPECT_NEAR(area * 1e6 / ref_area - 1.0, 0.0, 0.02);
  EXPECT_NEAR(pmax * 1e-6 / ref_pmax - 1.0, 0.0, 0.05);
  // ctab's strips placed on CONTACT's row line (manchester_side.hpp, ContactRowLine)
  const ctab::test::ContactRowLine line =
      ctab::test::contact_row_line(ctab::test::shared_path("reference/contact/wheelrail/summary.csv"), c.dy_mm,
                                   manchester_->rail);
  const double p0_rms = ctab::test::p0_profile_rms(contact, strip_file(c.tag), &line, &manchester_->rail);
  EXPECT_LT(p0_rms, 0.05);
  if (contact.patches.size() == 1) {
    EXPECT_NEAR(angle * 180 / M_PI, ref_angle * 180 / M_PI, 0.2);
  } else {
    // Two patches in two planes (tread 7.3 deg, flange root 16.7 deg): their resultant points at 10.45 deg, while
    // CONTACT's single merged plane gives 9.61 deg. Not comparable within 0.2 deg; recorded, see README.
    EXPECT_NEAR(angle * 180 / M_PI, ref_angle * 180 / M_PI, 1.0);
  }
  std::ostringstream report;
  report << std::fixed << std::setprecision(3) << "dy " << c.dy_mm << " mm: cop " << cop * 1e3 - ref_cop
         << " mm, angle " << (angle - ref_angle) * 180 / M_PI << " deg, area " << 100 * (area * 1e6 / ref_area - 1)
         << " %, pmax " << 100 * (pmax * 1e-6 / ref_pmax - 1) << " %, p0 rms " << 100 * p0_rms << " %";
  RecordProperty("deviation", report.str());
  std::cout << report.str() << '\n';
}

// With CONTACT's reference rule (--reference-point interpenetration-centre: the weighted centre of the
// interpenetration region, the plane at the weighted mean of the rail's inclination over it) the plane is CONTACT's
// at every dy, also at 5 mm where tread and flange root form one region: ctab solves both runs in that one plane, as
// CONTACT does, and the force points along its normal.
void expect_contacts_plane(const Case& c, const SideGeometry& side, const WheelRailOptions& options,
                           double ref_angle_deg, double ref_area_mm2, double ref_pmax_MPa) {
  const WheelContact contact = solve_wheel_contact(side, c.dy_mm * 1e-3, 0.0, effective_modulus(kSteel, kSteel),
                                                   LoadKind::NormalForce, 78.5e3, options);
  ASSERT_EQ(contact.status, SolveStatus::Converged);
  ASSERT_FALSE(contact.patches.empty());
  double area = 0, pmax = 0, lateral = 0, vertical = 0;
  for (const auto& p : contact.patches) {
    area += p.area_m2;
    pmax = std::max(pmax, p.max_pressure_Pa);
    lateral += p.force_lateral_N;
    vertical += p.force_vertical_N;
  }
  const double plane_deg = contact.patches.front().plane_angle_rad * 180 / M_PI;
  const double direction_deg = -std::atan2(lateral, vertical) * 180 / M_PI;
  std::cout << "dy " << c.dy_mm << " mm (" << contact.patches.size() << " patch): plane " << plane_deg - ref_angle_deg
            << " deg, force direction " << direction_deg - ref_angle_deg << " deg, area "
            << 100 * (area * 1e6 / ref_area_mm2 - 1) << " %, pmax " << 100 * (pmax * 1e-6 / ref_pmax_MPa - 1) << " %\n";
  EXPECT_NEAR(plane_deg, ref_angle_deg, 0.2);
  EXPECT_NEAR(direction_deg, ref_angle_deg, 0.2);
  EXPECT_NEAR(area * 1e6 / ref_area_mm2 - 1.0, 0.0, 0.02);
  EXPECT_NEAR(pmax * 1e-6 / ref_pmax_MPa - 1.0, 0.0, 0.05);
}

// The deepest point's plane at CONTACT's reference angle (--reference-angle interpenetration-mean) is CONTACT's plane
// too: a plane's gap is the same through any of its points.
TEST_P(WheelRailContact, PlaneMatchesContactsWithItsReferenceRuleOrAngle) {
  CTAB_REQUIRE_SHARED();
  const Case c = GetParam();
  const SummaryRow ref = summary_row(c.dy_mm);
  ASSERT_TRUE(ref.found);
  WheelRailOptions centre, deepest_at_contacts_angle;
  centre.surface = deepest_at_contacts_angle.surface = ContactSurface::Planar;  // a plane's identities
  centre.reference = ReferenceRule::InterpenetrationCentre;
  deepest_at_contacts_angle.reference = ReferenceRule::DeepestContactsAngle;
  for (const WheelRailOptions& options : {centre, deepest_at_contacts_angle}) {
    SCOPED_TRACE(options.at_interpenetration_centre() ? "CONTACT's rule" : "deepest point, CONTACT's angle");
    expect_contacts_plane(c, *side_, options, ref.angle_rad * 180 / M_PI, ref.area_mm2, ref.pmax_MPa);
  }
}

INSTANTIATE_TEST_SUITE_P(ContactCases, WheelRailContact,
                         ::testing::Values(Case{-1.0, "m1p00"}, Case{0.0, "p0p00"}, Case{1.0, "p1p00"},
                                           Case{2.0, "p2p00"}, Case{5.0, "p5p00"}),
                         [](const auto& param_info) { return std::string("dy_") + param_info.param.tag; });
