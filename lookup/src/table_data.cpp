// SPDX-License-Identifier: Apache-2.0
// TableData: sizing and validation (axes, shapes, finite values, statuses, presence, jumps).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ctab/lookup/table_data.hpp"
#include "ctab/tables/limits.hpp"

namespace ctab::lookup {

namespace {

constexpr int kCaseStatusMin = -6;  // tables::kCaseStatusMin
constexpr int kCaseStatusMax = 2;   // tables::kCaseStatusMax

LoadResult fail(ctab_status status, const std::string& what) { return {status, what}; }

bool all_finite(const std::vector<double>& values) noexcept {
  for (const double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

bool all_within(const std::vector<double>& values, double bound) noexcept {
  for (const double v : values)
    if (!(std::fabs(v) <= bound)) return false;
  return true;
}

// A step of an axis: positive, finite, and with a finite inverse (a subnormal step has none), so that a cell's
// fraction is a finite number.
bool usable_step(double step) noexcept { return step > 0.0 && std::isfinite(step) && std::isfinite(1.0 / step); }

LoadResult check_axes(const TableData& data) {
  const std::size_t n_dy = data.n_dy(), n_2 = data.n_second();
  if (n_dy < 2)
    return fail(CTAB_ERR_AXES, "the dy axis has " + std::to_string(n_dy) +
                                   " value(s): a lookup table needs at least 2 (a cell to interpolate in)");
  if (n_2 < 1) return fail(CTAB_ERR_AXES, "the second axis has no value");
  if (!all_finite(data.dy_m) || !all_finite(data.second)) return fail(CTAB_ERR_AXES, "an axis value is not finite");
  double smallest_step = data.dy_m[1] - data.dy_m[0];
  for (std::size_t i = 1; i < n_dy; ++i) {
    if (!(data.dy_m[i] > data.dy_m[i - 1]))
      return fail(CTAB_ERR_AXES, "the dy axis is not strictly increasing at index " + std::to_string(i));
    smallest_step = std::min(smallest_step, data.dy_m[i] - data.dy_m[i - 1]);
  }
  const double span = data.dy_m.back() - data.dy_m.front();
  if (!usable_step(smallest_step) || !usable_step(span))
    return fail(CTAB_ERR_AXES, "the dy axis's steps or span are too small or too large to divide by");
  if (!tables::dy_step_allowed(smallest_step))
    return fail(CTAB_ERR_AXES, "the dy axis has a step finer than 1e-7 m (the smallest a located jump's cell may be)");
  for (std::size_t i = 1; i < n_2; ++i) {
    if (!(data.second[i] > data.second[i - 1]))
      return fail(CTAB_ERR_AXES, "the second axis is not strictly increasing at index " + std::to_string(i));
    if (!usable_step(data.second[i] - data.second[i - 1]))
      return fail(CTAB_ERR_AXES, "the second axis's step at index " + std::to_string(i) +
                                     " is too small or too large to divide by");
  }
  if (static_cast<std::uint32_t>(data.second_axis) > 2) return fail(CTAB_ERR_AXES, "unknown second-axis quantity");
  return {};
}

}  // namespace

const char* second_axis_name(SecondAxis axis) noexcept {
  switch (axis) {
    case SecondAxis::VerticalLoad: return "vertical_load_N";
    case SecondAxis::NormalLoad: return "normal_load_N";
    case SecondAxis::Approach: return "approach_m";
  }
  return "unknown";
}

void TableData::allocate() {
  const std::size_t cases = n_dy() * n_second();
  const std::size_t patches = cases * kWheels * n_slots;
  roll_rad.assign(cases, 0.0);
  rolling_radius_difference_m.assign(cases, 0.0);
  case_status.assign(cases * kWheels, 0);
  present.assign(patches, 0);
  quantities.assign(patches * kQuantities, 0.0);
  strip_half_length_m.assign(patches * strip_samples, 0.0);
  strip_peak_pressure_Pa.assign(patches * strip_samples, 0.0);
}

LoadResult validate(const TableData& data) {
  if (LoadResult r = check_axes(data); !r.ok()) return r;
  const std::size_t n_dy = data.n_dy();
  const std::size_t n_2 = data.n_second();
  if (data.n_slots < 1 || data.n_slots > kMaxSlots) return fail(CTAB_ERR_SHAPE, "slots must be 1..16");
  if (data.strip_samples == 1 || data.strip_samples > kMaxStripSamples)
    return fail(CTAB_ERR_SHAPE, "strip samples must be 0 or 2..4096");

  const std::size_t cases = n_dy * n_2;
  const std::size_t patches = cases * kWheels * data.n_slots;
  const auto sized = [](const auto& v, std::size_t n) { return v.size() == n; };
  if (!sized(data.roll_rad, cases) || !sized(data.rolling_radius_difference_m, cases) ||
      !sized(data.case_status, cases * kWheels) || !sized(data.present, patches) ||
      !sized(data.quantities, patches * kQuantities) ||
      !sized(data.strip_half_length_m, patches * data.strip_samples) ||
      !sized(data.strip_peak_pressure_Pa, patches * data.strip_samples))
    return fail(CTAB_ERR_SHAPE, "an array's size does not match the axes, slots and strip samples");

  if (!all_finite(data.roll_rad) || !all_finite(data.rolling_radius_difference_m) || !all_finite(data.quantities) ||
      !all_finite(data.strip_half_length_m) || !all_finite(data.strip_peak_pressure_Pa))
    return fail(CTAB_ERR_CONTENT, "a tabulated value is not finite");
  for (const auto* values : {&data.roll_rad, &data.rolling_radius_difference_m, &data.quantities,
                             &data.strip_half_length_m, &data.strip_peak_pressure_Pa})
    if (!all_within(*values, kMaxTableValue))
      return fail(CTAB_ERR_CONTENT, "a tabulated value lies beyond +-1e300: interpolating it could overflow");
  for (const std::int8_t s : data.case_status)
    if (s < kCaseStatusMin || s > kCaseStatusMax)
      return fail(CTAB_ERR_CONTENT, "unknown case status " + std::to_string(s));
  for (const std::uint8_t p : data.present)
    if (p > 1) return fail(CTAB_ERR_CONTENT, "a presence flag is neither 0 nor 1");
  for (const Jump& j : data.jumps)
    if (!tables::index_in_range(j.i_second, n_2) || !tables::cell_in_range(j.i_dy, n_dy) ||
        !tables::index_in_range(j.wheel, kWheels) || !tables::index_in_range(j.slot, data.n_slots) ||
        static_cast<int>(j.kind) < 1 || static_cast<int>(j.kind) > 3)
      return fail(CTAB_ERR_CONTENT, "a jump lies outside the table");
  return {};
}

LoadResult check_float_range(const TableData& data) {
  constexpr double kFloatMax = static_cast<double>(std::numeric_limits<float>::max());
  const std::pair<const char*, const std::vector<double>*> fields[] = {
      {"a patch quantity", &data.quantities},
      {"the strip half-length a(s)", &data.strip_half_length_m},
      {"the strip peak pressure p0(s)", &data.strip_peak_pressure_Pa},
      {"the roll", &data.roll_rad},
      {"the rolling radius difference", &data.rolling_radius_difference_m}};
  for (const auto& [name, values] : fields)
    if (!all_within(*values, kFloatMax))
      return fail(CTAB_ERR_CONTENT, std::string(name) + " lies beyond the float range (+-3.4e38): single precision "
                                                        "cannot store this table");
  return {};
}

}  // namespace ctab::lookup
