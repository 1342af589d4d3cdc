// SPDX-License-Identifier: Apache-2.0
#pragma once
//! `ctab verify`'s sample points (docs/cli.md "verify"): the table's cells sorted into classes from the stored
//! nodes alone, and random off-grid points drawn from every class.
//!
//! A cell is one wheel between two neighbouring dy nodes (and, on a table with a second axis, between two
//! neighbouring second-axis values); cells with a failed node, or at most kLocatedJumpWidth_m wide (a located
//! jump), are not sampled. Classes, the first that applies:
//! - jump: a jump the table lists in the cell, or the slots present differ between its nodes; beside a located
//!   jump the neighbouring cells, without kLocatedJumpWidth_m next to it;
//! - two-patch: at least two patches at every node;
//! - knee: the top decile of the remaining (one-patch) cells by the fastest change of the normal force along dy
//!   (|dF/ddy| over the wheel's normal force);
//! - flange: a patch steeper than kFlangeAngle_rad at a node;
//! - tread: the rest that has contact.
//! On a table with a second axis every point takes a random second-axis value, and the class `load` takes points
//! at the dy nodes themselves, so that it measures the interpolation along the second axis alone.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ctab/tables/table.hpp"

namespace ctab::cli {

enum class CellClass { Tread, TwoPatch, Flange, Knee, Jump, Load };
inline constexpr std::size_t kCellClasses = 6;
[[nodiscard]] const char* cell_class_name(CellClass c) noexcept;

//! Located jumps are cells at most this wide; points within it of one are not drawn [m].
inline constexpr double kLocatedJumpWidth_m = 1e-6;
//! A patch whose contact angle is steeper than this makes a flange cell [rad] (30 deg).
inline constexpr double kFlangeAngle_rad = 0.5235987755982988;
//! Share of the cells (by the fastest force change) that are knee cells [-].
inline constexpr double kKneeShare = 0.1;
//! A knee cell's force changes faster than this share of the wheel's force per metre of dy (rounding noise of a
//! constant force does not make a knee) [1/m].
inline constexpr double kKneeMinGradient_per_m = 1e-3;

//! Where a class draws its points: one wheel, dy in [dy_low, dy_high], the second axis in [second_low,
//! second_high] (equal on a table with one value).
struct SampleCell {
  std::size_t wheel = 0;
  double dy_low_m = 0.0, dy_high_m = 0.0, second_low = 0.0, second_high = 0.0;
};

using CellClasses = std::array<std::vector<SampleCell>, kCellClasses>;

//! The table's cells sorted into classes (see above).
[[nodiscard]] CellClasses classify_cells(const tables::Table& table);

//! One point to check.
struct SamplePoint {
  CellClass cell_class = CellClass::Tread;
  std::size_t index = 0;  //!< position in the draw (with the seed, what reproduces it)
  std::size_t wheel = 0;
  double dy_m = 0.0, second = 0.0;
};

//! `samples` points shared evenly between the non-empty classes (the first classes take the remainder), each in a
//! cell of its class drawn at random, dy and second uniform inside it (never on a node, except the load class's
//! dy). Deterministic for a seed (its own generator, not the standard library's distributions).
[[nodiscard]] std::vector<SamplePoint> draw_samples(const CellClasses& classes, std::size_t samples,
                                                    std::uint64_t seed);

}  // namespace ctab::cli
