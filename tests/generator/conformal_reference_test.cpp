// SPDX-License-Identifier: Apache-2.0
// Flange root and flank, conformal surface (the default; --surface conformal): ctab's wheel-rail solve (Manchester
// S1002/UIC60, inclination 0, right wheel, single-wheel mode, 78.5 kN, 0.2 mm strips) with CONTACT's reference point
// and with the default (the deepest point, its strips centred on CONTACT's reference point) against CONTACT's
// conformal results (D = 4) at dy = 5.5, 6.5 and 7.5 mm (../shared/reference/contact/wheelrail/flange, issue 8),
// both loadings. Targets: area 3 %, max pressure 5 %, centre of pressure 0.3 mm, force direction 0.3 deg, lateral
// force 2 % of the vertical load, p0 profile 5 % RMS; every case meets them with both (docs/validation.md "Flange and flank").
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

// CONTACT's reference rule on the conformal surface.
WheelRailOptions contacts_rule() {
  WheelRailOptions options;
  options.reference = ReferenceRule::InterpenetrationCentre;
  options.surface = ContactSurface::Conformal;
  return options;
}

class ConformalReference : public ctab::test::ManchesterSuite<Case> {
 protected:
  static Deviation measure(const Case& c, const WheelRailOptions& options) {
    const Reference ref = read_reference("conformal", c);
    const bool vertical = std::string(c.loading) == "vertical_load";
    const WheelContact contact =
        solve_wheel_contact(*side_, c.dy_mm * 1e-3, 0.0, effective_modulus(kSteel, kSteel),
                            vertical ? LoadKind::VerticalForce : LoadKind::NormalForce, kLoad_N, options);
    EXPECT_TRUE(is_success(contact.status)) << contact.detail;  // the flank may be under-resolved (7-8 strips)
    return deviation(contact, ref, reference_path(std::string("strips/conformal_") + c.loading + "_" + c.tag + ".csv"));
  }
};

}  // namespace

TEST_P(ConformalReference, MatchesContact) {
  CTAB_REQUIRE_SHARED();
  const Case c = GetParam();
  const Deviation e = measure(c, contacts_rule());
  ASSERT_GT(e.patches, 0);
  report("conformal", c, e);
  expect_within_limits(e, c.guard, c.dy_mm > 7.0);
  if (std::string(c.loading) == "vertical_load") {
    EXPECT_LT(std::abs(e.vertical_balance), 1e-9);
  }
}

// The default: the deepest point (the reported contact point), its strips centred on CONTACT's reference point (the
// interpenetration centre followed through the gap passes). From the deepest point's own grid the flank's p0 profile
// was 9.8 % RMS off CONTACT's rows (vertical load, dy 7.5 mm: the reference points 0.079 mm apart laterally, 0.22 mm
// along the 69 deg surface). Measured:
//   VL 5.5: area -0.99 %, pmax -0.19 %, cop -0.037 mm, direction +0.015 deg, lateral 0.03 %, p0 rms 1.0 %
//   VL 6.5: area +1.18 %, pmax -0.75 %, cop -0.042 mm, direction -0.157 deg, lateral 0.36 %, p0 rms 1.2 %
//   VL 7.5: area -3.28 % (ellipse of CONTACT's rows -0.18 %), pmax -0.15 %, cop -0.010 mm, direction -0.024 deg,
//           lateral 0.35 %, p0 rms 2.1 %
//   NF 5.5: area -0.80 %, pmax -0.31 %, cop -0.039 mm, direction +0.004 deg, lateral 0.01 %, p0 rms 1.1 %
//   NF 6.5: area +0.33 %, pmax -0.67 %, cop -0.041 mm, direction -0.149 deg, lateral 0.26 %, p0 rms 1.2 %
//   NF 7.5: area -5.05 % (ellipse -0.35 %), pmax -0.22 %, cop -0.010 mm, direction -0.013 deg, lateral 0.03 %,
//           p0 rms 4.1 %
// (within 0.1 % and 0.005 mm of CONTACT's rule above: the same grid, the same conformal surface).
TEST_P(ConformalReference, DefaultMatchesContact) {
  CTAB_REQUIRE_SHARED();
  const Case c = GetParam();
  const WheelRailOptions defaults;
  ASSERT_EQ(defaults.surface, ContactSurface::Conformal);
  ASSERT_EQ(defaults.reference, ReferenceRule::DeepestContactsAngle);
  const Deviation e = measure(c, defaults);
  ASSERT_GT(e.patches, 0);
  report("conformal, deepest point,", c, e);
  expect_within_limits(e, c.guard, c.dy_mm > 7.0);
  if (std::string(c.loading) == "vertical_load") {
    EXPECT_LT(std::abs(e.vertical_balance), 1e-9);
  }
}

// Every case meets issue 8's targets (the flank's area against the ellipse of CONTACT's rows, flange_reference.hpp).
// Measured with CONTACT's normal (the rail and wheel inclinations at the surface point's own y, midway), s = 0 at the
// surface point above the reference rail point and the strips centred on it (CONTACT's rows):
//   VL 5.5: area -0.95 %, pmax -0.18 %, cop -0.035 mm, direction +0.016 deg, lateral 0.03 %, p0 rms 1.0 % (2 patches;
//           CONTACT combines tread and root into one)
//   VL 6.5: area +1.19 %, pmax -0.75 %, cop -0.042 mm, direction -0.157 deg, lateral 0.36 %, p0 rms 1.2 %
//   VL 7.5: area -3.28 % (ellipse of CONTACT's rows -0.18 %), pmax -0.15 %, cop -0.010 mm, direction -0.024 deg,
//           lateral 0.35 %, p0 rms 2.1 %
//   NF 5.5: area -0.82 %, pmax -0.35 %, cop -0.041 mm, direction +0.004 deg, lateral 0.01 %, p0 rms 1.1 %
//   NF 6.5: area +0.34 %, pmax -0.67 %, cop -0.041 mm, direction -0.149 deg, lateral 0.26 %, p0 rms 1.2 %
//   NF 7.5: area -5.05 % (ellipse -0.35 %), pmax -0.22 %, cop -0.010 mm, direction -0.013 deg, lateral 0.03 %,
//           p0 rms 4.1 %
// Before: the normal from the inclinations where it meets each profile (flank direction -0.589 / -0.291 deg, lateral
// 8.6 % of FZ), the marching started where the rail point's normal meets the surface (the strips 0.13 mm along the
// surface from CONTACT's rows on the flank) with edges at the reference point: p0 rms 4.5 / 31.6 % on the flank and
// 7.0 % at NF 6.5, held by guards.
INSTANTIATE_TEST_SUITE_P(
    Conformal, ConformalReference,
    ::testing::Values(Case{"vertical_load", 5.5, "p5p50", {}}, Case{"vertical_load", 6.5, "p6p50", {}},
                      Case{"vertical_load", 7.5, "p7p50", {}}, Case{"normal_force", 5.5, "p5p50", {}},
                      Case{"normal_force", 6.5, "p6p50", {}}, Case{"normal_force", 7.5, "p7p50", {}}),
    case_name);
