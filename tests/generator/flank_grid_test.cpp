// SPDX-License-Identifier: Apache-2.0
// Why ctab's flank area differs from CONTACT's (issue 8, dy 7.5 mm, planar; docs/validation.md "Flange and flank"). The flank
// patch is only 8-11 rows of 0.2 mm wide and CONTACT's area counts whole elements (ncon dx ds), which on so narrow a
// patch lies 5-9 % above the continuum. Two independent checks:
// - CONTACT's own rows describe a Hertzian ellipse (straight wheel flank on the rail's 13 mm arc): the row loads
//   q_i = (pi/2) p0_i a_i fall as 1 - u^2 across the patch and so do a_ell,i^2. Parabolas fitted to them give the
//   semi-axes and pi a b, the area of the pressure CONTACT computed, free of the element count.
// - ctab's boundary-element reference (bem2d, the same kind of element grid) at CONTACT's 0.2 mm reproduces
//   CONTACT's area; refined to 0.1 mm it falls towards MIM-1D, whose area does not move with the strip width.
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

class FlankGrid : public ctab::test::ManchesterSuite<const char*> {
 protected:
  static WheelContact solve(NormalMethod method, double width_m, LoadKind kind, double length_m = 0.0) {
    WheelRailOptions options;
    options.surface = ContactSurface::Planar;  // CONTACT's planar results
    options.bem2d_element_length_m = length_m;
    options.reference = ReferenceRule::InterpenetrationCentre;  // CONTACT's rule, as flange_reference_test
    options.method = method;
    options.mim1d.strip_width_m = width_m;
    options.bem2d_alignment = GridAlignment::CentresAtOrigin;  // CONTACT's wheel-rail grid
    const WheelContact c =
        solve_wheel_contact(*side_, 7.5e-3, 0.0, effective_modulus(kSteel, kSteel), kind, kLoad_N, options);
    EXPECT_TRUE(is_success(c.status)) << status_name(c.status) << " " << c.detail;
    EXPECT_EQ(c.patches.size(), 1u);
    return c;
  }
  static double area_mm2(const WheelContact& c) {
    double area = 0.0;
    for (const auto& p : c.patches) area += p.area_m2;
    return area * 1e6;
  }
};

}  // namespace

// Measured: vertical load 72.76 mm^2 counted, 69.35 as an ellipse (+4.9 %); normal force 37.28 and 34.46 (+8.2 %).
// MIM-1D against that ellipse (-1.1 / -1.0 %) is checked in flange_reference_test with issue 8's area target.
TEST_P(FlankGrid, ElementCountLiesAboveTheEllipse) {
  CTAB_REQUIRE_SHARED();
  const char* loading = GetParam();  // reference file prefix, as in flange_reference_test
  const Reference ref = read_reference("planar", Case{loading, 7.5, "p7p50", {}});
  const double ellipse =
      contact_ellipse_area_mm2(reference_path(std::string("strips/planar_") + loading + "_p7p50.csv"));
  std::cout << loading << ": CONTACT " << ref.area_mm2 << " mm^2 counted, " << ellipse << " as an ellipse\n";
  EXPECT_GT(ref.area_mm2 / ellipse - 1.0, 0.04);
}

// Measured (bem2d on CONTACT's wheel-rail grid): CONTACT 72.76 mm^2 at 223.1 kN normal force (ctab's 223.1 kN); bem2d
// 0.2 mm 72.84 (+0.1 %), 0.1 mm 70.66; with 0.1 mm long elements and rows of 0.05 / 0.025 mm 70.34 / 70.17 (first
// order from 0.1 mm down: steps of -0.325 and -0.163; the element length hardly matters: 72.88 / 72.84 at 0.4 / 0.2
// mm long, 0.2 mm rows), extrapolated from 0.1 / 0.05 mm 70.01, from 0.05 / 0.025 mm 70.01; MIM-1D
// 69.30 at 0.2 mm (-1.02 %), 69.88 / 69.81 / 69.78 at 0.1 / 0.05 / 0.025 mm (-0.29 % at 0.05 mm). The rows' error
// is first order only from 0.1 mm down (8 rows at 0.2 mm): the earlier estimate 2 x A(0.1) - A(0.2) = 68.48 lay 2.2 %
// under the continuum, and the bar "MIM-1D at 0.2 mm within 1 % of it" compared with that.
TEST_F(FlankGrid, BoundaryElementsOnContactsGridReproduceItsArea) {
  CTAB_REQUIRE_SHARED();
  const Reference ref = read_reference("planar", Case{"vertical_load", 7.5, "p7p50", {}});
  // CONTACT's normal force FN = FZ / cos(angle) (planar: every row along the reference normal).
  const double contact_force_N = ref.vertical_N / std::cos(ref.direction_deg / kDegPerRad);
  const WheelContact coarse_solution = solve(NormalMethod::Bem2d, 0.2e-3, LoadKind::VerticalForce);
  const double coarse = area_mm2(coarse_solution);
  const double fine = area_mm2(solve(NormalMethod::Bem2d, 0.1e-3, LoadKind::VerticalForce));
  // Rows refined below the element length (the patch is 1.6 mm wide and 29 mm long).
  const double rows_05 = area_mm2(solve(NormalMethod::Bem2d, 0.05e-3, LoadKind::VerticalForce, 0.1e-3));
  const double continuum = 2.0 * rows_05 - fine;  // the element-count error is first order in the row width from 0.1 mm
  const double mim1d = area_mm2(solve(NormalMethod::Mim1d, 0.2e-3, LoadKind::VerticalForce));
  const double mim1d_fine = area_mm2(solve(NormalMethod::Mim1d, 0.05e-3, LoadKind::VerticalForce));
  // Area grows as F^(2/3) (Hertz): CONTACT's area at ctab's normal force (the two differ through the angle).
  const double contact_at_our_force =
      ref.area_mm2 * std::cbrt(std::pow(coarse_solution.normal_force_N / contact_force_N, 2.0));
  std::cout << "CONTACT " << ref.area_mm2 << " mm^2 at " << contact_force_N << " N (" << contact_at_our_force
            << " at ctab's " << coarse_solution.normal_force_N << " N); bem2d 0.2 mm " << coarse << ", 0.1 mm " << fine
            << ", rows 0.05 mm " << rows_05 << ", extrapolated " << continuum << "; MIM-1D 0.2 mm " << mim1d
            << ", 0.05 mm " << mim1d_fine << " mm^2\n";
  EXPECT_LT(std::abs(coarse / contact_at_our_force - 1.0), 0.015);  // bem2d on CONTACT's grid reproduces CONTACT
  EXPECT_GT(coarse / fine - 1.0, 0.015);                            // and falls when refined
  EXPECT_GT(fine, rows_05);                                         // monotonically
  EXPECT_LT(std::abs(mim1d_fine / continuum - 1.0), 0.005);         // to MIM-1D's converged area
  EXPECT_LT(std::abs(mim1d / continuum - 1.0), 0.015);              // and MIM-1D at 0.2 mm is near it
}

INSTANTIATE_TEST_SUITE_P(Planar, FlankGrid, ::testing::Values("vertical_load", "normal_force"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string(p.param); });
