// SPDX-License-Identifier: Apache-2.0
// Interpolation error of a dy cell (cell_error.hpp).
#include "ctab/sweep/cell_error.hpp"

#include <algorithm>
#include <cmath>

namespace ctab::gen {

WheelSample wheel_sample(const tables::Table& table, std::size_t i_dy, std::size_t i_second, std::size_t wheel) {
  WheelSample sample;
  sample.success = tables::is_success(table.status[table.wheel_index(i_dy, i_second, wheel)]);
  const tables::PatchQuantities& p = table.patch;
  for (std::size_t slot = 0; slot < table.n_slots; ++slot) {
    const std::size_t i = table.patch_index(i_dy, i_second, wheel, slot);
    if (p.present[i] == 0) continue;
    sample.patches.push_back({p.normal_force_N[i], p.area_m2[i], p.y_rail_m[i], p.y_wheel_m[i]});
    sample.force_N += p.normal_force_N[i];
    sample.area_m2 += p.area_m2[i];
    sample.lateral_N += p.force_lateral_N[i];
  }
  std::sort(sample.patches.begin(), sample.patches.end(),
            [](const PatchSample& x, const PatchSample& y) { return x.y_rail_m < y.y_rail_m; });
  return sample;
}

bool discontinuous(const WheelSample& a, const WheelSample& b, const AxisTolerance& tolerance) {
  if (a.success != b.success || a.patches.size() != b.patches.size()) return true;
  const double move_m = tables::jump_move_threshold(tolerance.contact_point_m);
  for (std::size_t s = 0; s < a.patches.size(); ++s) {
    const PatchSample &x = a.patches[s], &y = b.patches[s];
    if (std::abs(x.y_rail_m - y.y_rail_m) > move_m || std::abs(x.y_wheel_m - y.y_wheel_m) > move_m) return true;
  }
  return false;
}

namespace {

double lerp(double a, double b, double t) noexcept { return a + t * (b - a); }

// |value - interpolated| relative to max(|value|, floor).
double relative(double value, double interpolated, double floor) noexcept {
  const double scale = std::max(std::abs(value), floor);
  return scale > 0.0 ? std::abs(value - interpolated) / scale : 0.0;
}

}  // namespace

CellErrors interpolation_error(const WheelSample& a, const WheelSample& b, const WheelSample& c, double t) {
  CellErrors e{0.0, 0.0, 0.0, 0.0};
  if (!(c.force_N > 0.0)) return e;  // no contact (or a failed case) at all three: nothing to interpolate
  for (std::size_t s = 0; s < c.patches.size() && s < a.patches.size() && s < b.patches.size(); ++s) {
    const PatchSample &x = a.patches[s], &y = b.patches[s], &z = c.patches[s];
    e[0] = std::max(e[0], relative(z.force_N, lerp(x.force_N, y.force_N, t), kSmallPatchShare * c.force_N));
    e[1] = std::max(e[1], relative(z.area_m2, lerp(x.area_m2, y.area_m2, t), kSmallPatchShare * c.area_m2));
    e[2] = std::max({e[2], std::abs(z.y_rail_m - lerp(x.y_rail_m, y.y_rail_m, t)),
                     std::abs(z.y_wheel_m - lerp(x.y_wheel_m, y.y_wheel_m, t))});
  }
  e[3] = std::abs(c.lateral_N - lerp(a.lateral_N, b.lateral_N, t)) / c.force_N;
  return e;
}

double tolerance_ratio(const CellErrors& e, const AxisTolerance& tolerance) noexcept {
  return std::max({e[0] / tolerance.force_rel, e[1] / tolerance.area_rel, e[2] / tolerance.contact_point_m,
                   e[3] / tolerance.lateral_force_rel});
}

}  // namespace ctab::gen
