// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Limits and index checks shared by every reader and writer of contact tables: the HDF5 reader and writer
//! (ctab::tables), the generator's size estimate of a config, and the lookup core's blob loader. Header-only and
//! free of HDF5, so that the lookup core may include it without depending on ctab::tables (tables/README.md,
//! "Limits").
#include <cstddef>
#include <cstdint>

namespace ctab::tables {

//! Largest table, as the bytes of its arrays in memory (table_bytes). Chosen: 2 GiB, a fixed figure (not a fraction
//! of a machine's memory) so that a table is valid or not everywhere; the default table takes about 1 MB. Loading
//! a table for lookup holds about this much once more at its peak (tables/README.md, "Limits").
inline constexpr double kMaxTableBytes = 2.0 * 1024.0 * 1024.0 * 1024.0;
//! Most values per axis (the lookup's cell indices are 32-bit).
inline constexpr std::uint64_t kMaxAxisLength = std::uint64_t{1} << 20;
//! Values stored per patch besides its strip profiles: 18 quantities, presence and the per-wheel values' share.
inline constexpr double kValuesPerPatch = 20.0;
//! Smallest step of the dy axis [m]: a located jump's cell may be this narrow (the generator brackets a jump to
//! 1 um or better). The axis is otherwise free (adaptive: steps from this to millimetres in one axis); the lookup's
//! prelookup stays bounded-time on any such axis (lookup/README.md, "Prelookup").
inline constexpr double kMinDyStep = 1e-7;
//! True when `step` (the difference of two neighbouring dy values) is at least kMinDyStep, to a relative 1e-9 so
//! that a 0.1 um cell whose ends were rounded to doubles still counts.
constexpr bool dy_step_allowed(double step) noexcept { return step >= kMinDyStep * (1.0 - 1e-9); }
//! Wheels per case (right, left).
inline constexpr double kTableWheelCount = 2.0;

//! The bytes of a table's arrays in memory: per patch kValuesPerPatch values and two strip profiles of
//! `strip_samples` values, 8 bytes each. In double so that absurd counts compare instead of overflowing.
constexpr double table_bytes(double n_dy, double n_second, double n_slots, double strip_samples) noexcept {
  return n_dy * n_second * kTableWheelCount * n_slots * (kValuesPerPatch + 2.0 * strip_samples) * 8.0;
}

//! True when `i` indexes an array of `n` values.
constexpr bool index_in_range(std::uint64_t i, std::uint64_t n) noexcept { return i < n; }

//! True when the cell (i, i + 1) lies on an axis of `n` nodes: i + 1 < n without computing i + 1 (a 32-bit
//! i = 0xFFFFFFFF would wrap to 0).
constexpr bool cell_in_range(std::uint64_t i, std::uint64_t n) noexcept { return n >= 2 && i < n - 1; }

}  // namespace ctab::tables
