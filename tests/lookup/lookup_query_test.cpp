// SPDX-License-Identifier: Apache-2.0
// Interpolation and the jump rules of lookup/README.md on synthetic tables (linear data: interpolation is exact).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "ctab/lookup/table.hpp"
#include "load_and_query.hpp"
#include "synthetic_table.hpp"

namespace ctab::lookup {
namespace {

using test::make_synthetic;
using test::synthetic_value;

constexpr std::size_t kYRail = CTAB_Y_RAIL_M;

using test::load;
using test::query;

double quantity(const ctab_patch& patch, std::size_t q) { return patch.q[q]; }

TEST(LookupQuery, LinearDataIsReproducedOffGridInBothModes) {
  for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
    const Table table = load(make_synthetic(), mode);
    for (const double dy : {-11.73e-3, -0.31e-3, 2.5e-3, 5.99e-3}) {
      const ctab_result r = query(table, dy, 0.0, 1);
      ASSERT_EQ(r.status, CTAB_OK);
      EXPECT_EQ(r.n_slots, 3);
      EXPECT_EQ(r.patch[0].present, 1);
      EXPECT_EQ(r.patch[1].present, 0) << "no flange below 6 mm";
      for (std::size_t q = 0; q < kQuantities; ++q)
        EXPECT_NEAR(quantity(r.patch[0], q), synthetic_value(q, 0, 1, dy, 60e3), 1e-9) << "q " << q << " mode " << mode;
      EXPECT_NEAR(r.roll_rad, 1e-3 * dy + 1e-9 * 60e3, 1e-15);
      EXPECT_NEAR(r.rolling_radius_difference_m, 0.1 * dy, 1e-15);
      for (std::size_t q = 0; q < kQuantities; ++q) EXPECT_EQ(quantity(r.patch[1], q), 0.0);
    }
  }
}

TEST(LookupQuery, AppearingPatchTakesTheNearerNeighbourInsideTheJumpCell) {
  const TableData data = make_synthetic();  // flange appears between 6 and 7 mm
  for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
    const Table table = load(data, mode);
    EXPECT_EQ(table.rule(18, 0, 0, 1), CellRule::Nearest);
    EXPECT_EQ(table.rule(18, 0, 0, 0), CellRule::Interpolate);
    const ctab_result below = query(table, 6.49e-3, 0.0, 0);
    EXPECT_EQ(below.patch[1].present, 0);
    EXPECT_EQ(below.patch[1].q[CTAB_NORMAL_FORCE_N], 0.0);
    const ctab_result above = query(table, 6.5e-3, 0.0, 0);
    EXPECT_EQ(above.patch[1].present, 1);
    for (std::size_t q = 0; q < kQuantities; ++q)  // exactly the upper neighbour (7 mm), not a blend
      EXPECT_EQ(quantity(above.patch[1], q), data.quantities[data.patch_index(19, 0, 0, 1) * kQuantities + q]);
    // The tread slot interpolates through the same cell.
    EXPECT_NEAR(above.patch[0].q[CTAB_NORMAL_FORCE_N], synthetic_value(0, 0, 0, 6.5e-3, 60e3), 1e-9);
  }
}

TEST(LookupQuery, MovingPatchIsNotBlendedAcrossItsJump) {
  const TableData data = make_synthetic();  // spare slot's y_rail jumps 5 mm between -5 and -4 mm
  const Table table = load(data);
  const std::size_t lo = data.patch_index(7, 0, 1, 2), hi = data.patch_index(8, 0, 1, 2);
  const ctab_result near_lo = query(table, -4.6e-3, 0.0, 1), near_hi = query(table, -4.4e-3, 0.0, 1);
  EXPECT_EQ(near_lo.patch[2].present, 1);
  EXPECT_EQ(quantity(near_lo.patch[2], kYRail), data.quantities[lo * kQuantities + kYRail]);
  EXPECT_EQ(quantity(near_hi.patch[2], kYRail), data.quantities[hi * kQuantities + kYRail]);
}

TEST(LookupQuery, FailedNeighbourIsNeverUsed) {
  const TableData data = make_synthetic({.failed_case = true});  // right wheel fails at -8 mm
  const Table table = load(data);
  EXPECT_EQ(table.rule(3, 0, 0, 0), CellRule::LowerOnly);  // cell (-9, -8)
  EXPECT_EQ(table.rule(4, 0, 0, 0), CellRule::UpperOnly);  // cell (-8, -7)
  for (const double dy : {-8.3e-3, -7.9e-3}) {
    const ctab_result r = query(table, dy, 0.0, 0);
    EXPECT_EQ(r.patch[0].present, 1) << dy;
    EXPECT_LT(r.worst_case_status, 0);
    const double expected = dy < -8e-3 ? synthetic_value(0, 0, 0, -9e-3, 60e3) : synthetic_value(0, 0, 0, -7e-3, 60e3);
    EXPECT_NEAR(r.patch[0].q[CTAB_NORMAL_FORCE_N], expected, 1e-9) << dy;
  }
  EXPECT_EQ(query(table, -8.3e-3, 0.0, 1).worst_case_status, 0) << "the left wheel did not fail";
}

TEST(LookupQuery, UnderResolvedNeighbourIsUsedAndReported) {
  TableData data = make_synthetic();
  const std::size_t i = 4;  // -8 mm, right wheel: a quality warning (tables::CaseStatus::UnderResolved), not a failure
  data.case_status[data.case_index(i, 0, 0)] = 2;
  const Table table = load(data);
  EXPECT_EQ(table.rule(3, 0, 0, 0), CellRule::Interpolate);
  EXPECT_EQ(table.rule(4, 0, 0, 0), CellRule::Interpolate);
  const ctab_result r = query(table, -8.3e-3, 0.0, 0);
  EXPECT_EQ(r.status, CTAB_OK);
  EXPECT_NEAR(r.patch[0].q[CTAB_NORMAL_FORCE_N], synthetic_value(0, 0, 0, -8.3e-3, 60e3), 1e-9);
  EXPECT_EQ(r.neighbour_status[1], 2) << "the upper neighbour (-8 mm) is reported under-resolved";
  EXPECT_EQ(r.worst_case_status, 0) << "worst is the most severe: no failed neighbour";
}

TEST(LookupQuery, SecondAxisBlendsRowsOnlyWhereBothHaveThePatch) {
  const TableData data = make_synthetic({.n_second = 3, .second_row_flange_later = true});
  const Table table = load(data);
  // Linear in both axes where the patch exists in all four neighbours.
  const ctab_result r = query(table, 1.23e-3, 71e3, 0);
  ASSERT_EQ(r.status, CTAB_OK);
  EXPECT_NEAR(r.patch[0].q[CTAB_AREA_M2], synthetic_value(3, 0, 0, 1.23e-3, 71e3), 1e-9);
  EXPECT_NEAR(r.second, 71e3, 0.0);
  // The flange appears in row 0 (60 kN) in the cell 6-7 mm and in row 1 (80 kN) in the cell 7-8 mm: between the
  // rows it appears at the cells' midpoints interpolated in load (6.5 mm + 1 mm x g). At 69 kN (g = 0.45) that is
  // 6.95 mm: at 7.2 mm the flange is there, row 1 (without it at 7.2 mm) giving its value at its cell's far end.
  const ctab_result near0 = query(table, 7.2e-3, 69e3, 0), near1 = query(table, 7.2e-3, 71e3, 0);
  EXPECT_EQ(near0.patch[1].present, 1);
  EXPECT_NEAR(near0.patch[1].q[CTAB_NORMAL_FORCE_N],
              0.55 * synthetic_value(0, 1, 0, 7.2e-3, 60e3) + 0.45 * synthetic_value(0, 1, 0, 8e-3, 80e3), 1e-9);
  EXPECT_EQ(near1.patch[1].present, 1) << "at 71 kN the flange appears at 7.05 mm";
  // At 6.9 mm and 71 kN the query lies before the interpolated jump: no flange, though row 0 has it there.
  const ctab_result before = query(table, 6.9e-3, 71e3, 0);
  EXPECT_EQ(before.patch[1].present, 0);
  EXPECT_EQ(before.patch[1].q[CTAB_NORMAL_FORCE_N], 0.0);
  EXPECT_EQ(query(table, 6.9e-3, 60e3, 0).patch[1].present, 1) << "row 0 alone: past its midpoint";
}

TEST(LookupQuery, PchipDoesNotOvershootAStep) {
  TableData data = make_synthetic({.dy_min_m = 0.0, .dy_max_m = 10e-3});
  const std::size_t q = CTAB_AREA_M2;
  for (std::size_t i = 0; i < data.n_dy(); ++i)
    data.quantities[data.patch_index(i, 0, 0, 0) * kQuantities + q] = i < 5 ? 1.0 : 2.0;
  const Table table = load(data, CTAB_PCHIP);
  for (double dy = 0.0; dy <= 10e-3; dy += 0.05e-3) {
    const double v = query(table, dy, 0.0, 0).patch[0].q[CTAB_AREA_M2];
    EXPECT_GE(v, 1.0);
    EXPECT_LE(v, 2.0);
  }
  EXPECT_DOUBLE_EQ(query(table, 2.5e-3, 0.0, 0).patch[0].q[CTAB_AREA_M2], 1.0) << "flat data stays flat";
}

TEST(LookupQuery, StripProfileFollowsTheSlotRules) {
  const TableData data = make_synthetic();
  const Table table = load(data);
  ctab_location where;
  table.prelookup(2.5e-3, 0.0, where);
  double s[8], a[8], p0[8];
  std::uint32_t count = 0;
  EXPECT_EQ(table.strip_profile(where, 0, 0, s, a, p0, 8, &count), CTAB_OK);
  ASSERT_EQ(count, 5u);
  EXPECT_NEAR(s[0], synthetic_value(16, 0, 0, 2.5e-3, 60e3), 1e-9);
  EXPECT_NEAR(s[4], synthetic_value(17, 0, 0, 2.5e-3, 60e3), 1e-9);
  EXPECT_NEAR(a[2], 3e-3 * (1.0 + 2.5e-3), 1e-15);
  EXPECT_EQ(table.strip_profile(where, 0, 1, s, a, p0, 8, &count), CTAB_OK);
  EXPECT_EQ(count, 0u) << "no flange at 2.5 mm";
  EXPECT_EQ(table.strip_profile(where, 0, 0, s, a, p0, 4, &count), CTAB_INVALID_INPUT) << "capacity too small";
  EXPECT_EQ(table.strip_profile(where, 0, 3, s, a, p0, 8, &count), CTAB_INVALID_INPUT) << "no slot 3";
}

}  // namespace
}  // namespace ctab::lookup

namespace ctab::lookup {
namespace {

// A locally refined dy axis (tables/docs/method.md "Tables: sweep, slots, jumps, refined axis"): 0.1 mm steps between 5 and 7.5 mm in a 1 mm table.
TableData refined_synthetic() {
  return make_synthetic({.refine_from_m = 5e-3, .refine_to_m = 7.5e-3, .refine_step_m = 0.1e-3});
}

// The prelookup's index finds the cell a binary search finds, at random points, at every node and one ulp either
// side of it, with the fraction that gives the point back.
TEST(LookupQuery, RefinedAxisFindsTheCellOfABinarySearch) {
  const TableData data = refined_synthetic();
  ASSERT_EQ(data.n_dy(), 25u + 26u - 3u);  // 26 refined nodes, 3 of them on the uniform grid
  const Table table = load(data);
  std::vector<double> points;
  for (int k = 0; k < 200000; ++k)
    points.push_back(-12e-3 + 24e-3 * ((k * 0.6180339887498949) - std::floor(k * 0.6180339887498949)));
  for (const double node : data.dy_m)
    for (const double at : {std::nextafter(node, -1.0), node, std::nextafter(node, 1.0)})
      if (at >= data.dy_m.front() && at <= data.dy_m.back()) points.push_back(at);
  for (const double dy : points) {
    ctab_location where;
    table.prelookup(dy, 0.0, where);
    ASSERT_EQ(where.status, CTAB_OK);
    const auto above = std::upper_bound(data.dy_m.begin(), data.dy_m.end(), dy);
    const std::size_t expected =
        std::min<std::size_t>(static_cast<std::size_t>(above - data.dy_m.begin()) - 1, data.n_dy() - 2);
    ASSERT_EQ(where.i_dy, expected) << dy;
    const double width = data.dy_m[expected + 1] - data.dy_m[expected];
    ASSERT_NEAR(data.dy_m[expected] + where.f_dy * width, dy, 1e-15) << dy;
    ASSERT_EQ(where.dy_m, dy);
  }
  ctab_location outside;
  table.prelookup(7.6e-3 + 12e-3, 0.0, outside);
  EXPECT_EQ(outside.status, CTAB_CLAMPED);
  EXPECT_EQ(outside.i_dy, data.n_dy() - 2);
  EXPECT_EQ(outside.f_dy, 1.0);
}

// Linear data stay exact across coarse and refined cells in both modes (PCHIP's weighted harmonic mean of equal
// secants is that secant), and the jump rules hold in a refined cell: the flange, present from 6.5 mm on, appears
// in the refined cell (6.4, 6.5) mm and takes the nearer node's presence there.
TEST(LookupQuery, RefinedAxisReproducesLinearDataAndItsJumps) {
  const TableData data = refined_synthetic();
  for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
    const Table table = load(data, mode);
    for (const double dy : {-11.73e-3, 4.97e-3, 5.03e-3, 5.55e-3, 6.12e-3, 7.49e-3, 7.51e-3, 11.2e-3}) {
      const ctab_result r = query(table, dy, 0.0, 1);
      ASSERT_EQ(r.status, CTAB_OK);
      for (std::size_t q = 0; q < kQuantities; ++q)
        EXPECT_NEAR(quantity(r.patch[0], q), synthetic_value(q, 0, 1, dy, 60e3), 1e-9) << dy << " q " << q;
      EXPECT_NEAR(r.roll_rad, 1e-3 * dy + 1e-9 * 60e3, 1e-15);
    }
    EXPECT_EQ(query(table, 6.44e-3, 0.0, 0).patch[1].present, 0);  // the jump cell (6.4, 6.5): lower half
    EXPECT_EQ(query(table, 6.46e-3, 0.0, 0).patch[1].present, 1);  // upper half: the node at 6.5 mm
    EXPECT_NEAR(query(table, 6.7e-3, 0.0, 0).patch[1].q[CTAB_NORMAL_FORCE_N], synthetic_value(0, 1, 0, 6.7e-3, 60e3),
                1e-9);
  }
}

// Where the refinement pays: a curve tabulated on the refined axis, interpolated between its nodes. Linear
// interpolation's error falls as the step squared (10x finer: about 100x smaller), and PCHIP (Fritsch-Butland
// slopes on unequal cells) stays below linear inside both zones. In the refined zone's end cells its node slope
// at the zone's edge leans on the coarse neighbour's secant: there it may exceed linear's error (measured 1.9x).
TEST(LookupQuery, RefinedZoneFollowsACurveAsItsStepSquared) {
  TableData data = refined_synthetic();
  const auto curve = [](double dy) { return 1e3 * (2.0 + std::sin(600.0 * dy)); };  // period 10.5 mm
  for (std::size_t i = 0; i < data.n_dy(); ++i)
    data.quantities[data.patch_index(i, 0, 0, 0) * kQuantities + CTAB_NORMAL_FORCE_N] = curve(data.dy_m[i]);
  double worst[2][3] = {};  // [linear, pchip][coarse zone, refined zone's inner cells, its end cells]
  for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
    const Table table = load(data, mode);
    for (double dy = -11.99e-3; dy < 11.99e-3; dy += 0.0137e-3) {
      const double error = std::abs(query(table, dy, 0.0, 0).patch[0].q[CTAB_NORMAL_FORCE_N] - curve(dy));
      const int zone = dy <= 5e-3 || dy >= 7.5e-3 ? 0 : dy > 5.1e-3 && dy < 7.4e-3 ? 1 : 2;
      worst[mode == CTAB_PCHIP][zone] = std::max(worst[mode == CTAB_PCHIP][zone], error);
    }
  }
  // Linear: h^2 |f''| / 8 = (1 mm)^2 x 360 / 8 = 45 N coarse, 0.45 N refined.
  EXPECT_NEAR(worst[0][0], 45.0, 5.0);
  EXPECT_LT(worst[0][1], 0.5);
  EXPECT_GT(worst[0][1], 0.3);
  EXPECT_LT(worst[1][0], worst[0][0]);
  EXPECT_LT(worst[1][1], worst[0][1]);
  EXPECT_LT(worst[1][2], 2.0 * std::max(worst[0][1], worst[0][2]));
  std::printf(
      "linear / PCHIP max error: coarse %.3g / %.3g N, refined inner %.3g / %.3g N, refined end cells %.3g / %.3g N\n",
      worst[0][0], worst[1][0], worst[0][1], worst[1][1], worst[0][2], worst[1][2]);
}

}  // namespace
}  // namespace ctab::lookup
