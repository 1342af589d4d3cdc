// SPDX-License-Identifier: Apache-2.0
// Query and load statuses: NaN, out of range, not loaded, bad arguments; bad tables refused with their status.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "ctab/lookup/ctab_lookup.h"
#include "ctab/lookup/table.hpp"
#include "synthetic_table.hpp"

namespace ctab::lookup {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void expect_finite_and_absent(const ctab_result& r) {
  for (int s = 0; s < CTAB_MAX_SLOTS; ++s) {
    EXPECT_EQ(r.patch[s].present, 0);
    for (const double v : r.patch[s].q) EXPECT_TRUE(std::isfinite(v));
  }
  EXPECT_TRUE(std::isfinite(r.roll_rad) && std::isfinite(r.rolling_radius_difference_m) && std::isfinite(r.dy_m));
}

ctab_result garbage_result() {
  ctab_result r;
  std::memset(&r, 0, sizeof r);
  for (auto& patch : r.patch) patch.present = 7;
  return r;
}

TEST(LookupStatus, NanAndInfinityAreInvalidWithZeroedFiniteOutputs) {
  Table table;
  ASSERT_TRUE(table.load(test::make_synthetic({.n_second = 2}), {}).ok());
  for (const auto& [dy, second] : {std::pair{kNaN, 70e3}, {1e-3, kNaN}, {INFINITY, 70e3}, {1e-3, -INFINITY}}) {
    ctab_location where;
    table.prelookup(dy, second, where);
    EXPECT_EQ(where.status, CTAB_INVALID_INPUT);
    ctab_result r = garbage_result();
    table.query(where, 0, r);
    EXPECT_EQ(r.status, CTAB_INVALID_INPUT);
    expect_finite_and_absent(r);
  }
}

TEST(LookupStatus, OneRowTableIgnoresTheSecondValue) {
  Table table;
  ASSERT_TRUE(table.load(test::make_synthetic(), {}).ok());
  ctab_location where;
  table.prelookup(1e-3, kNaN, where);
  EXPECT_EQ(where.status, CTAB_OK);
}

TEST(LookupStatus, OutOfRangeIsClampedToTheEdge) {
  Table table;
  ASSERT_TRUE(table.load(test::make_synthetic({.n_second = 2}), {}).ok());
  ctab_result outside = garbage_result(), edge = garbage_result();
  ctab_location where;
  table.prelookup(50e-3, 1e9, where);
  EXPECT_EQ(where.status, CTAB_CLAMPED);
  table.query(where, 1, outside);
  EXPECT_EQ(outside.status, CTAB_CLAMPED);
  EXPECT_EQ(outside.dy_m, 12e-3);
  table.prelookup(12e-3, 80e3, where);
  EXPECT_EQ(where.status, CTAB_OK) << "the last grid point is inside";
  table.query(where, 1, edge);
  EXPECT_EQ(outside.patch[0].q[CTAB_NORMAL_FORCE_N], edge.patch[0].q[CTAB_NORMAL_FORCE_N]);
  table.prelookup(-1.0, 0.0, where);
  EXPECT_EQ(where.status, CTAB_CLAMPED);
  EXPECT_EQ(where.i_dy, 0u);
  EXPECT_EQ(where.f_dy, 0.0);
}

TEST(LookupStatus, BadWheelAndNoTableAreReported) {
  Table table;
  ctab_location where;
  table.prelookup(0.0, 0.0, where);
  EXPECT_EQ(where.status, CTAB_NOT_LOADED);
  ctab_result r = garbage_result();
  table.query(where, 0, r);
  EXPECT_EQ(r.status, CTAB_NOT_LOADED);
  expect_finite_and_absent(r);
  ASSERT_TRUE(table.load(test::make_synthetic(), {}).ok());
  table.prelookup(0.0, 0.0, where);
  r = garbage_result();
  table.query(where, 2, r);
  EXPECT_EQ(r.status, CTAB_INVALID_INPUT);
  expect_finite_and_absent(r);
  where.f_dy = kNaN;  // a tampered location
  table.query(where, 0, r);
  EXPECT_EQ(r.status, CTAB_INVALID_INPUT);
  r = garbage_result();
  EXPECT_EQ(ctab_query(nullptr, 0.0, 0.0, 0, &r), CTAB_NOT_LOADED);
  expect_finite_and_absent(r);
}

TEST(LookupStatus, BadTablesAreRefusedWithTheirStatus) {
  const auto refused = [](TableData data) {
    Table table;
    const LoadResult result = table.load(data, {});
    EXPECT_FALSE(table.loaded());
    EXPECT_FALSE(result.message.empty());
    return result.status;
  };
  TableData data = test::make_synthetic();
  data.quantities[100] = kNaN;
  EXPECT_EQ(refused(data), CTAB_ERR_CONTENT);
  data = test::make_synthetic();
  data.roll_rad[3] = INFINITY;
  EXPECT_EQ(refused(data), CTAB_ERR_CONTENT);
  data = test::make_synthetic();
  data.dy_m[5] = data.dy_m[4];
  EXPECT_EQ(refused(data), CTAB_ERR_AXES) << "dy not strictly increasing";
  data = test::make_synthetic();
  data.dy_m[5] = data.dy_m[4] + 0.5e-7;  // a step below tables::kMinDyStep (0.1 um)
  EXPECT_EQ(refused(data), CTAB_ERR_AXES) << "dy step below kMinDyStep";
  data.dy_m[5] = data.dy_m[4] + 1e-7;  // a located jump's cell: an adaptive axis loads
  Table refined;
  EXPECT_TRUE(refined.load(data, {}).ok());
  data = test::make_synthetic();
  data.case_status[2] = 9;
  EXPECT_EQ(refused(data), CTAB_ERR_CONTENT);
  data = test::make_synthetic();
  data.present[4] = 2;
  EXPECT_EQ(refused(data), CTAB_ERR_CONTENT);
  data = test::make_synthetic();
  data.jumps.push_back({0, 24, 0, 0, JumpKind::Moves});  // i_dy + 1 beyond the axis
  EXPECT_EQ(refused(data), CTAB_ERR_CONTENT);
  data = test::make_synthetic();
  data.present.pop_back();
  EXPECT_EQ(refused(data), CTAB_ERR_SHAPE);
  data = test::make_synthetic();
  data.second = {2.0, 1.0};
  EXPECT_EQ(refused(data), CTAB_ERR_AXES);
}

TEST(LookupStatus, EveryStatusHasAMessage) {
  for (int s = -20; s <= 2; ++s) EXPECT_NE(ctab_status_message(s), nullptr);
  EXPECT_STREQ(ctab_status_message(CTAB_OK), "ok");
  EXPECT_STREQ(ctab_status_message(12345), "unknown status");
}

}  // namespace
}  // namespace ctab::lookup
