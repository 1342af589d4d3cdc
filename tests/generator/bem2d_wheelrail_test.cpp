// SPDX-License-Identifier: Apache-2.0
// bem2d against CONTACT on the wheel-rail cases (issue 10: the 2-D reference validated within 1 % against CONTACT's
// wheel-rail results): Manchester S1002/UIC60, inclination 0, right wheel, single wheel, 78.5 kN normal force, 0.2 mm
// elements on CONTACT's wheel-rail grid (element centres at multiples of the size from the reference point, which
// is CONTACT's: the centre of the interpenetration region). Tread (../reference/contact/wheelrail/summary.csv) and
// flange (flange/planar_normal_force.csv) cases; all patches summed (at 5 and 5.5 mm tread and flange root are two
// runs of elements in one plane, which CONTACT reports as one patch). MatchesContactOnItsGrid solves in ctab's own
// contact planes; MatchesContactInItsPlane in CONTACT's (its reference point and angle from the same rows): the
// geometry is then identical and only the normal solvers differ, so that test holds the 1 % without exception.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "ctab/contact/material.hpp"
#include "ctab/validation/reference_csv.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "manchester_side.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

constexpr double kLoad_N = 78.5e3;
constexpr double kTarget = 0.01;  // issue 10: within 1 %

struct Case {
  const char* file;  // under reference/contact/wheelrail/
  double dy_mm;
};

// CONTACT's row(s) of a case: the summed area, the largest pressure and, for a single row, its reference point.
struct ContactRow {
  double area_mm2 = 0.0, pmax_MPa = 0.0, ycp_rail_mm = 0.0, angle_rad = 0.0;
  int rows = 0;
};

ContactRow contact_row(const Case& c) {
  const auto summary =
      ctab::gen::read_csv(ctab::test::shared_path(std::string("reference/contact/wheelrail/") + c.file));
  const auto dys = summary.numbers("dy_mm"), areas = summary.numbers("area_mm2"), pmaxes = summary.numbers("pmax_MPa");
  const auto ycps = summary.numbers("ycp_rail_mm"), angles = summary.numbers("contact_angle_rad");
  ContactRow row;
  for (std::size_t i = 0; i < dys.size(); ++i)
    if (dys[i] == c.dy_mm) {
      row.area_mm2 += areas[i];
      row.pmax_MPa = std::max(row.pmax_MPa, pmaxes[i]);
      row.ycp_rail_mm = ycps[i];
      row.angle_rad = angles[i];
      ++row.rows;
    }
  return row;
}

// Whose contact plane bem2d solves in.
enum class Plane { Ctab, Contact };

class Bem2dWheelRail : public ctab::test::ManchesterSuite<Case> {
 protected:
  // bem2d on CONTACT's wheel-rail grid, in ctab's plane (CONTACT's reference rule) or in CONTACT's imposed plane.
  static void expect_matches(const Case& c, Plane plane) {
    const ContactRow ref = contact_row(c);
    ASSERT_GT(ref.rows, 0) << c.file << " has no row at dy " << c.dy_mm;
    WheelRailOptions options;
    options.surface = ContactSurface::Planar;  // CONTACT's planar results
    options.method = NormalMethod::Bem2d;
    options.bem2d_alignment = GridAlignment::CentresAtOrigin;
    if (plane == Plane::Ctab) {
      options.reference = ReferenceRule::InterpenetrationCentre;
    } else {
      ASSERT_EQ(ref.rows, 1) << c.file << ": one patch at dy " << c.dy_mm;
      options.reference = ReferenceRule::Prescribed;
      options.prescribed_reference = PrescribedReference{ref.ycp_rail_mm * 1e-3, ref.angle_rad};
    }
    const WheelContact contact = solve_wheel_contact(*side_, c.dy_mm * 1e-3, 0.0, effective_modulus(kSteel, kSteel),
                                                     LoadKind::NormalForce, kLoad_N, options);
    ASSERT_TRUE(is_success(contact.status)) << status_name(contact.status) << " " << contact.detail;
    double area = 0.0, pmax = 0.0;
    for (const ContactPatch& p : contact.patches) area += p.area_m2, pmax = std::max(pmax, p.max_pressure_Pa);
    const double area_error = area * 1e6 / ref.area_mm2 - 1.0, pmax_error = pmax * 1e-6 / ref.pmax_MPa - 1.0;
    std::cout << "dy " << c.dy_mm << " mm in " << (plane == Plane::Ctab ? "ctab's" : "CONTACT's") << " plane ("
              << contact.patches.size() << " patch): area " << 100 * area_error << " %, max pressure "
              << 100 * pmax_error << " %\n";
    EXPECT_LT(std::abs(area_error), kTarget);
    EXPECT_LT(std::abs(pmax_error), kTarget);
  }
};

}  // namespace

TEST_P(Bem2dWheelRail, MatchesContactOnItsGrid) {
  CTAB_REQUIRE_SHARED();
  expect_matches(GetParam(), Plane::Ctab);
}

// The same cases in CONTACT's own contact plane (its reference point ycp_rail_mm and angle contact_angle_rad from the
// same rows, WheelRailOptions::prescribed_reference): identical geometry, so only the normal solver differs.
TEST_P(Bem2dWheelRail, MatchesContactInItsPlane) {
  CTAB_REQUIRE_SHARED();
  expect_matches(GetParam(), Plane::Contact);
}

// Measured (ctab's own contact planes / CONTACT's plane), area and max pressure: -1 mm 0.00 / +0.00 %, 0.00 / -0.00 %;
// 0: 0.00 / +0.07 %, +0.05 / +0.10 %; 1 mm: 0.00 / +0.04 %, -0.10 / +0.02 %; 2 mm: 0.00 / +0.00 %, +0.21 / +0.01 %;
// 5 mm: -0.08 / +0.37 %, -0.15 / +0.30 %; 5.5 mm: +0.25 / +0.32 %, +0.50 / +0.32 %; 6.5 mm: 0.00 / +0.01 %, -0.21 /
// +0.03 %; 7.5 mm: 0.00 / +0.01 %, -0.64 / +0.47 %. ctab's own plane is CONTACT's rule (the weighted centre of the
// interpenetration region and the weighted mean of the rail's inclination over it, one plane for tread and flange
// root at 5 and 5.5 mm). Before that rule took the weighted mean (the inclination at the centre, and the deepest
// point for a region with two minima) 5 mm was +1.61 % in max pressure; before the wheel's rise along x was seen along
// the normal (wheelrail_contact.cpp, fill_strip_geometry) the flange root was off by -1.90 % in area on ctab's plane
// and -1.80 % in CONTACT's, the flank by -0.86 / -1.07 %. With the element edges at the origin instead (bem2d's
// default) the tread cases were off by up to 0.23 % and the flank by -4.1 %.
INSTANTIATE_TEST_SUITE_P(Cases, Bem2dWheelRail,
                         ::testing::Values(Case{"summary.csv", -1.0}, Case{"summary.csv", 0.0},
                                           Case{"summary.csv", 1.0}, Case{"summary.csv", 2.0}, Case{"summary.csv", 5.0},
                                           Case{"flange/planar_normal_force.csv", 5.5},
                                           Case{"flange/planar_normal_force.csv", 6.5},
                                           Case{"flange/planar_normal_force.csv", 7.5}),
                         [](const ::testing::TestParamInfo<Case>& p) {
                           std::string name = "dy_" + std::to_string(static_cast<int>(std::lround(p.param.dy_mm * 10)));
                           std::replace(name.begin(), name.end(), '-', 'm');
                           return name;
                         });
