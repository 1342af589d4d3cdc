// SPDX-License-Identifier: Apache-2.0
// Slots follow the contacts along dy (generator/sweep/include/ctab/sweep/slot_assignment.hpp): unit cases of the
// serial assignment, and a table on a hollow-worn S1002 (Manchester file with a 1 mm deep, 40 mm wide cosine hollow
// dug into the tread) whose two tread contacts used to swap slots 0 and 2 between neighbouring dy.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/slot_assignment.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/tables/table.hpp"
#include "test_support.hpp"

using namespace ctab::gen;
using ctab::tables::CaseStatus;
using ctab::tables::JumpKind;
using ctab::tables::Table;

namespace {

SlotCase success(std::vector<SlotPatch> patches) { return {true, std::move(patches)}; }

}  // namespace

TEST(SlotAssignment, FirstCaseIsTheZoneRule) {
  // Solver order: tread, flange, then two more tread patches: those go to 2, 3 in order of y_rail.
  const auto a = assign_slots_along_dy({success({{-5e-3, false}, {-34e-3, true}, {4e-3, false}, {-20e-3, false}})}, 4);
  EXPECT_EQ(a[0].slot_of, (std::vector<std::size_t>{0, 1, 3, 2}));
  EXPECT_FALSE(a[0].overflow);
}

TEST(SlotAssignment, TwoContactsKeepTheirSlotsWhenTheSolverOrderSwaps) {
  // The hollow-wheel case: the deepest (first) patch changes from +5 mm to -25 mm between two dy.
  const auto a = assign_slots_along_dy({success({{5.3e-3, false}, {-25.8e-3, false}}),
                                        success({{-25.8e-3, false}, {5.5e-3, false}}), success({{-25.7e-3, false}})},
                                       3);
  EXPECT_EQ(a[0].slot_of, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(a[1].slot_of, (std::vector<std::size_t>{2, 0}));
  EXPECT_EQ(a[2].slot_of, (std::vector<std::size_t>{2}));  // the +5 mm contact ended: slot 0 empties
}

TEST(SlotAssignment, NewContactTakesItsZoneSlotAndALoneJumpKeepsItsSlot) {
  const auto a =
      assign_slots_along_dy({success({{-7e-3, false}}), success({{-18e-3, false}}),  // lone tread jump, 11 mm
                             success({{-23e-3, false}, {-34e-3, true}}),             // flange appears
                             success({{-42e-3, true}}),                              // tread ends, flange jumps
                             success({})},                                           // no contact
                            3);
  EXPECT_EQ(a[1].slot_of, (std::vector<std::size_t>{0}));
  EXPECT_EQ(a[2].slot_of, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(a[3].slot_of, (std::vector<std::size_t>{1}));
  EXPECT_TRUE(a[4].slot_of.empty());
  EXPECT_FALSE(a[4].overflow);
}

TEST(SlotAssignment, TreadAndFlangeFarApartAreDifferentContacts) {
  // A lone tread patch followed by a lone flange patch 11 mm away (> 1 mm): the flange opens slot 1.
  const auto far = assign_slots_along_dy({success({{-23e-3, false}}), success({{-34e-3, true}})}, 3);
  EXPECT_EQ(far[1].slot_of, (std::vector<std::size_t>{1}));
  // Within the threshold it is one contact crossing the zone boundary: it keeps its slot.
  const auto near = assign_slots_along_dy({success({{-25.6e-3, false}}), success({{-26.4e-3, true}})}, 3);
  EXPECT_EQ(near[1].slot_of, (std::vector<std::size_t>{0}));
}

TEST(SlotAssignment, FailedAndOverflowingCasesCarryTheSlotsOver) {
  const auto a = assign_slots_along_dy({success({{5e-3, false}, {-25e-3, false}}), SlotCase{},       // failed
                                        success({{-25e-3, false}, {5e-3, false}, {-10e-3, false}}),  // 3 > 2 slots
                                        success({{-24.8e-3, false}, {5.1e-3, false}})},
                                       2);
  EXPECT_EQ(a[0].slot_of, (std::vector<std::size_t>{0, 1}));  // two slots: the second tread patch takes slot 1
  EXPECT_TRUE(a[1].slot_of.empty());
  EXPECT_TRUE(a[2].overflow);
  EXPECT_TRUE(a[2].slot_of.empty());
  EXPECT_EQ(a[3].slot_of, (std::vector<std::size_t>{1, 0}));  // matched to the last stored case
}

TEST(SlotAssignment, TiesAreDeterministic) {
  // Two previous contacts equally far from one patch: the lower slot wins.
  const auto a = assign_slots_along_dy({success({{-1e-3, false}, {1e-3, false}}), success({{0.0, false}})}, 3);
  EXPECT_EQ(a[1].slot_of, (std::vector<std::size_t>{0}));
}

namespace {

// The Manchester S1002 with a hollow of `depth_m` (cosine, `width_m` wide, centred on the tape circle) subtracted
// from its radius, written as a plain `y z` file in mm (canonical frame: y = S, z = radius increase).
std::string hollow_worn_wheel(double depth_m, double width_m) {
  ProfileReadOptions options;
  const ProfilePoints points =
      read_profile_points(ctab::test::shared_path("profiles/MBench_S1002_v3.prw"), ProfileRole::Wheel, options);
  // One file per test (CTest runs the tests of this file in parallel processes).
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string path = ::testing::TempDir() + "hollow_worn_s1002_" + test + ".txt";
  std::ofstream out(path);
  out.precision(12);
  for (std::size_t i = 0; i < points.y_m.size(); ++i) {
    const double u = points.y_m[i] / width_m;
    const double hollow = std::abs(u) < 0.5 ? depth_m * 0.5 * (1.0 + std::cos(2.0 * std::numbers::pi * u)) : 0.0;
    out << points.y_m[i] * 1e3 << ' ' << (points.z_m[i] - hollow) * 1e3 << '\n';
  }
  return path;
}

Table hollow_table(int threads) {
  const std::string config = "[profiles]\nwheel = \"" + hollow_worn_wheel(1e-3, 40e-3) + "\"\nrail = \"" +
                             ctab::test::shared_path("profiles/MBench_UIC60_v3.prr") +
                             "\"\ninclination = \"0\"\n[solver]\nmode = \"wheel\"\n"
                             "[axes]\nlateral_displacement_m = { start = -10e-3, stop = 10e-3, step = 0.25e-3 }\n"
                             "normal_load_N = 78.5e3\n[output]\nstrip_samples = 8\n";
  GeneratorInfo info;
  info.threads = threads;
  return generate_table(parse_table_config(config, "hollow.toml"), info);
}

}  // namespace

TEST(SlotAssignment, HollowWornWheelSlotsFollowTheContacts) {
  const Table table = hollow_table(2);
  const double few_mm = 3e-3;
  const std::size_t wheel = 0;  // single-wheel mode: the right wheel
  std::size_t two_contact_cells = 0;
  for (std::size_t i = 0; i + 1 < table.lateral_displacement_m.size(); ++i) {
    const CaseStatus status = table.status[table.wheel_index(i, 0, wheel)];  // under-resolved: usable, patches stored
    ASSERT_TRUE(status == CaseStatus::Converged || status == CaseStatus::UnderResolved) << "dy index " << i;
    for (std::size_t slot = 0; slot < table.n_slots; ++slot) {
      const std::size_t low = table.patch_index(i, 0, wheel, slot), high = table.patch_index(i + 1, 0, wheel, slot);
      if (!table.patch.present[low] || !table.patch.present[high]) continue;
      const double y_low = table.patch.y_rail_m[low], y_high = table.patch.y_rail_m[high];
      if (std::abs(y_high - y_low) <= few_mm) continue;
      // A slot moves by more than a few mm only where its contact really jumps: no patch at the next dy lies near
      // where this slot's contact was (so identity was not handed to a far contact), and the jump is in /jumps,
      // so the lookup never blends the two ends.
      for (std::size_t other = 0; other < table.n_slots; ++other) {
        const std::size_t k = table.patch_index(i + 1, 0, wheel, other);
        EXPECT_FALSE(table.patch.present[k] && std::abs(table.patch.y_rail_m[k] - y_low) <= few_mm)
            << "slot " << slot << " at dy " << table.lateral_displacement_m[i] * 1e3 << " mm: its contact at y_rail "
            << y_low * 1e3 << " mm went on in slot " << other << " while it took the one at " << y_high * 1e3 << " mm";
      }
      bool flagged = false;
      for (const auto& jump : table.jumps)
        flagged |= jump.i_second == 0 && jump.wheel == wheel && jump.slot == slot && jump.i_dy == i &&
                   jump.kind == JumpKind::Moves;
      EXPECT_TRUE(flagged) << "slot " << slot << " jumps at dy index " << i << " without a 'moves' jump";
    }
    std::size_t both = 0;
    for (std::size_t slot = 0; slot < table.n_slots; ++slot)
      both += table.patch.present[table.patch_index(i, 0, wheel, slot)] &&
              table.patch.present[table.patch_index(i + 1, 0, wheel, slot)];
    two_contact_cells += both >= 2;
  }
  EXPECT_GE(two_contact_cells, 3u) << "the hollow must give two tread contacts over a range of dy";
  // The swap of the zone rule (dy 0 -> 0.5 mm: the deepest patch changes from y_rail +5.3 to -25.8 mm): gone.
  const std::size_t at_0 = 40, at_half = 42;  // dy = 0 and 0.5 mm
  for (std::size_t slot = 0; slot < table.n_slots; ++slot) {
    const std::size_t a = table.patch_index(at_0, 0, wheel, slot), b = table.patch_index(at_half, 0, wheel, slot);
    if (table.patch.present[a] && table.patch.present[b]) {
      EXPECT_NEAR(table.patch.y_rail_m[a], table.patch.y_rail_m[b], 1e-3) << "slot " << slot;
    }
  }
}

TEST(SlotAssignment, HollowWornTableIsBitIdenticalAtOneAndTwoThreads) {
  const Table one = hollow_table(1), two = hollow_table(2);
  EXPECT_EQ(one.status, two.status);
  EXPECT_EQ(one.patch.present, two.patch.present);
  EXPECT_EQ(one.patch.y_rail_m, two.patch.y_rail_m);
  EXPECT_EQ(one.patch.normal_force_N, two.patch.normal_force_N);
  EXPECT_EQ(one.jumps.size(), two.jumps.size());
}

TEST(SlotAssignment, ALoneFlangePatchFitsOneSlot) {
  // Single wheel at dy = +7 mm: one flange patch. With one slot it takes slot 0 (the zone rule's slot 1 does not
  // exist); only a case with more patches than slots overflows.
  const Table table = generate_table(parse_table_config(R"(
[solver]
mode = "wheel"
[axes]
lateral_displacement_m = { start = -7e-3, stop = 7e-3, step = 7e-3 }
vertical_load_N = 78.5e3
[output]
patch_slots = 1
)",
                                                        "one_slot.toml"),
                                     GeneratorInfo{});
  EXPECT_EQ(table.status[table.wheel_index(2, 0, 0)], CaseStatus::Converged);
  EXPECT_EQ(table.patch.present[table.patch_index(2, 0, 0, 0)], 1);
  EXPECT_NEAR(table.patch.force_vertical_N[table.patch_index(2, 0, 0, 0)], 78.5e3, 1e-9 * 78.5e3);
}
