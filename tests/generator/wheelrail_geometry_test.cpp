// SPDX-License-Identifier: Apache-2.0
// Rigid wheel-rail geometry on the Manchester set-up against independent references: CONTACT's first-touch
// height at dy = 0 and the rigid zero-yaw contact table of facts/profiles.md 4.5 (a separate Python computation).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ctab/wheelrail/contact_geometry_sweep.hpp"
#include "ctab/io/profile_io.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

struct Manchester {
  ProfileTable wheel, rail;
  SideGeometry side;
  Manchester()
      : wheel(load_profile(ctab::test::shared_path("profiles/MBench_S1002_v3.prw"), ProfileRole::Wheel, options())),
        rail(load_profile(ctab::test::shared_path("profiles/MBench_UIC60_v3.prr"), ProfileRole::Rail, options())),
        side(wheel, rail, TrackSetup{}) {}
  static ProfileReadOptions options() {
    ProfileReadOptions o;
    o.inclination = 0.0;  // the file is already inclined
    return o;
  }
};

}  // namespace

TEST(WheelRailGeometry, PlacementAndFirstTouch) {
  CTAB_REQUIRE_SHARED();
  const Manchester m;
  EXPECT_NEAR(m.side.rail_origin_y_m(), 0.7605326, 0.02e-3);  // CONTACT: YCP(TR) - YCP(R) = 760.5326 mm
  EXPECT_NEAR(m.side.wheel_origin_y_m(), 0.750, 1e-12);
  std::vector<GapMinimum> minima;
  double z = 0.0;
  m.side.gap_minima(0.0, 0.0, minima, z);
  EXPECT_NEAR((z + 0.460) * 1e3, 0.1821, 0.0005);  // CONTACT's rigid first touch at dy = 0: 0.1821 mm
  EXPECT_NEAR(minima[0].rail_y_m * 1e3, -7.28, 0.05);
  EXPECT_NEAR(minima[0].wheel_s_m * 1e3, 3.25, 0.05);
}

TEST(WheelRailGeometry, WheelsetRollAndContactPositions) {
  CTAB_REQUIRE_SHARED();
  const Manchester m;
  struct Row {
    double dy_mm, roll_mrad, right_y_rail_mm, right_s_mm, right_angle_deg;
  };
  // Rigid, zero-yaw reference (facts/profiles.md 4.5 table, "rigid" columns).
  for (const Row r : {Row{1.0, -0.054, -18.86, -9.36, -4.1}, Row{3.0, -0.184, -20.55, -13.10, -5.3},
                      Row{5.0, -0.370, -33.98, -28.61, -17.2}, Row{6.5, -4.252, -42.13, -40.12, -67.4},
                      Row{8.0, -8.663, -40.74, -42.34, -54.7}, Row{10.0, -11.350, -39.46, -44.36, -45.9}}) {
    const RigidContactRow row = rigid_contact(m.side, m.side, r.dy_mm * 1e-3, ContactMode::Wheelset);
    EXPECT_NEAR(row.roll_rad * 1e3, r.roll_mrad, 0.005) << "dy " << r.dy_mm;
    EXPECT_NEAR(row.right.rail_y_m * 1e3, r.right_y_rail_mm, 0.05) << "dy " << r.dy_mm;
    EXPECT_NEAR(row.right.wheel_s_m * 1e3, r.right_s_mm, 0.05) << "dy " << r.dy_mm;
    EXPECT_NEAR(row.right.contact_angle_rad * 180 / M_PI, r.right_angle_deg, 0.1) << "dy " << r.dy_mm;
  }
}

TEST(WheelRailGeometry, JumpsAndEquivalentConicity) {
  CTAB_REQUIRE_SHARED();
  const Manchester m;
  std::vector<RigidContactRow> rows;
  for (int i = 0; i <= 100; ++i) rows.push_back(rigid_contact(m.side, m.side, i * 0.1e-3, ContactMode::Wheelset));
  const auto jumps = find_contact_jumps(rows, 1e-3);
  std::vector<double> right_jumps;
  for (const auto& j : jumps)
    if (j.right_side) right_jumps.push_back(j.dy_after_m);
  // Reference: right-wheel jumps between 0.2-0.25, 4.8-4.9 and 6.2-6.3 mm.
  ASSERT_EQ(right_jumps.size(), 3u);
  EXPECT_NEAR(right_jumps[0], 0.3e-3, 1e-9);
  EXPECT_NEAR(right_jumps[1], 4.9e-3, 1e-9);
  EXPECT_NEAR(right_jumps[2], 6.3e-3, 1e-9);
  std::vector<double> ys, dr;
  for (int i = 0; i <= 400; ++i) {
    ys.push_back(i * 0.01e-3);
    dr.push_back(rigid_contact(m.side, m.side, ys.back(), ContactMode::Wheelset).rolling_radius_difference_m);
  }
  EXPECT_NEAR(equivalent_conicity(ys, dr, 3e-3), 0.184, 0.002);  // reference 0.184 (MBench rail)
  // A linear dr = 2 * 0.2 * y gives exactly 0.2.
  std::vector<double> linear;
  for (const double y : ys) linear.push_back(0.4 * y);
  EXPECT_NEAR(equivalent_conicity(ys, linear, 3e-3), 0.2, 1e-6);
}
