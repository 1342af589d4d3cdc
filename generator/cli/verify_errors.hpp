// SPDX-License-Identifier: Apache-2.0
#pragma once
//! `ctab verify`'s measures (docs/cli.md "verify"): one lookup result against the direct solve of the same point,
//! and their distribution over a class of points.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "ctab/lookup/ctab_lookup.h"
#include "ctab/tables/table.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::cli {

//! The quantities compared: patch normal force and area (relative to the direct solve's patch), contact point on
//! the rail (absolute [m]) and the wheel's total lateral force (over its wheel load, the direct solve's summed
//! vertical force).
enum class Quantity { Force, Area, ContactPoint, Lateral };
inline constexpr std::size_t kQuantities = 4;
[[nodiscard]] const char* quantity_name(Quantity q) noexcept;

//! A table's tolerance per quantity: its root attributes tolerance_force_rel, tolerance_area_rel,
//! tolerance_contact_point_m and tolerance_lateral_force_rel, or where absent 0.005, 0.005, 1e-5 m and 0.005.
[[nodiscard]] std::array<double, kQuantities> table_tolerances(const tables::Table& table);

//! Errors of one point per quantity; NaN where the quantity has nothing to compare (no patch in common, no load).
//! Patches are matched by slot: each direct patch takes the present lookup slot nearest by rail contact point,
//! nearest pairs first; a patch left without a partner on either side is a force and area error of 1 (100 %).
struct PointErrors {
  std::array<double, kQuantities> error{};
  std::size_t unmatched = 0;  //!< patches without a partner
};
[[nodiscard]] PointErrors compare_point(const ctab_result& lookup, const gen::WheelContact& direct);

//! Distribution of one quantity over a class: count, median, 95th percentile, max and the point of the max.
struct ErrorStats {
  std::size_t count = 0;
  double median = 0.0, p95 = 0.0, max = 0.0;
  std::size_t worst = 0;  //!< index of the point with the max (into the caller's points)
};
//! `errors[k]` belongs to point `points[k]`; NaN errors are not counted. Percentiles: nearest rank.
[[nodiscard]] ErrorStats error_stats(const std::vector<double>& errors, const std::vector<std::size_t>& points);

}  // namespace ctab::cli
