// SPDX-License-Identifier: Apache-2.0
// The conformal contact surface (WheelRailOptions::surface) without ../shared: on the built-in S1002/60E1 tread,
// nearly flat, conformal and planar agree; the force components add up to the prescribed vertical load; the strips'
// normals follow the curved surface on the flange root.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "ctab/contact/material.hpp"
#include "ctab/profiles/builtin_profiles.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"

using namespace ctab::gen;

namespace {

constexpr double kLoad_N = 78.5e3;

class ConformalSurface : public ::testing::Test {
 protected:
  static WheelContact solve(double dy_m, ContactSurface surface, LoadKind load = LoadKind::VerticalForce,
                            double value = kLoad_N) {
    WheelRailOptions options;
    options.surface = surface;
    return solve_wheel_contact(side_, dy_m, 0.0, effective_modulus(kSteel, kSteel), load, value, options);
  }
  static inline const ProfileTable wheel_{*s1002_curve(), kProfileTableStep_m, "S1002"};
  static inline const ProfileTable rail_{*uic60_inclined_curve(1.0 / 40.0), kProfileTableStep_m, "60E1"};
  static inline const SideGeometry side_{wheel_, rail_, TrackSetup{}};
};

}  // namespace

// On the tread the surface is nearly a plane: CONTACT's two approaches agree within 0.15 % there (its README);
// ctab's within 0.5 % in area and pressure (measured: see the output).
TEST_F(ConformalSurface, AgreesWithPlanarOnTheTread) {
  for (double dy_mm : {-4.0, 0.0, 3.0}) {
    const WheelContact planar = solve(dy_mm * 1e-3, ContactSurface::Planar);
    const WheelContact conformal = solve(dy_mm * 1e-3, ContactSurface::Conformal);
    ASSERT_EQ(planar.status, SolveStatus::Converged) << planar.detail;
    ASSERT_EQ(conformal.status, SolveStatus::Converged) << conformal.detail;
    ASSERT_EQ(planar.patches.size(), conformal.patches.size()) << "dy " << dy_mm << " mm";
    for (std::size_t k = 0; k < planar.patches.size(); ++k) {
      const ContactPatch &p = planar.patches[k], &c = conformal.patches[k];
      std::cout << "dy " << dy_mm << " mm patch " << k << ": area " << 100 * (c.area_m2 / p.area_m2 - 1) << " %, pmax "
                << 100 * (c.max_pressure_Pa / p.max_pressure_Pa - 1) << " %, cop "
                << 1e3 * (c.y_cop_rail_m - p.y_cop_rail_m) << " mm\n";
      EXPECT_NEAR(c.area_m2 / p.area_m2, 1.0, 0.005) << "dy " << dy_mm << " mm";
      EXPECT_NEAR(c.max_pressure_Pa / p.max_pressure_Pa, 1.0, 0.005) << "dy " << dy_mm << " mm";
      EXPECT_NEAR(c.y_cop_rail_m, p.y_cop_rail_m, 0.05e-3) << "dy " << dy_mm << " mm";
    }
  }
}

// Each strip pushes along its own normal; the vertical components add up to the prescribed load (issue 8: 1e-9).
TEST_F(ConformalSurface, VerticalLoadBalances) {
  for (double dy_mm : {-6.0, 0.0, 5.5, 6.5, 7.5}) {
    const WheelContact c = solve(dy_mm * 1e-3, ContactSurface::Conformal);
    ASSERT_EQ(c.status, SolveStatus::Converged) << "dy " << dy_mm << " mm: " << c.detail;
    double vertical = 0.0;
    for (const ContactPatch& p : c.patches) vertical += p.force_vertical_N;
    EXPECT_NEAR(vertical / kLoad_N, 1.0, 1e-9) << "dy " << dy_mm << " mm";
    EXPECT_NEAR(c.vertical_force_N / kLoad_N, 1.0, 1e-9) << "dy " << dy_mm << " mm";
  }
}

// On the flange root the normals turn across the patch: the resultant's direction lies between the reference angle
// and the steeper flange side, and it is the direction of the reported components.
TEST_F(ConformalSurface, ResultantFollowsTheStripNormals) {
  const WheelContact c = solve(6.5e-3, ContactSurface::Conformal);
  ASSERT_EQ(c.status, SolveStatus::Converged) << c.detail;
  ASSERT_FALSE(c.patches.empty());
  const ContactPatch& p = c.patches.front();
  EXPECT_NEAR(p.contact_angle_rad, std::atan2(-p.force_lateral_N, p.force_vertical_N), 1e-12);
  EXPECT_LT(p.contact_angle_rad, 0.0);
  // The strips span a range of normals (the planar patch has one): s is the arc length along a curved surface.
  ASSERT_GE(p.strips.size(), 10u);
  EXPECT_GT(p.s_max_m - p.s_min_m, 1e-3);
}

// A prescribed vertical approach: the gap is sampled with the wheel lowered by it, so the normal approach of the
// patch is the vertical approach times the cosine of the reference angle.
TEST_F(ConformalSurface, ApproachLoading) {
  const WheelContact c = solve(0.0, ContactSurface::Conformal, LoadKind::Approach, 0.1e-3);
  ASSERT_EQ(c.status, SolveStatus::Converged) << c.detail;
  ASSERT_FALSE(c.patches.empty());
  const ContactPatch& p = c.patches.front();
  EXPECT_NEAR(p.approach_m, 0.1e-3 * std::cos(p.plane_angle_rad), 1e-12);
  EXPECT_GT(p.normal_force_N, 0.0);
}

// Where the strips sit. With CONTACT's reference rule they take CONTACT's wheel-rail grid: a strip centred on the
// reference point (s = k 2b), and on the conformal surface s = 0 is the surface point above the reference rail point
// (CONTACT's row at s = 0 has the reference point's y_rail). The conformal surface at the deepest point (the default)
// centres its strips on CONTACT's reference point as well (s_origin_y_rail_m, the rail y of s = 0); the planar
// surface at the deepest point puts strip edges there (s = (k + 1/2) 2b).
TEST(StripPlacement, FollowsContactsGridWithItsReferenceRule) {
  const ProfileTable wheel{*s1002_curve(), kProfileTableStep_m, "S1002"};
  const ProfileTable rail{*uic60_inclined_curve(1.0 / 40.0), kProfileTableStep_m, "60E1"};
  const SideGeometry side{wheel, rail, TrackSetup{}};
  for (const ContactSurface surface : {ContactSurface::Planar, ContactSurface::Conformal})
    for (const bool contacts_rule : {false, true})
      for (const double dy_mm : {0.0, 6.5, 7.5}) {
        WheelRailOptions options;
        options.surface = surface;
        if (contacts_rule) options.reference = ReferenceRule::InterpenetrationCentre;
        const WheelContact c = solve_wheel_contact(side, dy_mm * 1e-3, 0.0, effective_modulus(kSteel, kSteel),
                                                   LoadKind::VerticalForce, kLoad_N, options);
        ASSERT_TRUE(is_success(c.status)) << c.detail;
        const ContactPatch& main = c.patches.front();
        const bool conformal = surface == ContactSurface::Conformal;
        const double width = options.mim1d.strip_width_m, offset = contacts_rule || conformal ? 0.0 : 0.5;
        const std::string where = std::string(surface_name(surface)) + (contacts_rule ? " centre" : " deepest") +
                                  " dy " + std::to_string(dy_mm) + " mm";
        bool at_reference = false;
        for (const PatchStrip& s : main.strips) {
          const double k = s.s_m / width - offset;
          EXPECT_NEAR(k, std::round(k), 1e-6) << where << ": strip at s " << s.s_m;
          if (conformal && std::abs(s.s_m) < 1e-9) {
            at_reference = true;
            EXPECT_NEAR(s.y_rail_m, main.s_origin_y_rail_m, 1e-9) << where;
            if (contacts_rule) {
              EXPECT_NEAR(s.y_rail_m, main.y_rail_m, 1e-9) << where;
            }
          }
        }
        if (conformal) {
          EXPECT_TRUE(at_reference) << where;
        } else {
          EXPECT_TRUE(std::isnan(main.s_origin_y_rail_m)) << where;  // the plane's tangent point (table_generator)
        }
      }
}
