// SPDX-License-Identifier: Apache-2.0
// `ctab verify`'s classes of cell and its draw (generator/cli/verify_cells.hpp) on small synthetic tables: a located
// jump (a cell 0.5 um wide) is never sampled, nor the 1 um beside it; its neighbours are jump cells; the knee is the
// cell where the force changes fastest; a second axis adds the load class; the draw is the same for a seed.
#include <gtest/gtest.h>

#include <cmath>

#include "ctab/tables/table.hpp"
#include "verify_cells.hpp"

namespace {

using ctab::cli::CellClass;
using ctab::cli::kLocatedJumpWidth_m;

constexpr std::size_t index(CellClass c) { return static_cast<std::size_t>(c); }

// One slot everywhere on both wheels (force `force(i)` at dy node i, flat rail contact point) on the given dy axis
// and second axis.
ctab::tables::Table synthetic(const std::vector<double>& dy_m, const std::vector<double>& second,
                              double (*force)(std::size_t)) {
  ctab::tables::Table t;
  t.lateral_displacement_m = dy_m;
  t.second_axis = second;
  t.second_axis_name = "vertical_load_N";
  t.n_slots = 2;
  t.strip_samples = 0;
  t.allocate();
  for (std::size_t i = 0; i < t.n_dy(); ++i)
    for (std::size_t j = 0; j < t.n_second(); ++j)
      for (std::size_t wheel = 0; wheel < ctab::tables::kWheels; ++wheel) {
        const std::size_t k = t.patch_index(i, j, wheel, 0);
        t.patch.present[k] = 1;
        t.patch.normal_force_N[k] = force(i);
      }
  return t;
}

double steady(std::size_t) { return 80e3; }
double knee_at_4(std::size_t i) { return i <= 4 ? 80e3 : 120e3; }

}  // namespace

TEST(VerifyCells, LocatedJumpIsNotSampledNorTheMicrometreBesideIt) {
  // nodes 0..2 at 0.1 mm steps, a located jump 0.5 um wide between nodes 2 and 3, then 0.1 mm steps again
  const double located = 0.2e-3;
  std::vector<double> dy{0.0, 0.1e-3, located, located + 0.5e-6, 0.3e-3, 0.4e-3};
  ctab::tables::Table t = synthetic(dy, {78.5e3}, steady);
  for (std::size_t i = 3; i < t.n_dy(); ++i) {  // a second patch from the jump on, on the right wheel
    const std::size_t k = t.patch_index(i, 0, 0, 1);
    t.patch.present[k] = 1;
    t.patch.normal_force_N[k] = 1e3;
  }
  t.jumps.push_back({0, 0, 1, 2, ctab::tables::JumpKind::Appears});
  const ctab::cli::CellClasses classes = ctab::cli::classify_cells(t);
  const auto& jump = classes[index(CellClass::Jump)];
  ASSERT_EQ(jump.size(), 2u);
  EXPECT_DOUBLE_EQ(jump[0].dy_high_m, located - kLocatedJumpWidth_m);
  EXPECT_DOUBLE_EQ(jump[1].dy_low_m, located + 0.5e-6 + kLocatedJumpWidth_m);
  for (const auto& cell : jump) EXPECT_EQ(cell.wheel, 0u);
  for (std::size_t c = 0; c < ctab::cli::kCellClasses; ++c)
    for (const auto& cell : classes[c])
      EXPECT_FALSE(cell.dy_low_m < located + 0.5e-6 && cell.dy_high_m > located)
          << ctab::cli::cell_class_name(static_cast<CellClass>(c));
  EXPECT_EQ(classes[index(CellClass::TwoPatch)].size(), 1u);  // the right wheel's last cell
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    std::printf("seed %llu\n", static_cast<unsigned long long>(seed));
    const auto points = ctab::cli::draw_samples(classes, 200, seed);
    ASSERT_EQ(points.size(), 200u);
    for (const auto& p : points)  // the left wheel has no jump there: its cells reach the narrow cell
      EXPECT_FALSE(p.wheel == 0 && p.dy_m > located - kLocatedJumpWidth_m &&
                   p.dy_m < located + 0.5e-6 + kLocatedJumpWidth_m)
          << "seed " << seed << " point " << p.index << " dy " << p.dy_m;
  }
}

TEST(VerifyCells, KneeIsTheFastestForceChange) {
  std::vector<double> dy;
  for (int i = 0; i <= 10; ++i) dy.push_back(i * 0.1e-3);
  const ctab::cli::CellClasses classes = ctab::cli::classify_cells(synthetic(dy, {78.5e3}, knee_at_4));
  const auto& knee = classes[index(CellClass::Knee)];
  ASSERT_EQ(knee.size(), 2u);  // both wheels of the cell (4, 5)
  EXPECT_DOUBLE_EQ(knee[0].dy_low_m, dy[4]);
  EXPECT_EQ(classes[index(CellClass::Tread)].size(), 18u);
  EXPECT_TRUE(classes[index(CellClass::Load)].empty());
}

TEST(VerifyCells, SecondAxisDrawsLoadsAndTheLoadClass) {
  const std::vector<double> dy{0.0, 0.1e-3, 0.2e-3}, loads{40e3, 80e3, 120e3};
  const ctab::cli::CellClasses classes = ctab::cli::classify_cells(synthetic(dy, loads, steady));
  EXPECT_EQ(classes[index(CellClass::Tread)].size(), 2u * 2u * 2u);  // dy cells x load cells x wheels
  EXPECT_EQ(classes[index(CellClass::Load)].size(), 3u * 2u * 2u);   // dy nodes x load cells x wheels
  const auto points = ctab::cli::draw_samples(classes, 40, 5), again = ctab::cli::draw_samples(classes, 40, 5);
  ASSERT_EQ(points.size(), 40u);
  std::size_t load_points = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_EQ(points[k].dy_m, again[k].dy_m);
    EXPECT_EQ(points[k].second, again[k].second);
    EXPECT_GT(points[k].second, 40e3);
    EXPECT_LT(points[k].second, 120e3);
    if (points[k].cell_class != CellClass::Load) continue;
    ++load_points;
    EXPECT_TRUE(points[k].dy_m == dy[0] || points[k].dy_m == dy[1] || points[k].dy_m == dy[2]);
  }
  EXPECT_EQ(load_points, 20u);  // shared evenly between the two classes drawn
}
