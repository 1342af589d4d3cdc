// SPDX-License-Identifier: Apache-2.0
// The wheelset roll search (issue 11, "Faster on one machine"): FirstContactTracker's windowed scans return the
// full scan's first-contact height bit for bit, and a roll searched from a neighbour's roll (the sweep's runs) is
// the roll searched cold, bit for bit, within one lattice step of the root. Swept in 0.01 mm steps across the
// contact jumps of S1002 on UIC60 1:40 (dy about 0.2, 5.18 and 6.63 mm), built-in and Manchester profiles.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ctab/io/profile_io.hpp"
#include "ctab/wheelrail/first_contact_tracker.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"
#include "manchester_side.hpp"
#include "test_support.hpp"

namespace {

using namespace ctab::gen;

// Shifts in 0.01 mm steps across each jump (+-0.1 mm) [m].
std::vector<double> shifts_across_jumps() {
  std::vector<double> dy;
  for (const double jump_mm : {0.2, 5.18, 6.63})
    for (int k = -10; k <= 10; ++k) dy.push_back((jump_mm + 0.01 * k) * 1e-3);
  return dy;
}

bool same_bits(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

// Mismatch z_right - z_left of the full scans (what the cold search solves for).
double mismatch(const SideGeometry& side, double dy, double roll) {
  return side.first_contact_height(dy, roll) - side.first_contact_height(-dy, -roll);
}

void expect_tracker_equals_full_scan(const SideGeometry& side) {
  int windowed = 0, evaluations = 0;
  for (const double dy : shifts_across_jumps())
    for (const double shift : {dy, -dy}) {
      const double root = rigid_wheelset_pose(side, side, dy).roll_rad * (shift == dy ? 1.0 : -1.0);
      FirstContactTracker tracker(side, shift);
      // The roll search's pattern: a bracket around the guess, steps closing in, one far step (a full scan again).
      for (const double offset : {-2e-5, 2e-5, 1e-6, -3e-7, 1e-9, 0.0, 5e-14, -5e-14, 3e-3, 1e-4, 0.0}) {
        const double roll = root + offset;
        ASSERT_TRUE(same_bits(tracker.height(roll), side.first_contact_height(shift, roll)))
            << "dy " << shift << " roll " << roll;
        ++evaluations;
      }
      windowed += tracker.window_scans();
    }
  // The windows do the work away from the jumps (else the tracker saves nothing).
  EXPECT_GT(windowed, evaluations / 2) << windowed << " of " << evaluations;
}

void expect_guess_changes_nothing(const SideGeometry& side) {
  std::vector<double> rolls;
  for (const double dy : shifts_across_jumps()) {
    const WheelsetPose cold = rigid_wheelset_pose(side, side, dy);
    ASSERT_TRUE(cold.converged) << "dy " << dy;
    // From the previous shift's roll (as the sweep's runs), and from a guess 1 mrad off with a tiny spread.
    RollGuess neighbour{rolls.empty() ? cold.roll_rad : rolls.back(), 1e-6};
    RollGuess far_off{cold.roll_rad + 1e-3, 0.0};
    for (const RollGuess* guess : {&neighbour, &far_off}) {
      const WheelsetPose warm = rigid_wheelset_pose(side, side, dy, guess);
      EXPECT_TRUE(warm.converged);
      EXPECT_EQ(warm.roll_rad, cold.roll_rad) << "dy " << dy;  // bit for bit
      EXPECT_EQ(warm.z_right_m, cold.z_right_m) << "dy " << dy;
      EXPECT_EQ(warm.z_left_m, cold.z_left_m) << "dy " << dy;
    }
    // On the lattice, within one step of the root (the mismatch falls with the roll), and within the old cold
    // search's height tolerance (1e-12 m).
    EXPECT_EQ(std::fmod(cold.roll_rad, kRollLattice_rad), 0.0);
    EXPECT_GE(mismatch(side, dy, cold.roll_rad - kRollLattice_rad), 0.0) << "dy " << dy;
    EXPECT_LE(mismatch(side, dy, cold.roll_rad + kRollLattice_rad), 0.0) << "dy " << dy;
    EXPECT_LE(std::abs(mismatch(side, dy, cold.roll_rad)), 1e-12) << "dy " << dy;
    rolls.push_back(cold.roll_rad);
  }
}

struct BuiltInSide {
  ProfileTable wheel = load_profile("S1002", ProfileRole::Wheel, {});
  ProfileTable rail = load_profile("UIC60", ProfileRole::Rail, {});
  SideGeometry side{wheel, rail, TrackSetup{}};
};

TEST(RollSearch, TrackerEqualsFullScanBuiltIn) {
  const BuiltInSide built_in;
  expect_tracker_equals_full_scan(built_in.side);
}

TEST(RollSearch, GuessChangesNothingBuiltIn) {
  const BuiltInSide built_in;
  expect_guess_changes_nothing(built_in.side);
}

TEST(RollSearch, TrackerEqualsFullScanManchester) {
  if (!ctab::test::shared_dir_present()) GTEST_SKIP() << "../shared not available";
  const ctab::test::ManchesterSide manchester;
  expect_tracker_equals_full_scan(manchester.side);
}

TEST(RollSearch, GuessChangesNothingManchester) {
  if (!ctab::test::shared_dir_present()) GTEST_SKIP() << "../shared not available";
  const ctab::test::ManchesterSide manchester;
  expect_guess_changes_nothing(manchester.side);
}

// Derivative bounds of a profile's cubic: no sample of its slope or (finite-difference) curvature exceeds them.
TEST(RollSearch, DerivativeBoundsHoldBetweenNodes) {
  const BuiltInSide built_in;
  const DerivativeBlocks blocks(built_in.rail);
  const ProfileTable& rail = built_in.rail;
  const double h = rail.step() / 16;
  for (double y = rail.y_min(); y + h < rail.y_max(); y += h) {
    const ProfileTable::DerivativeBounds b = blocks.between(y, y + h);
    const double slope = rail.at(y).dz;
    EXPECT_LE(slope, b.slope_high + 1e-12 * std::abs(b.slope_high) + 1e-15) << y;
    EXPECT_GE(slope, b.slope_low - 1e-12 * std::abs(b.slope_low) - 1e-15) << y;
    EXPECT_LE(std::abs(rail.at(y + h).dz - slope) / h, b.second_derivative * (1 + 1e-6) + 1e-9) << y;
  }
}

}  // namespace
