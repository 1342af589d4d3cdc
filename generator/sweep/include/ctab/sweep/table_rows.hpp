// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Rows of a table (one lateral shift: every load, both wheels, every per-case dataset) moved between tables of
//! the same shape: shards merged, MPI results gathered. Axes, jumps and attributes are not rows.
#include <cstddef>
#include <vector>

#include "ctab/tables/table.hpp"

namespace ctab::gen {

//! Bytes of one row over every per-case dataset of `table` (its shape set, e.g. by allocate()).
[[nodiscard]] std::size_t row_bytes(const tables::Table& table) noexcept;
//! Copies rows `rows` from `from` into `to` (the same n_dy, n_second, n_slots and strip_samples; not checked).
void copy_rows(const tables::Table& from, tables::Table& to, const std::vector<std::size_t>& rows);
//! The rows as one buffer of rows.size() * row_bytes(table) bytes (for sending between processes).
[[nodiscard]] std::vector<unsigned char> pack_rows(const tables::Table& table, const std::vector<std::size_t>& rows);
//! Stores a pack_rows buffer of the same rows; false (and `table` untouched) if its size does not fit.
[[nodiscard]] bool unpack_rows(tables::Table& table, const std::vector<std::size_t>& rows,
                               const std::vector<unsigned char>& buffer);
//! Gives every case of `rows` the failure `status` on both wheels, no patch, roll and rolling-radius difference 0
//! (rows a process did not deliver; rows outside a shard).
void fail_rows(tables::Table& table, const std::vector<std::size_t>& rows, tables::CaseStatus status);
//! Moves the patch in slot k of wheel-case `wheel_index` (Table::wheel_index) to slot new_slot[k], for every
//! per-slot dataset; new_slot is a permutation of 0 .. n_slots - 1.
void permute_slots(tables::Table& table, std::size_t wheel_index, const std::vector<std::size_t>& new_slot);

}  // namespace ctab::gen
