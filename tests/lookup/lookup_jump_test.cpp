// SPDX-License-Identifier: Apache-2.0
// Located jumps on adaptive dy axes (lookup/README.md "Jumps and absent patches", "Prelookup"): the prelookup on
// axes with steps from 0.1 um to 1 mm, the side a query takes near and inside a located jump's cell, between
// second-axis rows whose jumps lie at different dy (the load-interpolated jump), PCHIP slopes that stop at a jump
// cell, single precision and the blob round trip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/open.hpp"
#include "ctab/lookup/table.hpp"
#include "load_and_query.hpp"
#include "synthetic_table.hpp"

namespace ctab::lookup {
namespace {

using test::kLocatedHalfCell;
using test::located_jump;
using test::located_value;
using test::LocatedOptions;

const LocatedOptions kOptions;
const TableData kLocated = test::make_located(kOptions);

using test::load;
using test::query;

double load_of(std::size_t row) { return 60e3 + 20e3 * static_cast<double>(row); }

// What one row gives for slot s at dy on its own: the side of its jump dy is on, and inside the jump's cell the
// nearer end's one-sided value.
double own_value(std::size_t q, std::size_t s, std::size_t w, double dy, std::size_t row, bool& present) {
  const double x = located_jump(kOptions, s, row);
  if (std::abs(dy - x) < kLocatedHalfCell) {
    const bool after = dy >= x;
    return located_value(q, s, w, x + (after ? kLocatedHalfCell : -kLocatedHalfCell), load_of(row), after, present);
  }
  return located_value(q, s, w, dy, load_of(row), dy > x, present);
}

// The documented answer between rows j and j + 1 (fraction g): the jump at the midpoints' load-interpolated
// position when the rows' cells differ; a row on the other side of its own jump gives its cell's end on the query's
// side; the rows blend where both give the patch, else the nearer row.
double expected(std::size_t q, std::size_t s, std::size_t w, double dy, std::size_t j, double g, bool& present) {
  const double x0 = located_jump(kOptions, s, j), x1 = located_jump(kOptions, s, j + 1);
  const bool after = dy >= (1.0 - g) * x0 + g * x1;
  double v[2];
  bool p[2];
  for (std::size_t r = 0; r < 2; ++r) {
    const double x = r == 0 ? x0 : x1;
    if (x0 == x1 || (dy >= x) == after) v[r] = own_value(q, s, w, dy, j + r, p[r]);
    else v[r] = located_value(q, s, w, x + (after ? kLocatedHalfCell : -kLocatedHalfCell), load_of(j + r), after, p[r]);
  }
  const double w1 = p[0] && p[1] ? g : g >= 0.5 ? 1.0 : 0.0;
  present = (w1 < 0.5 ? p[0] : p[1]);
  return (1.0 - w1) * v[0] + w1 * v[1];
}

TEST(LookupJump, AdaptiveAxisWithLocatedCellsLoads) {
  const auto& dy = kLocated.dy_m;
  double smallest = 1.0, largest = 0.0;
  for (std::size_t i = 1; i < dy.size(); ++i) {
    smallest = std::min(smallest, dy[i] - dy[i - 1]);
    largest = std::max(largest, dy[i] - dy[i - 1]);
  }
  EXPECT_NEAR(smallest, 2.0 * kLocatedHalfCell, 1e-12);
  EXPECT_GT(largest / smallest, 64.0) << "the steps' ratio exceeds the old refinement bound";
  for (const Jump& j : kLocated.jumps) EXPECT_LE(dy[j.i_dy + 1] - dy[j.i_dy], 1e-6 + 1e-12);
  const Table table = load(kLocated);
  // Per wheel: slot 0 disappears in the same cell in rows 0 and 1 (no band), slots 1 and 2 move in both row pairs.
  EXPECT_EQ(table.jump_bands(), 2u * 5u);
  EXPECT_LE(table.dy_search_length(), 16u) << "the index keeps the search short";
  std::printf("adaptive axis: %zu nodes, steps %.2g .. %.2g m, search over %u cells\n", dy.size(), smallest, largest,
              table.dy_search_length());
}

// Every point's cell is the one std::upper_bound finds, on the located axis and on random adaptive axes of 600 nodes
// with steps from 0.1 um to 1 mm (index entries hold many cells where the nodes cluster).
TEST(LookupJump, PrelookupFindsTheCellOnAnyIncreasingAxis) {
  std::mt19937_64 random(5);
  for (int trial = 0; trial < 4; ++trial) {
    TableData data = trial == 0 ? kLocated : test::make_synthetic();
    if (trial > 0) {
      std::uniform_real_distribution<double> log_step(std::log(1.01e-7), std::log(1e-3));
      std::vector<double> axis = {-5e-3};
      for (std::size_t i = 1; i < 600; ++i) axis.push_back(axis.back() + std::exp(log_step(random)));
      data.dy_m = axis;
      data.jumps.clear();
      data.allocate();
    }
    const Table table = load(data);
    const auto& dy = data.dy_m;
    std::vector<double> points;
    for (std::size_t i = 0; i + 1 < dy.size(); ++i)
      points.insert(points.end(), {dy[i], 0.5 * (dy[i] + dy[i + 1]), std::nextafter(dy[i + 1], dy[i])});
    std::uniform_real_distribution<double> anywhere(dy.front(), dy.back());
    for (int k = 0; k < 20000; ++k) points.push_back(anywhere(random));
    for (const double d : points) {
      ctab_location where;
      table.prelookup(d, table.second_axis().front(), where);
      const auto above = std::upper_bound(dy.begin(), dy.end(), d);
      const auto cell = std::min<std::size_t>(static_cast<std::size_t>(above - dy.begin()) - 1, dy.size() - 2);
      ASSERT_EQ(where.i_dy, cell) << "trial " << trial << " dy " << d;
      ASSERT_NEAR(where.f_dy, (d - dy[cell]) / (dy[cell + 1] - dy[cell]), 1e-9);
    }
  }
}

// On one row: a query within 2 um of a located jump takes its side's values, exact (linear data on each side);
// inside the 1 um cell, the nearer end's one-sided value. PCHIP gives the same: its slopes at the cell's ends come
// from the own side only (a slope across the cell would carry the jump, 100 x a value, into its neighbours).
TEST(LookupJump, OneRowTakesTheSideOfTheJump) {
  for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP})
    for (const bool single : {false, true}) {
      const Table table = load(kLocated, mode, single);
      const double tolerance = single ? 1e-6 : 1e-10;
      for (std::size_t row = 0; row < kOptions.appears_at_m.size(); ++row)
        for (std::size_t s = 0; s < 3; ++s)
          for (const double offset : {-2e-6, -1.5e-6, -0.6e-6, -0.4e-6, -0.1e-6, 0.1e-6, 0.4e-6, 0.6e-6, 1.5e-6, 2e-6,
                                      -30e-6, 30e-6, -0.3e-3, 0.3e-3}) {
            const double dy = located_jump(kOptions, s, row) + offset;
            for (int w = 0; w < 2; ++w) {
              const ctab_result r = query(table, dy, load_of(row), w);
              for (const std::size_t q : {std::size_t{CTAB_NORMAL_FORCE_N}, std::size_t{CTAB_Y_RAIL_M}}) {
                bool present = false;
                const double v = own_value(q, s, static_cast<std::size_t>(w), dy, row, present);
                ASSERT_EQ(r.patch[s].present, present ? 1 : 0) << mode << single << " row " << row << " slot " << s
                                                               << " offset " << offset;
                ASSERT_NEAR(r.patch[s].q[q], v, tolerance * (1.0 + std::abs(v)))
                    << mode << single << " row " << row << " slot " << s << " offset " << offset;
              }
            }
          }
    }
}

// Between rows the jump lies at the load-interpolated position: the query takes one side, from both rows, and never
// blends one row's values before the jump with the other's after it (Moves: the 100 x step comes whole or not at all).
TEST(LookupJump, RowsBetweenTakeOneSideOfTheInterpolatedJump) {
  for (const bool single : {false, true}) {
    const Table table = load(kLocated, CTAB_LINEAR, single);
    const double tolerance = single ? 1e-6 : 1e-10;
    std::mt19937_64 random(17);
    std::uniform_real_distribution<double> near(-1e-3, 1e-3), load(60e3, 100e3);
    for (int k = 0; k < 20000; ++k) {
      const std::size_t s = static_cast<std::size_t>(k % 3), w = static_cast<std::size_t>(k / 3 % 2);
      const double second = load(random);
      const std::size_t j = second < 80e3 ? 0 : 1;
      const double g = (second - load_of(j)) / 20e3;
      const double dy = 0.5 * (located_jump(kOptions, s, j) + located_jump(kOptions, s, j + 1)) + near(random);
      const ctab_result r = query(table, dy, second, static_cast<int>(w));
      for (const std::size_t q : {std::size_t{CTAB_NORMAL_FORCE_N}, std::size_t{CTAB_Y_RAIL_M}}) {
        bool present = false;
        const double v = expected(q, s, w, dy, j, g, present);
        ASSERT_EQ(r.patch[s].present, present ? 1 : 0) << "slot " << s << " dy " << dy << " load " << second;
        ASSERT_NEAR(r.patch[s].q[q], v, tolerance * (1.0 + std::abs(v)))
            << "slot " << s << " wheel " << w << " dy " << dy << " load " << second;
      }
    }
  }
}

// At a fixed dy between the rows' jumps, the flange appears once as the load rises: where the interpolated jump
// passes dy (rows 0 and 1: 1.234 and 2.071 mm; at 1.5 mm that is g = 0.318, 66.36 kN).
TEST(LookupJump, PresenceSwitchesOnceAtTheInterpolatedJump) {
  const Table table = load(kLocated);
  const double dy = 1.5e-3, x0 = located_jump(kOptions, 1, 0), x1 = located_jump(kOptions, 1, 1);
  const double switch_load = 60e3 + 20e3 * (dy - x0) / (x1 - x0);
  for (double second = 60e3; second <= 80e3; second += 50.0)
    EXPECT_EQ(query(table, dy, second, 0).patch[1].present, second <= switch_load - 1.0 ? 1 : 0) << second;
  // The strip profile takes the same side.
  for (double second = 60e3; second <= 80e3; second += 250.0) {
    ctab_location where;
    table.prelookup(dy, second, where);
    double a[4];
    std::uint32_t count = 0;
    EXPECT_GE(table.strip_profile(where, 0, 1, nullptr, a, nullptr, 4, &count), 0);
    EXPECT_EQ(count, query(table, dy, second, 0).patch[1].present ? 2u : 0u) << second;
  }
}

TEST(LookupJump, BlobRoundTripKeepsTheAxisAndTheJumps) {
  for (const bool single : {false, true}) {
    const std::vector<unsigned char> blob = write_blob(kLocated, single);
    TableData back;
    bool back_single = false;
    ASSERT_TRUE(read_blob(blob.data(), blob.size(), back, back_single).ok());
    EXPECT_EQ(back.dy_m, kLocated.dy_m);
    ASSERT_EQ(back.jumps.size(), kLocated.jumps.size());
    for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
      const Table direct = load(back, mode, single);  // in single precision the blob holds the values as floats
      Table from_blob;
      ASSERT_TRUE(open_memory(blob.data(), blob.size(), {mode, single}, from_blob).ok());
      EXPECT_EQ(from_blob.jump_bands(), direct.jump_bands());
      std::vector<ctab_result> a, b;
      for (double dy = -5.1e-3; dy <= 5.1e-3; dy += 0.0173e-3)
        for (const double second : {60e3, 67e3, 80e3, 93e3})
          for (int w = 0; w < 2; ++w) {
            a.push_back(query(direct, dy, second, w));
            b.push_back(query(from_blob, dy, second, w));
          }
      EXPECT_TRUE(test::identical(a, b)) << single << mode;
    }
  }
}

}  // namespace
}  // namespace ctab::lookup
