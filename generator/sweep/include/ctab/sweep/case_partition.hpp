// SPDX-License-Identifier: Apache-2.0
#pragma once
//! How a table sweep is split into parts: work units of lateral-shift rows (MPI hands them out one at a time),
//! shards (`ctab generate --shard K/N`: a contiguous run of units each) and the row sets written as text in shard
//! files. The partition depends only on the axis length and on whether the sweep is mirrored, never on threads,
//! ranks or timing, so every part of every run of a config holds the same rows.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ctab::gen {

//! Lateral-shift rows per work unit. Chosen: 8 rows of the default table are 8 to 16 wheel solves (about 10 ms on
//! one core), far above the cost of handing a unit out and gathering it (tens of microseconds), and the default
//! table still makes 16 units for load balancing.
inline constexpr std::size_t kRowsPerUnit = 8;
//! Long sweeps take longer units, up to kMaxRowsPerUnit rows, while they keep kTargetUnits units: every unit's warm
//! chain starts cold, and a cold start costs a few MIM-1D iterations more than a warm one. 48 units keep a
//! 2401-row table's 10 loads at 960 tasks for the threads and 49 units for MPI ranks; 32 rows take most of the
//! gain (a cold start in 32 solves instead of 8).
inline constexpr std::size_t kTargetUnits = 48;
inline constexpr std::size_t kMaxRowsPerUnit = 32;

//! Rows per work unit of a sweep over `n_dy` rows (mirrored: counted on the half axis): kRowsPerUnit, or
//! ceil(rows / kTargetUnits) up to kMaxRowsPerUnit for long sweeps. Depends on the axis alone.
[[nodiscard]] std::size_t rows_per_unit(std::size_t n_dy, bool mirrored);

//! The work units of a sweep over `n_dy` rows: contiguous blocks of rows_per_unit(n_dy, mirrored) rows from row 0.
[[nodiscard]] std::vector<std::vector<std::size_t>> sweep_units(std::size_t n_dy, bool mirrored);

//! The work units of a sweep over `n_dy` rows: contiguous blocks of `rows_per_unit` rows from row 0. For a
//! mirrored sweep (row i and n_dy - 1 - i are solved together) the blocks are over the half axis 0..ceil(n_dy/2)
//! and each unit also holds the mirror rows, so every unit is mirror-closed. Every row is in exactly one unit;
//! each unit is sorted. rows_per_unit 0 is taken as 1.
[[nodiscard]] std::vector<std::vector<std::size_t>> sweep_units(std::size_t n_dy, bool mirrored,
                                                                std::size_t rows_per_unit);

//! The rows of shard `index` of `count` (1 <= index <= count): the units [floor((index-1) U / count),
//! floor(index U / count)) of U units, sorted. A shard may be empty when count > U.
[[nodiscard]] std::vector<std::size_t> shard_rows(const std::vector<std::vector<std::size_t>>& units, std::size_t index,
                                                  std::size_t count);

//! Rows as ranges, "0-7,233-240" (sorted input; "" for none).
[[nodiscard]] std::string format_rows(const std::vector<std::size_t>& rows);
//! The inverse of format_rows; nullopt for malformed text (not ascending, bad numbers, a row >= n_dy).
[[nodiscard]] std::optional<std::vector<std::size_t>> parse_rows(const std::string& text, std::size_t n_dy);

}  // namespace ctab::gen
