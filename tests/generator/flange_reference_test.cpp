// SPDX-License-Identifier: Apache-2.0
// Flange root and flank, planar surface: ctab's wheel-rail solve (Manchester S1002/UIC60, inclination 0, right
// wheel, single-wheel mode, 78.5 kN, 0.2 mm strips) against CONTACT's planar results at dy = 5.5, 6.5 and 7.5 mm
// (../shared/reference/contact/wheelrail/flange, issue 8), both loadings (vertical load and normal force
// prescribed). Targets: area 3 %, max pressure 5 %, centre of pressure 0.3 mm, force direction 0.3 deg, lateral
// force 2 % of the vertical load, p0 profile 5 % RMS; every case meets them (docs/validation.md "Flange and flank").
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "ctab/contact/material.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "flange_reference.hpp"
#include "manchester_side.hpp"

using namespace ctab::gen;
using namespace ctab::test::flange;

namespace {

// The planar surface (the conformal one is the default: conformal_reference_test).
WheelRailOptions planar() {
  WheelRailOptions options;
  options.surface = ContactSurface::Planar;
  return options;
}

// CONTACT's reference point: the centre of the interpenetration region (WheelRailOptions).
WheelRailOptions centred_options() {
  WheelRailOptions options = planar();
  options.reference = ReferenceRule::InterpenetrationCentre;
  return options;
}

// The deepest point's plane inclined at CONTACT's reference angle (WheelRailOptions::reference_angle).
WheelRailOptions deepest_at_contacts_angle() {
  WheelRailOptions options = planar();
  options.reference = ReferenceRule::DeepestContactsAngle;
  return options;
}

class FlangeReference : public ctab::test::ManchesterSuite<Case> {
 protected:
  static WheelContact solve(const Case& c, const WheelRailOptions& options) {
    const bool vertical = std::string(c.loading) == "vertical_load";
    return solve_wheel_contact(*side_, c.dy_mm * 1e-3, 0.0, effective_modulus(kSteel, kSteel),
                               vertical ? LoadKind::VerticalForce : LoadKind::NormalForce, kLoad_N, options);
  }
  static Deviation measure(const Case& c, const WheelRailOptions& options = centred_options()) {
    const Reference ref = read_reference("planar", c);
    const WheelContact contact = solve(c, options);
    // the flank patch (dy 7.5 mm, about 1.5 mm wide) spans 7-8 strips of 0.2 mm: under-resolved (usable) below 8
    const bool flank = c.dy_mm > 7.0;
    EXPECT_TRUE(contact.status == SolveStatus::Converged || (flank && contact.status == SolveStatus::UnderResolved))
        << status_name(contact.status) << " " << contact.detail;
    const ctab::test::ContactRowLine line =
        ctab::test::contact_row_line(reference_path(std::string("planar_") + c.loading + ".csv"), c.dy_mm,
                                     manchester_->rail);
    return deviation(contact, ref, reference_path(std::string("strips/planar_") + c.loading + "_" + c.tag + ".csv"),
                     &line, &manchester_->rail);
  }
};

}  // namespace

TEST_P(FlangeReference, PlanarMatchesContact) {
  CTAB_REQUIRE_SHARED();
  const Case c = GetParam();
  const Deviation e = measure(c);
  ASSERT_GT(e.patches, 0);
  report("planar", c, e);
  expect_within_limits(e, c.guard, c.dy_mm > 7.0);
}

// The deepest point's plane at CONTACT's reference angle meets every target too: a plane's gap is the same through
// any of its points, so only the strip grid's origin differs from CONTACT's rule (measured, VL / NF: direction
// -0.011 / -0.013 deg at 5.5 mm, -0.002 / -0.002 at 6.5, -0.004 / 0.000 at 7.5; lateral within 0.02 % of FZ; p0 rms
// 1.1 / 1.8, 1.9 / 0.6, 3.7 / 3.4 %). With the rail's tangent at the deepest point (the default) the direction misses
// by -1.48 / -1.35, 2.84 / 2.61 and -0.60 / -0.30 deg and the lateral force by up to 8.6 % of FZ.
TEST_P(FlangeReference, DeepestPointAtContactsAngleMatchesContact) {
  CTAB_REQUIRE_SHARED();
  const Case c = GetParam();
  const Deviation e = measure(c, deepest_at_contacts_angle());
  ASSERT_GT(e.patches, 0);
  report("planar, deepest point at CONTACT's angle,", c, e);
  expect_within_limits(e, c.guard, c.dy_mm > 7.0);
}

// With CONTACT's reference angle the deepest point's plane has CONTACT's rule's inclination (the same weights over
// the same region) while it stays through the deepest point.
TEST_F(FlangeReference, ContactsAngleAtTheDeepestPointIsCentresAngle) {
  CTAB_REQUIRE_SHARED();
  for (const char* loading : {"vertical_load", "normal_force"}) {
    for (double dy : {5.5, 6.5, 7.0, 7.5}) {
      const Case c{loading, dy, "", {}};
      WheelRailOptions tangent_options = planar();
      tangent_options.reference = ReferenceRule::DeepestTangent;
      const WheelContact tangent = solve(c, tangent_options);
      const WheelContact deepest = solve(c, deepest_at_contacts_angle());
      const WheelContact centre = solve(c, centred_options());
      ASSERT_EQ(deepest.status, SolveStatus::Converged) << deepest.detail;
      ASSERT_FALSE(deepest.patches.empty());
      ASSERT_FALSE(tangent.patches.empty());
      ASSERT_EQ(deepest.patches.size(), centre.patches.size());
      const auto& d = deepest.patches.front();
      EXPECT_EQ(d.y_rail_m, tangent.patches.front().y_rail_m) << loading << " dy " << dy;  // the deepest point
      // measured within 0.0056 deg (the approaches differ by the grids' discretisation); the tangent 0.30-2.84 deg
      EXPECT_NEAR((d.plane_angle_rad - centre.patches.front().plane_angle_rad) * kDegPerRad, 0.0, 0.02)
          << loading << " dy " << dy;
    }
  }
}

// The reference point is the centre of the interpenetration region (wheelrail_contact.cpp, recentre_main_patch):
// on the straight flank it follows the patch. With the deepest rigid point it stayed at rail y = -42.354 mm and
// -69.99 deg for every dy from 6.7 to 7.6 mm (issue 8); CONTACT moves between -68.6 and -69.4 deg.
TEST_F(FlangeReference, FlankReferencePointFollowsTheShift) {
  CTAB_REQUIRE_SHARED();
  // Measured (vertical load): -56.1 deg at 6.7 mm, -64.1 at 6.8, then -67.5 ... -69.41 deg from 6.9 to 7.6 mm (the
  // inclination at the centre instead of the weighted mean: -60.6, -66.6, -67.4 ... -69.16 deg).
  double previous = 0.0, lowest = 0.0, highest = -M_PI;
  int moves = 0;
  for (int k = 0; k <= 9; ++k) {
    const double dy = (6.7 + 0.1 * k) * 1e-3;
    const WheelContact c = solve_wheel_contact(*side_, dy, 0.0, effective_modulus(kSteel, kSteel),
                                               LoadKind::VerticalForce, kLoad_N, centred_options());
    ASSERT_EQ(c.status, SolveStatus::Converged) << c.detail;
    ASSERT_EQ(c.patches.size(), 1u);
    const double angle = c.patches.front().plane_angle_rad * kDegPerRad;
    if (k > 0 && std::abs(angle - previous) > 1e-3) ++moves;
    lowest = std::min(lowest, angle);
    highest = std::max(highest, angle);
    previous = angle;
  }
  EXPECT_GE(moves, 8);  // of 9 steps (before: 0, every angle -69.99 deg)
  EXPECT_GT(highest - lowest, 1.0);
  EXPECT_GT(lowest, -69.6);  // CONTACT: -68.6 ... -69.4 deg
}

// The default keeps the deepest rigid point and inclines its plane at CONTACT's reference angle: on the flank the
// rail point stays where the rail's slope is -69.99 deg, the plane takes CONTACT's rule's angle (within 0.02 deg);
// with the tangent (the earlier default) the plane is the rail's -69.99 deg.
TEST_F(FlangeReference, DefaultKeepsTheDeepestPointAtContactsAngle) {
  CTAB_REQUIRE_SHARED();
  const auto solve = [&](const WheelRailOptions& options) {
    const WheelContact c = solve_wheel_contact(*side_, 7.5e-3, 0.0, effective_modulus(kSteel, kSteel),
                                               LoadKind::VerticalForce, kLoad_N, options);
    EXPECT_EQ(c.status, SolveStatus::Converged) << c.detail;
    EXPECT_EQ(c.patches.size(), 1u);
    return c.patches.front();
  };
  WheelRailOptions tangent = planar();
  tangent.reference = ReferenceRule::DeepestTangent;
  const ContactPatch by_default = solve(WheelRailOptions{}), at_tangent = solve(tangent),
                     at_centre = solve(centred_options());
  EXPECT_NEAR(at_tangent.plane_angle_rad * kDegPerRad, -69.99, 0.01);
  EXPECT_EQ(by_default.y_rail_m, at_tangent.y_rail_m);
  EXPECT_NEAR(by_default.plane_angle_rad * kDegPerRad, at_centre.plane_angle_rad * kDegPerRad, 0.02);
  EXPECT_GT(std::abs(by_default.plane_angle_rad - at_tangent.plane_angle_rad) * kDegPerRad, 0.3);
}

// The reference point itself against CONTACT's at the flange root and flank (a single minimum there): measured
// -0.003, -0.013, -0.005, -0.010 mm (with weights pen^(3/2) instead of pen^(5/2): -0.12, +0.008, -0.12, 0.000 mm).
TEST_F(FlangeReference, ReferencePointMatchesContact) {
  CTAB_REQUIRE_SHARED();
  for (const char* loading : {"vertical_load", "normal_force"}) {
    for (double dy : {6.5, 7.5}) {
      const Deviation e = measure(Case{loading, dy, dy < 7 ? "p6p50" : "p7p50", {}});
      EXPECT_LT(std::abs(e.rail_point_mm), 0.02) << loading << " dy " << dy << " mm";
    }
  }
}

// The plane's inclination against CONTACT's reference angle (DELT_CP): the weighted mean of the rail's inclination
// over the interpenetration region (interpenetration_centre). Measured: VL 5.5 / 6.5 / 7.5 mm -0.012 / -0.001 /
// -0.004 deg, NF -0.010 / -0.001 / -0.000 deg; the inclination at the centre was 0.3-0.4 deg shallower at the root
// and flank, and at 5.5 mm (tread and flange root in one region) 2.6 deg.
TEST_F(FlangeReference, PlaneAngleMatchesContactsReferenceAngle) {
  CTAB_REQUIRE_SHARED();
  for (const char* loading : {"vertical_load", "normal_force"}) {
    for (const char* tag : {"p5p50", "p6p50", "p7p50"}) {
      const double dy = tag[1] == '5' ? 5.5 : tag[1] == '6' ? 6.5 : 7.5;
      const Deviation e = measure(Case{loading, dy, tag, {}});
      EXPECT_LT(std::abs(e.plane_angle_deg), 0.05) << loading << " dy " << dy << " mm";
    }
  }
}

// Every case meets issue 8's targets (the flank's area against the ellipse of CONTACT's rows, flange_reference.hpp).
// Measured with the gap sampled at the solved vertical approach (wheelrail_contact.cpp, solve_main_patch; before: h
// at first contact), the wheel's rise along x seen along the plane normal (fill_strip_geometry; before: cos(delta) /
// 2r at every strip), CONTACT's reference angle (the weighted mean of the rail's inclination over the
// interpenetration region, one plane for a region that spans tread and flange root) and CONTACT's grid (a strip
// centred on the reference point, strip_alignment):
//   VL 5.5: area -0.14 % (was -7.7), pmax -0.02 %, cop -0.001 mm (was -0.38), direction -0.006 deg (was -1.48),
//           lateral 0.01 % (was 2.84), p0 rms 0.8 %
//   VL 6.5: area +0.14 % (was +17.7), pmax -0.14 % (was -11.5), cop -0.031 mm (was -0.58), direction -0.001 deg
//           (was 0.38), p0 rms 0.6 %
//   VL 7.5: area -3.7 % (CONTACT's element count; ellipse of its rows +1.0 %, flank_grid_test), direction -0.000 deg,
//           lateral 0.04 % (was -3.86), p0 rms 2.4 %
//   NF 5.5: area -0.82 % (was -9.5), cop -0.016 mm, direction -0.012 deg (was -1.35), lateral 0.02 % (was 2.34),
//           p0 rms 1.1 %
//   NF 6.5: area -0.16 % (was +16.0), pmax +0.01 %, cop -0.032 mm, direction -0.002 deg (was 0.33), p0 rms 0.5 %
//   NF 7.5: area -5.8 % (ellipse +1.9 %), direction 0.000 deg, p0 rms 3.4 %
// The p0 profile places ctab's strips on CONTACT's row line (manchester_side.hpp, ContactRowLine); with the rail
// points below the strips it was 7.7 / 10.7 / 6.4 / 17.1 % at VL 6.5 / VL 7.5 / NF 6.5 / NF 7.5. With the strip
// edges at the reference point (half a strip off CONTACT's rows) and rows beyond the edge strips' centres read as 0,
// NF 6.5 and NF 7.5 were 5.26 and 17.2 % (guards 0.06 and 0.18 until the grid and the reading changed).
INSTANTIATE_TEST_SUITE_P(
    Planar, FlangeReference,
    ::testing::Values(Case{"vertical_load", 5.5, "p5p50", {}}, Case{"vertical_load", 6.5, "p6p50", {}},
                      Case{"vertical_load", 7.5, "p7p50", {}}, Case{"normal_force", 5.5, "p5p50", {}},
                      Case{"normal_force", 6.5, "p6p50", {}}, Case{"normal_force", 7.5, "p7p50", {}}),
    case_name);
