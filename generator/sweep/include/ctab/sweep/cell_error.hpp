// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The interpolation error of one dy cell, as the adaptive axis measures it (docs/method.md "Error-controlled
//! axes") and as tests re-measure it at points the generator never used: one wheel of a case reduced to the
//! quantities the tolerance bounds, and the error of the linear interpolant of two such samples at a third.
#include <array>
#include <cstddef>
#include <vector>

#include "ctab/sweep/table_config.hpp"
#include "ctab/tables/table.hpp"

namespace ctab::gen {

//! A patch below this share of the wheel's normal force (or area) has its relative error taken against the share
//! instead of its own value: a patch appearing with zero force has no relative error to bound. Chosen: 5 %.
inline constexpr double kSmallPatchShare = 0.05;

//! One patch of a wheel sample. Patches are matched between samples by their order in y_rail (two contacts cannot
//! pass each other without merging), not by slot: the zone rule would swap slots when a root contact crosses the
//! tread-flange boundary.
struct PatchSample {
  double force_N = 0.0, area_m2 = 0.0, y_rail_m = 0.0, y_wheel_m = 0.0;
};
//! One wheel of one case: success, totals over its patches, and the patches.
struct WheelSample {
  bool success = false;
  double force_N = 0.0;    //!< sum of the patches' normal forces (the wheel load the relative errors refer to)
  double area_m2 = 0.0;    //!< sum of the patches' areas
  double lateral_N = 0.0;  //!< total lateral force
  std::vector<PatchSample> patches;  //!< present patches in increasing y_rail_m
};
//! The sample of (i_dy, i_second, wheel) of a table.
[[nodiscard]] WheelSample wheel_sample(const tables::Table& table, std::size_t i_dy, std::size_t i_second,
                                       std::size_t wheel);

//! Errors in tables::CellErrorQuantity order.
using CellErrors = std::array<double, tables::kCellErrorQuantities>;

//! True when the number of patches differs between two samples (or the case fails at one only), or a contact point
//! moves by more than tables::jump_move_threshold(tolerance.contact_point_m): a jump candidate, bracketed until its
//! cell is at most tables::kJumpCellWidth_m wide (a continuous motion stops being one long before that).
[[nodiscard]] bool discontinuous(const WheelSample& a, const WheelSample& b, const AxisTolerance& tolerance);

//! Error at `c` of the linear interpolant between `a` and `b`, c lying at fraction t of the way from a to b; the
//! three samples must not be discontinuous (the same number of patches).
[[nodiscard]] CellErrors interpolation_error(const WheelSample& a, const WheelSample& b, const WheelSample& c,
                                             double t);

//! The largest ratio of error to tolerance over the four quantities.
[[nodiscard]] double tolerance_ratio(const CellErrors& errors, const AxisTolerance& tolerance) noexcept;

}  // namespace ctab::gen
