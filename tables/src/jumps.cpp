// SPDX-License-Identifier: Apache-2.0
// Contact jumps along the lateral axis (the rules are in table.hpp and tables/README.md).
#include <algorithm>
#include <cmath>

#include "ctab/tables/table.hpp"

namespace ctab::tables {

namespace {

// Jumps in the cells `in_cell` accepts: a slot that appears or disappears, or whose y_rail_m moves by more than
// threshold_m, in the order of Table::jumps.
template <class CellFilter>
std::vector<Jump> jumps_in_cells(const Table& table, double threshold_m, const CellFilter& in_cell) {
  std::vector<Jump> jumps;
  const auto& dy = table.lateral_displacement_m;
  const auto& present = table.patch.present;
  const auto& y_rail = table.patch.y_rail_m;
  for (std::size_t i_second = 0; i_second < table.n_second(); ++i_second)
    for (std::size_t wheel = 0; wheel < kWheels; ++wheel)
      for (std::size_t slot = 0; slot < table.n_slots; ++slot)
        for (std::size_t i_dy = 0; i_dy + 1 < dy.size(); ++i_dy) {
          if (!in_cell(i_dy, i_second)) continue;
          const std::size_t low = table.patch_index(i_dy, i_second, wheel, slot);
          const std::size_t high = table.patch_index(i_dy + 1, i_second, wheel, slot);
          JumpKind kind{};
          if (present[low] == 0 && present[high] != 0) kind = JumpKind::Appears;
          else if (present[low] != 0 && present[high] == 0) kind = JumpKind::Disappears;
          else if (present[low] != 0 && std::abs(y_rail[high] - y_rail[low]) > threshold_m) kind = JumpKind::Moves;
          else continue;
          jumps.push_back({static_cast<std::uint32_t>(i_second), static_cast<std::uint8_t>(wheel),
                           static_cast<std::uint8_t>(slot), static_cast<std::uint32_t>(i_dy), kind});
        }
  return jumps;
}

}  // namespace

std::vector<Jump> detect_jumps(const Table& table) {
  const auto& dy = table.lateral_displacement_m;
  if (dy.size() < 2) return {};
  double largest_step = 0.0;  // a refined axis keeps the threshold of its coarse step
  for (std::size_t i = 1; i < dy.size(); ++i) largest_step = std::max(largest_step, dy[i] - dy[i - 1]);
  const double threshold_m = std::max(1e-3, 10.0 * largest_step);  // max(1 mm, 10 dy steps)
  return jumps_in_cells(table, threshold_m, [](std::size_t, std::size_t) { return true; });
}

std::vector<Jump> table_jumps(const Table& table) {
  const std::size_t n_second = table.n_second();
  if (table.cell_error.empty() || table.cell_error.size() != (table.n_dy() - 1) * n_second * kCellErrorQuantities)
    return detect_jumps(table);
  const auto found = table.number_attributes.find(kToleranceAttributes[2]);
  const double threshold_m = jump_move_threshold(found != table.number_attributes.end() ? found->second : 0.0);
  const auto& dy = table.lateral_displacement_m;
  return jumps_in_cells(table, threshold_m, [&](std::size_t i_dy, std::size_t i_second) {
    return dy[i_dy + 1] - dy[i_dy] <= kJumpCellWidth_m &&
           table.cell_error[(i_dy * n_second + i_second) * kCellErrorQuantities] == kCellNotMeasured;
  });
}

}  // namespace ctab::tables
