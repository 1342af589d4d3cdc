// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Shards for array schedulers (Slurm job arrays and the like): `ctab generate --shard K/N` solves only the rows
//! of shard K (case_partition.hpp) and writes a shard file; `ctab merge` joins the N shard files into the table
//! a single run gives, bit for bit (the same datasets, jumps and provenance; run with the same SOURCE_DATE_EPOCH
//! and --threads the files are byte-identical).
//!
//! A shard file is a table file of the full shape (tables/README.md) with three more root attributes:
//! `shard_index` K (1..N), `shard_count` N and `shard_rows` (its lateral-shift rows, "0-7,233-240"). Rows outside
//! the shard hold status invalid-input and no patch, so a shard used by mistake as a table fails those cases
//! loudly instead of giving zero forces; its jumps are left empty (the merge finds them over the whole table).
#include <cstddef>
#include <string>
#include <vector>

#include "ctab/sweep/table_generator.hpp"

namespace ctab::gen {

struct ShardSpec {
  std::size_t index = 1;  //!< K, 1..count
  std::size_t count = 1;  //!< N >= 1
};

//! Most shards of one table. Chosen: far more than any array job needs; bounds the merge's file list.
inline constexpr std::size_t kMaxShards = 100'000;

//! Parses "K/N" (1 <= K <= N <= kMaxShards); an InputError names `source` (e.g. "--shard") and what was expected.
[[nodiscard]] ShardSpec parse_shard_spec(const std::string& text, const std::string& source);

//! Solves shard `spec` of the config's table and returns the shard (header above). Throws InputError at set-up.
[[nodiscard]] tables::Table generate_shard(const TableConfig& config, const GeneratorInfo& info, ShardSpec spec,
                                           const ProgressCallback& progress = {});

//! One shard as read from its file.
struct ShardFile {
  std::string path;
  tables::Table table;
};

//! Joins shards into the whole table: provenance from shard 1 without the shard attributes (threads and
//! created_utc as shard 1 ran), rows from their own shards, jumps over the whole table. Throws InputError naming
//! the file(s) when one is not a shard, shard counts differ, a shard is missing or given twice, the shards come from
//! different configs, profiles or generator builds (any provenance attribute but created_utc, config_source and
//! threads), their axes or shapes differ, or a shard's rows are not the rows of its index.
[[nodiscard]] tables::Table merge_shards(std::vector<ShardFile> shards);

}  // namespace ctab::gen
