// SPDX-License-Identifier: Apache-2.0
// Content validation of a table read from a file (every check names the dataset and the first bad index).
#include "table_validation.hpp"

#include <cmath>
#include <cstdio>

#include "schema_fields.hpp"

namespace ctab::tables::detail {

namespace {

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

TableResult invalid(const std::string& path, const Field& field, const std::vector<hsize_t>& shape, std::size_t flat,
                    const std::string& what) {
  return {TableStatus::InvalidContent,
          path + ": " + field.path + "[" + index_text(field.extent, shape, flat) + "]: " + what};
}

TableResult check_axes(const Table& t, const std::string& path) {
  const auto& dy = t.lateral_displacement_m;
  const std::string axis = path + ": /axes/lateral_displacement_m";
  for (std::size_t i = 1; i < dy.size(); ++i)
    if (!(dy[i] > dy[i - 1]))
      return {TableStatus::InvalidContent, axis + "[" + std::to_string(i) + "]: the axis must be strictly increasing"};
  for (std::size_t i = 1; i < dy.size(); ++i)
    if (!dy_step_allowed(dy[i] - dy[i - 1]))
      return {TableStatus::InvalidContent, axis + "[" + std::to_string(i) + "]: a step finer than " +
                                               "1e-7 m (tables::kMinDyStep)"};
  for (std::size_t i = 0; i < t.second_axis.size(); ++i)
    if (!(t.second_axis[i] > 0.0) || (i > 0 && !(t.second_axis[i] > t.second_axis[i - 1])))
      return {TableStatus::InvalidContent,
              path + ": /axes/second[" + std::to_string(i) + "]: values must be positive and strictly increasing"};
  return {};
}

// The slot (flat index of the per-slot arrays) that an element of a patch dataset belongs to.
std::size_t slot_of(const Field& f, const Table& t, std::size_t flat) {
  return f.extent == Extent::PerSample ? flat / t.strip_samples : flat;
}

TableResult check_field(const Field& f, const Table& t, const std::string& path) {
  const std::vector<hsize_t> shape = shape_of(f.extent, t.n_dy(), t.n_second(), t.n_slots, t.strip_samples);
  const auto& present = t.patch.present;
  if (f.element == Element::Status) {
    for (std::size_t i = 0; i < f.size(); ++i)
      if (!is_case_status(static_cast<int>((*f.statuses)[i])))
        return invalid(path, f, shape, i, "unknown case status " + std::to_string(static_cast<int>((*f.statuses)[i])));
    return {};
  }
  if (f.element == Element::Int8) {  // /wheels/method: a ContactMethod value or kMethodNotRecorded
    for (std::size_t i = 0; i < f.size(); ++i)
      if ((*f.int8s)[i] < kMethodNotRecorded || (*f.int8s)[i] > kMaxMethodValue)
        return invalid(path, f, shape, i, "method " + std::to_string((*f.int8s)[i]) + " (must be -1 to 4)");
    return {};
  }
  if (f.element == Element::Presence) {
    for (std::size_t i = 0; i < f.size(); ++i)
      if ((*f.bytes)[i] > 1)
        return invalid(path, f, shape, i, "presence " + std::to_string((*f.bytes)[i]) + " (must be 0 or 1)");
    return {};
  }
  const std::vector<double>& v = *f.doubles;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) return invalid(path, f, shape, i, number_text(v[i]) + " (must be finite)");
    if (f.extent == Extent::PerCell && !(v[i] >= 0.0 || v[i] == kCellNotMeasured))
      return invalid(path, f, shape, i, number_text(v[i]) + " (must be >= 0, or -1: not measured)");
    if (!f.patch) continue;
    const bool here = present[slot_of(f, t, i)] != 0;
    if (!here && v[i] != 0.0) return invalid(path, f, shape, i, number_text(v[i]) + " in an empty slot (must be 0)");
    if (here && f.sign == 2 && !(v[i] > 0.0)) return invalid(path, f, shape, i, number_text(v[i]) + " (must be > 0)");
    if (here && f.sign == 1 && !(v[i] >= 0.0)) return invalid(path, f, shape, i, number_text(v[i]) + " (must be >= 0)");
  }
  return {};
}

// A failed case (status < 0) holds no patch.
TableResult check_failed_cases(const Table& t, const std::string& path) {
  for (std::size_t w = 0; w < t.status.size(); ++w) {
    if (is_success(t.status[w])) continue;
    for (std::size_t slot = 0; slot < t.n_slots; ++slot)
      if (t.patch.present[w * t.n_slots + slot] != 0)
        return {TableStatus::InvalidContent,
                path + ": /patches/present[" +
                    index_text(Extent::PerSlot, shape_of(Extent::PerSlot, t.n_dy(), t.n_second(), t.n_slots, 1),
                               w * t.n_slots + slot) +
                    "]: a patch in a failed case (" + case_status_name(t.status[w]) + ")"};
  }
  return {};
}

TableResult check_jumps(const Table& t, const std::string& path) {
  for (std::size_t i = 0; i < t.jumps.size(); ++i) {
    const Jump& j = t.jumps[i];
    const int kind = static_cast<int>(j.kind);
    if (!index_in_range(j.i_second, t.n_second()) || !index_in_range(j.wheel, kWheels) ||
        !index_in_range(j.slot, t.n_slots) || !cell_in_range(j.i_dy, t.n_dy()) ||
        kind < static_cast<int>(JumpKind::Appears) || kind > static_cast<int>(JumpKind::Moves))
      return {TableStatus::InvalidContent, path + ": /jumps[" + std::to_string(i) + "]: index or kind out of range"};
  }
  return {};
}

}  // namespace

TableResult validate_contents(Table& table, const std::string& path) {
  if (TableResult r = check_axes(table, path); !r.ok()) return r;
  for (const Field& f : schema_fields(table))
    if (TableResult r = check_field(f, table, path); !r.ok()) return r;
  if (TableResult r = check_failed_cases(table, path); !r.ok()) return r;
  return check_jumps(table, path);
}

}  // namespace ctab::tables::detail
