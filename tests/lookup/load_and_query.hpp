// SPDX-License-Identifier: Apache-2.0
#pragma once
// The two steps most lookup tests take: load a TableData (the load must succeed) and query one wheel at a point.
#include <gtest/gtest.h>

#include <cstring>

#include "ctab/lookup/table.hpp"

namespace ctab::lookup::test {

inline Table load(const TableData& data, ctab_interpolation interpolation = CTAB_LINEAR, bool single = false) {
  Table table;
  const LoadResult result = table.load(data, {interpolation, single});
  EXPECT_TRUE(result.ok()) << result.message;
  return table;
}

inline ctab_result query(const Table& table, double dy, double second, int wheel) {
  ctab_location where;
  table.prelookup(dy, second, where);
  ctab_result result;
  std::memset(&result, 0, sizeof result);
  table.query(where, wheel, result);
  return result;
}

}  // namespace ctab::lookup::test
