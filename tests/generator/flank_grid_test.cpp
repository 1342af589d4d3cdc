// Why ctab's flank area differs from CONTACT's (issue 8, dy 7.5 mm, planar; README "Flange and flank"). The flank
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
  static WheelContact solve(NormalMethod method, double width_m, LoadKind kind) {
    WheelRailOptions options;
    options.reference_at_interpenetration_centre = true;  // CONTACT's rule, as flange_reference_test
    options.method = method;
    options.mim1d.strip_width_m = width_m;
    options.bem2d_alignment = Bem2dAlignment::CentresAtOrigin;  // CONTACT's wheel-rail grid
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
// MIM-1D against that ellipse (-1.6 / -1.5 %) is checked in flange_reference_test with issue 8's area target.
TEST_P(FlankGrid, ElementCountLiesAboveTheEllipse) {
  CTAB_REQUIRE_SHARED();
  const char* loading = GetParam();  // reference file prefix, as in flange_reference_test
  const Reference ref = read_reference("planar", Case{loading, 7.5, "p7p50", {}});
  const double ellipse =
      contact_ellipse_area_mm2(reference_path(std::string("strips/planar_") + loading + "_p7p50.csv"));
  std::cout << loading << ": CONTACT " << ref.area_mm2 << " mm^2 counted, " << ellipse << " as an ellipse\n";
  EXPECT_GT(ref.area_mm2 / ellipse - 1.0, 0.04);
}

// Measured (bem2d on CONTACT's wheel-rail grid): CONTACT 72.76 mm^2 at 223.1 kN normal force (72.14 at ctab's
// 220.3 kN); bem2d 0.2 mm 71.40 (-1.0 %), 0.1 mm 69.83, extrapolated 68.26; MIM-1D 0.2 mm 68.23 (-0.04 %).
TEST_F(FlankGrid, BoundaryElementsOnContactsGridReproduceItsArea) {
  CTAB_REQUIRE_SHARED();
  const Reference ref = read_reference("planar", Case{"vertical_load", 7.5, "p7p50", {}});
  // CONTACT's normal force FN = FZ / cos(angle) (planar: every row along the reference normal).
  const double contact_force_N = ref.vertical_N / std::cos(ref.direction_deg / kDegPerRad);
  const WheelContact coarse_solution = solve(NormalMethod::Bem2d, 0.2e-3, LoadKind::VerticalForce);
  const double coarse = area_mm2(coarse_solution);
  const double fine = area_mm2(solve(NormalMethod::Bem2d, 0.1e-3, LoadKind::VerticalForce));
  const double mim1d = area_mm2(solve(NormalMethod::Mim1d, 0.2e-3, LoadKind::VerticalForce));
  const double continuum = 2.0 * fine - coarse;  // the element-count error is first order in the element size
  // Area grows as F^(2/3) (Hertz): CONTACT's area at ctab's normal force (the two differ through the angle).
  const double contact_at_our_force =
      ref.area_mm2 * std::cbrt(std::pow(coarse_solution.normal_force_N / contact_force_N, 2.0));
  std::cout << "CONTACT " << ref.area_mm2 << " mm^2 at " << contact_force_N << " N (" << contact_at_our_force
            << " at ctab's " << coarse_solution.normal_force_N << " N); bem2d 0.2 mm " << coarse << ", 0.1 mm " << fine
            << ", extrapolated " << continuum << "; MIM-1D 0.2 mm " << mim1d << " mm^2\n";
  EXPECT_LT(std::abs(coarse / contact_at_our_force - 1.0), 0.015);  // bem2d on CONTACT's grid reproduces CONTACT
  EXPECT_GT(coarse / fine - 1.0, 0.015);                            // and falls when refined
  EXPECT_LT(std::abs(mim1d / continuum - 1.0), 0.01);               // towards MIM-1D
}

INSTANTIATE_TEST_SUITE_P(Planar, FlankGrid, ::testing::Values("vertical_load", "normal_force"),
                         [](const ::testing::TestParamInfo<const char*>& p) { return std::string(p.param); });
