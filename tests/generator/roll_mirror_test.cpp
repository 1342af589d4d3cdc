// SPDX-License-Identifier: Apache-2.0
// Wheelset roll mirror symmetry: on mirror-image sides roll(-dy) = -roll(dy) to the bit, which lets a mirrored
// sweep solve the roll only for dy >= 0 (table_generator.cpp, solve_rolls) and keep the table bit-identical.
#include <gtest/gtest.h>

#include <vector>

#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/wheelrail/axis_range.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"

namespace {

using namespace ctab::gen;

TEST(RollMirror, RigidWheelsetPoseIsExactlyAntisymmetric) {
  const ProfileTable wheel = load_profile("S1002", ProfileRole::Wheel, {});
  const ProfileTable rail = load_profile("UIC60", ProfileRole::Rail, {});
  const SideGeometry side(wheel, rail, TrackSetup{});
  const UniformAxis axis = make_uniform_axis(0.0, 12e-3, 0.3e-3);  // tread, flange root and flange contacts
  ASSERT_TRUE(axis.ok());
  for (const double dy : axis.values) {
    const WheelsetPose plus = rigid_wheelset_pose(side, side, dy);
    const WheelsetPose minus = rigid_wheelset_pose(side, side, -dy);
    ASSERT_TRUE(plus.converged) << "dy " << dy;
    EXPECT_EQ(minus.converged, plus.converged);
    EXPECT_EQ(minus.roll_rad, -plus.roll_rad) << "dy " << dy;  // bit for bit, not within a tolerance
  }
}

// A mirrored wheelset table (rolls of dy < 0 mirrored from dy > 0) holds at every row the roll a direct solve gives.
TEST(RollMirror, MirroredSweepRollsEqualDirectSolves) {
  const TableConfig config = parse_table_config(
      "[solver]\nmode = \"wheelset\"\n[axes]\n"
      "lateral_displacement_m = { start = -10e-3, stop = 10e-3, step = 2.5e-3 }\nvertical_load_N = [60e3, 90e3]\n"
      "[output]\nstrip_samples = 8\n",
      "roll_mirror.toml");
  GeneratorInfo info;
  info.threads = 2;
  const ctab::tables::Table table = generate_table(config, info, {});
  const SweepSetup setup = make_sweep_setup(config);
  const std::size_t n_dy = table.n_dy(), n_second = table.n_second();
  for (std::size_t i = 0; i < n_dy; ++i) {
    const double dy = table.lateral_displacement_m[i];
    const CaseRoll direct = solve_case_roll(setup, dy);
    ASSERT_TRUE(direct.converged);
    for (std::size_t j = 0; j < n_second; ++j) {
      EXPECT_EQ(table.roll_rad[i * n_second + j], direct.roll_rad) << "dy " << dy;
      EXPECT_EQ(table.roll_rad[(n_dy - 1 - i) * n_second + j], -direct.roll_rad) << "dy " << dy;
    }
  }
}

}  // namespace
