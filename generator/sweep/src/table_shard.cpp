// SPDX-License-Identifier: Apache-2.0
#include "ctab/sweep/table_shard.hpp"

#include <algorithm>
#include <charconv>
#include <map>

#include "ctab/core/error.hpp"
#include "ctab/sweep/case_partition.hpp"
#include "ctab/sweep/slot_assignment.hpp"
#include "ctab/sweep/table_rows.hpp"

namespace ctab::gen {

namespace {

constexpr const char* kShardIndex = "shard_index";
constexpr const char* kShardCount = "shard_count";
constexpr const char* kShardRows = "shard_rows";

// Provenance that may differ between the shards of one table (the merged table keeps shard 1's).
bool may_differ(const std::string& name) {
  return name == "created_utc" || name == "config_source" || name == "threads" || name == kShardIndex ||
         name == kShardRows;
}

std::vector<std::size_t> all_rows_except(std::size_t n, const std::vector<std::size_t>& rows) {
  std::vector<bool> in(n, false);
  for (const std::size_t r : rows) in[r] = true;
  std::vector<std::size_t> others;
  for (std::size_t i = 0; i < n; ++i)
    if (!in[i]) others.push_back(i);
  return others;
}

// The first attribute (of one map) in which two shards differ, or "" when they agree.
template <class Map>
std::string first_difference(const Map& a, const Map& b) {
  for (const auto& [name, value] : a) {
    if (may_differ(name)) continue;
    const auto other = b.find(name);
    if (other == b.end() || !(other->second == value)) return name;
  }
  for (const auto& [name, value] : b)
    if (!may_differ(name) && a.find(name) == a.end()) return name;
  return "";
}

std::string shape_difference(const tables::Table& a, const tables::Table& b) {
  if (a.lateral_displacement_m != b.lateral_displacement_m) return "lateral_displacement_m axis";
  if (a.second_axis != b.second_axis || a.second_axis_name != b.second_axis_name) return "second axis";
  if (a.n_slots != b.n_slots) return "n_slots";
  if (a.strip_samples != b.strip_samples) return "strip_samples";
  std::string name = first_difference(a.text_attributes, b.text_attributes);
  if (name.empty()) name = first_difference(a.number_attributes, b.number_attributes);
  if (name.empty()) name = first_difference(a.integer_attributes, b.integer_attributes);
  return name.empty() ? "" : "attribute " + name;
}

std::size_t integer_attribute(const ShardFile& shard, const char* name) {
  const auto& integers = shard.table.integer_attributes;
  const auto found = integers.find(name);
  if (found == integers.end() || found->second < 1 || found->second > static_cast<std::int64_t>(kMaxShards))
    throw InputError(shard.path, 0,
                     std::string("not a shard file (no valid '") + name +
                         "' attribute; a complete table needs no merge)");
  return static_cast<std::size_t>(found->second);
}

bool is_mirrored(const tables::Table& table) {
  const auto found = table.text_attributes.find("mirrored");
  return found != table.text_attributes.end() && found->second.rfind("true", 0) == 0;
}

}  // namespace

ShardSpec parse_shard_spec(const std::string& text, const std::string& source) {
  ShardSpec spec;
  const auto slash = text.find('/');
  const char* const end = text.data() + text.size();
  const auto [index_end, index_error] =
      std::from_chars(text.data(), text.data() + std::min(slash, text.size()), spec.index);
  const bool index_ok = slash != std::string::npos && index_error == std::errc() && index_end == text.data() + slash;
  const auto [count_end, count_error] = index_ok ? std::from_chars(text.data() + slash + 1, end, spec.count)
                                                 : std::from_chars_result{end, std::errc::invalid_argument};
  if (!index_ok || count_error != std::errc() || count_end != end || spec.count < 1 || spec.count > kMaxShards ||
      spec.index < 1 || spec.index > spec.count)
    throw InputError(source, 0,
                     "expected K/N with 1 <= K <= N <= " + std::to_string(kMaxShards) + ", got '" + text + "'");
  return spec;
}

tables::Table generate_shard(const TableConfig& config, const GeneratorInfo& info, ShardSpec spec,
                             const ProgressCallback& progress) {
  const TableSweep sweep(config, info);
  const std::vector<std::size_t> rows = shard_rows(sweep_units(sweep.n_dy(), sweep.mirrored()), spec.index, spec.count);
  tables::Table table = sweep.empty_table();
  sweep.solve_rows(rows, table, progress);
  fail_rows(table, all_rows_except(sweep.n_dy(), rows), tables::CaseStatus::InvalidInput);
  sweep.finish(table);
  table.jumps.clear();
  table.integer_attributes[kShardIndex] = static_cast<std::int64_t>(spec.index);
  table.integer_attributes[kShardCount] = static_cast<std::int64_t>(spec.count);
  table.text_attributes[kShardRows] = format_rows(rows);
  return table;
}

tables::Table merge_shards(std::vector<ShardFile> shards) {
  if (shards.empty()) throw InputError("ctab merge", 0, "no shard files given");
  const std::size_t count = integer_attribute(shards.front(), kShardCount);
  std::map<std::size_t, const ShardFile*> by_index;
  for (const ShardFile& shard : shards) {
    const std::size_t index = integer_attribute(shard, kShardIndex);
    if (integer_attribute(shard, kShardCount) != count || index > count)
      throw InputError(shard.path, 0,
                       "shard " + std::to_string(index) + "/" + std::to_string(integer_attribute(shard, kShardCount)) +
                           " is not one of " + std::to_string(count) + " shards as " + shards.front().path + " is");
    if (const auto [at, inserted] = by_index.emplace(index, &shard); !inserted)
      throw InputError(shard.path, 0,
                       "shard " + std::to_string(index) + "/" + std::to_string(count) + " is given twice (also " +
                           at->second->path + ")");
  }
  std::string missing;
  for (std::size_t k = 1; k <= count; ++k)
    if (by_index.count(k) == 0) {
      if (!missing.empty()) missing += ", ";
      missing += std::to_string(k);
    }
  if (!missing.empty())
    throw InputError("ctab merge", 0, "missing shard(s) " + missing + " of " + std::to_string(count));

  const ShardFile& first = *by_index.at(1);
  const auto units = sweep_units(first.table.n_dy(), is_mirrored(first.table));
  tables::Table merged = first.table;
  for (const auto& [index, shard] : by_index) {
    if (const std::string difference = shape_difference(first.table, shard->table); !difference.empty())
      throw InputError(shard->path, 0,
                       "does not belong with " + first.path + ": the " + difference +
                           " differs (shards of different configs, profiles or ctab builds)");
    const std::vector<std::size_t> rows = shard_rows(units, index, count);
    const auto recorded = shard->table.text_attributes.find(kShardRows);
    if (recorded == shard->table.text_attributes.end() || recorded->second != format_rows(rows))
      throw InputError(shard->path, 0,
                       "its shard_rows attribute is not the rows of shard " + std::to_string(index) + "/" +
                           std::to_string(count) + " (" + format_rows(rows) + ")");
    copy_rows(shard->table, merged, rows);
  }
  merged.integer_attributes.erase(kShardIndex);
  merged.integer_attributes.erase(kShardCount);
  merged.text_attributes.erase(kShardRows);
  assign_table_slots_along_dy(merged);  // as TableSweep::finish: on the whole table, never per shard
  merged.jumps = tables::table_jumps(merged);  // the located jumps of an adaptive axis
  return merged;
}

}  // namespace ctab::gen
