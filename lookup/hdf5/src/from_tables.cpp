// SPDX-License-Identifier: Apache-2.0
// tables::Table (schema 2) -> lookup::TableData: the patch quantities gathered per patch in ctab_patch order.
#include <array>
#include <cstddef>

#include "ctab/lookup/hdf5_table.hpp"
#include "load_guard.hpp"

namespace ctab::lookup {

namespace {

using Column = std::vector<double> tables::PatchQuantities::*;

//! The schema-2 datasets in ctab_patch order.
constexpr std::array<Column, kQuantities> kColumns = {
    &tables::PatchQuantities::normal_force_N,    &tables::PatchQuantities::force_lateral_N,
    &tables::PatchQuantities::force_vertical_N,  &tables::PatchQuantities::area_m2,
    &tables::PatchQuantities::max_pressure_Pa,   &tables::PatchQuantities::approach_m,
    &tables::PatchQuantities::contact_angle_rad, &tables::PatchQuantities::plane_angle_rad,
    &tables::PatchQuantities::s_origin_y_rail_m, &tables::PatchQuantities::s_origin_z_rail_m,
    &tables::PatchQuantities::y_wheel_m,         &tables::PatchQuantities::y_rail_m,
    &tables::PatchQuantities::y_cop_rail_m,      &tables::PatchQuantities::rolling_radius_m,
    &tables::PatchQuantities::semi_axis_a_m,     &tables::PatchQuantities::semi_axis_b_m,
    &tables::PatchQuantities::s_min_m,           &tables::PatchQuantities::s_max_m};

static_assert(CTAB_S_MAX_M == kQuantities - 1);
static_assert(kMaxSlots == tables::kMaxSlots && kWheels == tables::kWheels);

// Moves or converts every array of `table` into `data`, releasing each source array once converted, so that the
// two together hold little more than one table.
LoadResult convert(tables::Table& table, TableData& data) {
  data = TableData{};
  if (table.second_axis_name == "vertical_load_N") data.second_axis = SecondAxis::VerticalLoad;
  else if (table.second_axis_name == "normal_load_N") data.second_axis = SecondAxis::NormalLoad;
  else if (table.second_axis_name == "approach_m") data.second_axis = SecondAxis::Approach;
  else return {CTAB_ERR_AXES, "unknown second axis '" + table.second_axis_name + "'"};
  data.dy_m = std::move(table.lateral_displacement_m);
  data.second = std::move(table.second_axis);
  data.n_slots = table.n_slots;
  data.strip_samples = table.strip_samples;
  data.roll_rad = std::move(table.roll_rad);
  data.rolling_radius_difference_m = std::move(table.rolling_radius_difference_m);
  data.case_status.reserve(table.status.size());
  for (const tables::CaseStatus s : table.status) data.case_status.push_back(static_cast<std::int8_t>(s));
  data.present = std::move(table.patch.present);
  const std::size_t patches = data.present.size();
  data.quantities.assign(patches * kQuantities, 0.0);
  for (std::size_t q = 0; q < kQuantities; ++q) {
    std::vector<double>& column = table.patch.*kColumns[q];
    if (column.size() != patches) return {CTAB_ERR_SHAPE, "a patch quantity's size differs from the presence flags"};
    for (std::size_t p = 0; p < patches; ++p) data.quantities[p * kQuantities + q] = column[p];
    std::vector<double>{}.swap(column);
  }
  data.strip_half_length_m = std::move(table.patch.strip_half_length_m);
  data.strip_peak_pressure_Pa = std::move(table.patch.strip_peak_pressure_Pa);
  data.jumps.reserve(table.jumps.size());
  for (const tables::Jump& j : table.jumps)
    data.jumps.push_back({j.i_second, j.i_dy, j.wheel, j.slot, static_cast<JumpKind>(j.kind)});
  return validate(data);
}

}  // namespace

LoadResult from_tables(const tables::Table& table, TableData& data) {
  return detail::guard_allocation([&] {
    tables::Table copy = table;
    return from_tables(std::move(copy), data);
  });
}

LoadResult from_tables(tables::Table&& table, TableData& data) {
  return detail::guard_allocation([&] { return convert(table, data); });
}

}  // namespace ctab::lookup
