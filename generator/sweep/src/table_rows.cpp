// SPDX-License-Identifier: Apache-2.0
#include "ctab/sweep/table_rows.hpp"

#include <algorithm>
#include <cstring>

namespace ctab::gen {

namespace {

// One per-case dataset: its data and the bytes one row (n_second cases) of it takes.
struct RowArray {
  unsigned char* data;
  std::size_t row_bytes;
};

template <class T>
RowArray row_array(std::vector<T>& values, std::size_t per_row) {
  return {reinterpret_cast<unsigned char*>(values.data()), per_row * sizeof(T)};
}

// One per-slot dataset: its data and the bytes one slot of one wheel-case takes.
struct SlotArray {
  unsigned char* data;
  std::size_t slot_bytes;
};

template <class T>
SlotArray slot_array(std::vector<T>& values, std::size_t per_slot) {
  return {reinterpret_cast<unsigned char*>(values.data()), per_slot * sizeof(T)};
}

// Every per-slot dataset of the schema (tables/table.hpp). The merge tests compare merged tables with single runs
// byte for byte, so a dataset missing here fails them.
std::vector<SlotArray> slot_arrays(tables::Table& t) {
  auto& p = t.patch;
  std::vector<SlotArray> arrays = {slot_array(p.present, 1), slot_array(p.strip_half_length_m, t.strip_samples),
                                   slot_array(p.strip_peak_pressure_Pa, t.strip_samples)};
  for (std::vector<double>* slot_values :
       {&p.normal_force_N, &p.force_lateral_N, &p.force_vertical_N, &p.area_m2, &p.max_pressure_Pa, &p.approach_m,
        &p.contact_angle_rad, &p.plane_angle_rad, &p.s_origin_y_rail_m, &p.s_origin_z_rail_m, &p.y_wheel_m, &p.y_rail_m,
        &p.y_cop_rail_m, &p.rolling_radius_m, &p.semi_axis_a_m, &p.semi_axis_b_m, &p.s_min_m, &p.s_max_m})
    arrays.push_back(slot_array(*slot_values, 1));
  return arrays;
}

// Every per-case dataset of the schema, with the bytes one row holds.
std::vector<RowArray> row_arrays(tables::Table& t) {
  const std::size_t cases = t.n_second(), wheels = cases * tables::kWheels, slots = wheels * t.n_slots;
  std::vector<RowArray> arrays = {row_array(t.roll_rad, cases), row_array(t.rolling_radius_difference_m, cases),
                                  row_array(t.status, wheels), row_array(t.method, wheels),
                                  row_array(t.strip_width_m, wheels)};
  for (const SlotArray& a : slot_arrays(t)) arrays.push_back({a.data, a.slot_bytes * slots});
  return arrays;
}

// Read-only use of row_arrays: the pointers are only read through.
std::vector<RowArray> row_arrays(const tables::Table& t) { return row_arrays(const_cast<tables::Table&>(t)); }

}  // namespace

std::size_t row_bytes(const tables::Table& table) noexcept {
  std::size_t bytes = 0;
  for (const RowArray& a : row_arrays(table)) bytes += a.row_bytes;
  return bytes;
}

void copy_rows(const tables::Table& from, tables::Table& to, const std::vector<std::size_t>& rows) {
  const std::vector<RowArray> source = row_arrays(from), target = row_arrays(to);
  for (std::size_t a = 0; a < source.size(); ++a)
    for (const std::size_t row : rows)
      std::memcpy(target[a].data + row * target[a].row_bytes, source[a].data + row * source[a].row_bytes,
                  source[a].row_bytes);
}

std::vector<unsigned char> pack_rows(const tables::Table& table, const std::vector<std::size_t>& rows) {
  std::vector<unsigned char> buffer;
  buffer.reserve(rows.size() * row_bytes(table));
  for (const RowArray& a : row_arrays(table))
    for (const std::size_t row : rows)
      buffer.insert(buffer.end(), a.data + row * a.row_bytes, a.data + (row + 1) * a.row_bytes);
  return buffer;
}

bool unpack_rows(tables::Table& table, const std::vector<std::size_t>& rows, const std::vector<unsigned char>& buffer) {
  if (buffer.size() != rows.size() * row_bytes(table)) return false;
  const unsigned char* at = buffer.data();
  for (const RowArray& a : row_arrays(table))
    for (const std::size_t row : rows) {
      std::memcpy(a.data + row * a.row_bytes, at, a.row_bytes);
      at += a.row_bytes;
    }
  return true;
}

void fail_rows(tables::Table& table, const std::vector<std::size_t>& rows, tables::CaseStatus status) {
  for (const RowArray& a : row_arrays(table))
    for (const std::size_t row : rows) std::memset(a.data + row * a.row_bytes, 0, a.row_bytes);
  for (const std::size_t row : rows)
    for (std::size_t i_second = 0; i_second < table.n_second(); ++i_second)
      for (std::size_t wheel = 0; wheel < tables::kWheels; ++wheel)
        table.status[table.wheel_index(row, i_second, wheel)] = status;
}

void permute_slots(tables::Table& table, std::size_t wheel_index, const std::vector<std::size_t>& new_slot) {
  std::vector<unsigned char> old;
  for (const SlotArray& a : slot_arrays(table)) {
    unsigned char* const wheel_case = a.data + wheel_index * table.n_slots * a.slot_bytes;
    old.assign(wheel_case, wheel_case + table.n_slots * a.slot_bytes);
    for (std::size_t slot = 0; slot < table.n_slots; ++slot)
      std::memcpy(wheel_case + new_slot[slot] * a.slot_bytes, old.data() + slot * a.slot_bytes, a.slot_bytes);
  }
}

}  // namespace ctab::gen
