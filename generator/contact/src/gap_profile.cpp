// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/gap_profile.hpp"

#include <cmath>
#include <string>

#include "ctab/core/error.hpp"

namespace ctab::gen {

void validate(const GapProfile& gap) {
  const std::size_t n = gap.y_m.size();
  if (gap.h_m.size() != n || gap.A_per_m.size() != n || gap.B_per_m.size() != n)
    throw InputError(gap.source, 0, "columns y_m, h_m, A_per_m, B_per_m must have equal lengths");
  if (n < 3) throw InputError(gap.source, 0, "need at least 3 rows of gap data, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::string row = "row " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(gap.y_m[i]) || !std::isfinite(gap.h_m[i]) || !std::isfinite(gap.A_per_m[i]) ||
        !std::isfinite(gap.B_per_m[i]))
      throw InputError(gap.source, i + 1, row + "non-finite value");
    if (!(gap.A_per_m[i] > 0.0))
      throw InputError(gap.source, i + 1, row + "A_per_m must be positive, got " + std::to_string(gap.A_per_m[i]));
    if (i > 0 && !(gap.y_m[i] > gap.y_m[i - 1]))
      throw InputError(gap.source, i + 1, row + "y_m must be strictly increasing");
  }
}

GapProfile sphere_on_flat_gap(double radius_m, double half_range_m, double step_m) {
  const double curvature = 1.0 / (2.0 * radius_m);
  return sample_gap(
      -half_range_m, half_range_m, step_m, [=](double y) { return curvature * y * y; },
      [=](double) { return curvature; }, [=](double) { return curvature; }, "sphere-on-flat");
}

GapProfile two_radius_gap(double rolling_radius_m, double radius_negative_m, double radius_positive_m, double y_min_m,
                          double y_max_m, double step_m) {
  auto lateral = [=](double y) { return 1.0 / (2.0 * (y < 0.0 ? radius_negative_m : radius_positive_m)); };
  return sample_gap(
      y_min_m, y_max_m, step_m, [=](double y) { return lateral(y) * y * y; },
      [=](double) { return 1.0 / (2.0 * rolling_radius_m); }, lateral, "two-radius body");
}

}  // namespace ctab::gen
