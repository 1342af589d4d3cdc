// SPDX-License-Identifier: Apache-2.0
#pragma once
// Size checks of a profile read from a file that sets its own length unit (Simpack units.len.f): a unit factor
// off by 2 (or 10) gives a profile that still looks fine to every other check. Bounds, with their reasons:
// - wheel width (y extent) 100 to 160 mm: S1002 spans 130 mm (flange back to field-side end), rims are 135 mm
//   wide (EN 13715), so half or twice a real wheel (65 / 260 mm) falls outside;
// - wheel flange height (flange tip above the tape circle at y = 0) 20 to 40 mm: S1002 new 28 mm, the wear limit
//   is 36 mm (EN 15313: 27.5 to 36 mm);
// - rail width (y extent) 50 to 120 mm: 60E1 head 72 mm, 49E1 67 mm, 54E1 70 mm, 136RE 75 mm; grooved rails
//   with their groove and check up to about 115 mm; half or twice 60E1 (36 / 144 mm) falls outside;
// - rail height (depth of the deepest point below the top) 5 to 60 mm: 60E1's head is 51 mm deep, and below the
//   head z(y) is no longer single valued; under 5 mm there is no head to speak of.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "ctab/io/profile_io.hpp"

namespace ctab::gen::detail {

struct SizeBound {
  const char* what;
  double min_mm, max_mm;
};

inline constexpr SizeBound kWheelWidth{"wheel profile width", 100.0, 160.0};
inline constexpr SizeBound kWheelFlangeHeight{"wheel flange height (flange tip above the tape circle y = 0)", 20.0,
                                              40.0};
inline constexpr SizeBound kRailWidth{"rail profile width", 50.0, 120.0};
inline constexpr SizeBound kRailHeight{"rail profile height (deepest point below the top)", 5.0, 60.0};

inline std::optional<std::string> outside(const SizeBound& bound, double value_mm, const char* advice) {
  if (value_mm >= bound.min_mm && value_mm <= bound.max_mm) return std::nullopt;
  char text[256];
  std::snprintf(text, sizeof text, "%s %.1f mm is outside %g to %g mm: %s", bound.what, value_mm, bound.min_mm,
                bound.max_mm, advice);
  return std::string(text);
}

//! A message when the canonical profile (y increasing, z down, SI) cannot be a wheel or rail of that size.
inline std::optional<std::string> implausible_size(const std::vector<double>& y, const std::vector<double>& z,
                                                   ProfileRole role) {
  constexpr const char* kScale = "check units.len.f (scale)";
  const double width_mm = (y.back() - y.front()) * 1e3;
  const auto [z_min, z_max] = std::minmax_element(z.begin(), z.end());
  if (role == ProfileRole::Rail) {
    if (auto m = outside(kRailWidth, width_mm, kScale)) return m;
    return outside(kRailHeight, (*z_max - *z_min) * 1e3, kScale);
  }
  if (auto m = outside(kWheelWidth, width_mm, kScale)) return m;
  if (!(y.front() <= 0.0 && y.back() >= 0.0)) {
    char text[200];
    std::snprintf(
        text, sizeof text,
        "wheel profile spans y = %.1f to %.1f mm, without the tape circle y = 0: check shift.y and units.len.f",
        y.front() * 1e3, y.back() * 1e3);
    return std::string(text);
  }
  const auto k = static_cast<std::size_t>(std::upper_bound(y.begin(), y.end(), 0.0) - y.begin());
  const std::size_t hi = std::min(std::max<std::size_t>(k, 1), y.size() - 1);
  const double s = (0.0 - y[hi - 1]) / (y[hi] - y[hi - 1]);
  const double tape_z = z[hi - 1] + s * (z[hi] - z[hi - 1]);
  return outside(kWheelFlangeHeight, (*z_max - tape_z) * 1e3, "check units.len.f (scale) and shift.y");
}

}  // namespace ctab::gen::detail
