// SPDX-License-Identifier: Apache-2.0
// Sweeps in parts: work units and shards (case_partition.hpp), rows moved between tables (table_rows.hpp), shards
// and their merge (table_shard.hpp) against a single run of the same config.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "ctab/core/error.hpp"
#include "ctab/sweep/case_partition.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/sweep/table_rows.hpp"
#include "ctab/sweep/table_shard.hpp"

namespace {

using namespace ctab::gen;
using ctab::tables::CaseStatus;
using ctab::tables::Table;

// Single wheel, mirrored (symmetric axis), 9 rows.
const char* const kMirroredConfig =
    "[solver]\nmode = \"wheel\"\n[axes]\n"
    "lateral_displacement_m = { start = -2e-3, stop = 2e-3, step = 0.5e-3 }\nvertical_load_N = 78.5e3\n";
// Wheelset, not mirrored (asymmetric axis), two loads, 19 rows.
const char* const kAsymmetricConfig = "[axes]\nlateral_displacement_m = { start = -1e-3, stop = 8e-3, step = 0.5e-3 }\n"
                                      "vertical_load_N = [60e3, 90e3]\n";

std::vector<std::size_t> all_rows(std::size_t n) {
  std::vector<std::size_t> rows(n);
  for (std::size_t i = 0; i < n; ++i) rows[i] = i;
  return rows;
}

// Every dataset, the jumps and every attribute equal.
void expect_same_table(const Table& a, const Table& b) {
  EXPECT_EQ(a.lateral_displacement_m, b.lateral_displacement_m);
  EXPECT_EQ(a.second_axis, b.second_axis);
  EXPECT_EQ(pack_rows(a, all_rows(a.n_dy())), pack_rows(b, all_rows(b.n_dy())));
  ASSERT_EQ(a.jumps.size(), b.jumps.size());
  for (std::size_t j = 0; j < a.jumps.size(); ++j) {
    EXPECT_EQ(a.jumps[j].i_dy, b.jumps[j].i_dy);
    EXPECT_EQ(a.jumps[j].slot, b.jumps[j].slot);
    EXPECT_EQ(a.jumps[j].kind, b.jumps[j].kind);
  }
  EXPECT_EQ(a.text_attributes, b.text_attributes);
  EXPECT_EQ(a.number_attributes, b.number_attributes);
  EXPECT_EQ(a.integer_attributes, b.integer_attributes);
}

std::vector<ShardFile> make_shards(const TableConfig& config, std::size_t count) {
  std::vector<ShardFile> shards;
  for (std::size_t k = 1; k <= count; ++k)
    shards.push_back({"shard" + std::to_string(k) + ".h5", generate_shard(config, GeneratorInfo{}, {k, count})});
  return shards;
}

std::string merge_error(std::vector<ShardFile> shards) {
  try {
    (void)merge_shards(std::move(shards));
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(SweepUnits, EveryRowOnceAndMirrorClosed) {
  for (const std::size_t n : {1u, 2u, 9u, 16u, 17u, 241u})
    for (const bool mirrored : {false, true}) {
      const auto units = sweep_units(n, mirrored, 4);
      std::vector<std::size_t> seen;
      for (const auto& unit : units) {
        EXPECT_TRUE(std::is_sorted(unit.begin(), unit.end()));
        const std::set<std::size_t> in(unit.begin(), unit.end());
        for (const std::size_t i : unit)
          if (mirrored) {
            EXPECT_EQ(in.count(n - 1 - i), 1u) << "n " << n << " row " << i;
          }
        seen.insert(seen.end(), unit.begin(), unit.end());
      }
      std::sort(seen.begin(), seen.end());
      EXPECT_EQ(seen, all_rows(n)) << "n " << n << (mirrored ? " mirrored" : "");
    }
  const auto plain = sweep_units(10, false, 4);
  ASSERT_EQ(plain.size(), 3u);
  EXPECT_EQ(plain[2], (std::vector<std::size_t>{8, 9}));
  const auto mirrored = sweep_units(9, true, 2);  // half axis 0..4: {0,1}, {2,3}, {4}
  ASSERT_EQ(mirrored.size(), 3u);
  EXPECT_EQ(mirrored[0], (std::vector<std::size_t>{0, 1, 7, 8}));
  EXPECT_EQ(mirrored[2], (std::vector<std::size_t>{4}));
}

TEST(SweepUnits, LongSweepsTakeLongerUnits) {
  // The default table (241 rows, mirrored: 121 on the half axis) keeps units of 8 rows, 16 units.
  EXPECT_EQ(rows_per_unit(241, true), kRowsPerUnit);
  EXPECT_EQ(sweep_units(241, true).size(), 16u);
  // The 0.01 mm sweep (2401 rows, 1201 on the half axis): ceil(1201 / 48) = 26 rows, 47 units of whole chains.
  EXPECT_EQ(rows_per_unit(2401, true), 26u);
  const auto fine = sweep_units(2401, true);
  EXPECT_EQ(fine.size(), 47u);
  EXPECT_EQ(fine[0].size(), 52u);  // 26 rows and their mirrors
  const std::vector<std::size_t> previous = warm_start_previous_rows(2401, true);
  std::size_t cold = 0;
  for (std::size_t i = 0; i < 2401; ++i) cold += previous[i] == kColdStart ? 1u : 0u;
  EXPECT_EQ(cold, 2 * 47u - 1);  // one chain per half of every unit; the centre row's unit holds it once
  // Never above kMaxRowsPerUnit, and the length depends on the axis alone.
  EXPECT_EQ(rows_per_unit(1000000, false), kMaxRowsPerUnit);
  EXPECT_EQ(rows_per_unit(385, false), 9u);
}

TEST(SweepUnits, ShardsAreDisjointContiguousRunsOfUnits) {
  const auto units = sweep_units(241, true);
  for (const std::size_t count : {1u, 2u, 3u, 7u, 16u, 40u}) {
    std::vector<std::size_t> seen;
    for (std::size_t k = 1; k <= count; ++k) {
      const auto rows = shard_rows(units, k, count);
      seen.insert(seen.end(), rows.begin(), rows.end());
    }
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(seen, all_rows(241)) << count << " shards";
  }
  EXPECT_TRUE(shard_rows(units, 1, 40).empty());  // 16 units over 40 shards: some are empty
  EXPECT_TRUE(shard_rows(units, 0, 2).empty());
  EXPECT_TRUE(shard_rows(units, 3, 2).empty());
}

TEST(SweepUnits, RowsTextRoundTripsAndRejectsMalformedText) {
  const std::vector<std::size_t> rows = {0, 1, 2, 5, 7, 8};
  EXPECT_EQ(format_rows(rows), "0-2,5,7-8");
  EXPECT_EQ(parse_rows("0-2,5,7-8", 9), rows);
  EXPECT_EQ(parse_rows("", 9), std::vector<std::size_t>{});
  for (const char* bad : {"3-1", "1,1", "2,1", "a", "1,", "1-", "-1", "0-9", "1;2", "99999999999999999999"})
    EXPECT_FALSE(parse_rows(bad, 9).has_value()) << bad;
}

TEST(ShardSpec, ParsesKOfNAndRejectsTheRest) {
  const ShardSpec spec = parse_shard_spec("2/3", "--shard");
  EXPECT_EQ(spec.index, 2u);
  EXPECT_EQ(spec.count, 3u);
  for (const char* bad : {"0/3", "4/3", "1/0", "x", "1/2/3", "", "/2", "1/", " 1/2", "1/100001", "-1/2"})
    EXPECT_THROW((void)parse_shard_spec(bad, "--shard"), InputError) << bad;
}

TEST(TableRows, PackUnpackCopyAndFail) {
  const TableConfig config = parse_table_config(kMirroredConfig, "mirrored.toml");
  const Table table = generate_table(config, GeneratorInfo{});
  const std::vector<std::size_t> rows = {1, 4, 7};
  Table copy = table, packed = table;
  fail_rows(copy, all_rows(table.n_dy()), CaseStatus::SolverException);
  fail_rows(packed, all_rows(table.n_dy()), CaseStatus::SolverException);
  EXPECT_EQ(copy.status[copy.wheel_index(4, 0, 1)], CaseStatus::SolverException);
  EXPECT_EQ(copy.patch.present[copy.patch_index(4, 0, 0, 0)], 0);
  copy_rows(table, copy, rows);
  const std::vector<unsigned char> buffer = pack_rows(table, rows);
  EXPECT_EQ(buffer.size(), rows.size() * row_bytes(table));
  EXPECT_FALSE(unpack_rows(packed, rows, std::vector<unsigned char>(buffer.begin(), buffer.end() - 1)));
  ASSERT_TRUE(unpack_rows(packed, rows, buffer));
  EXPECT_EQ(pack_rows(copy, all_rows(table.n_dy())), pack_rows(packed, all_rows(table.n_dy())));
  EXPECT_EQ(pack_rows(copy, rows), buffer);
  EXPECT_EQ(copy.status[copy.wheel_index(4, 0, 0)], table.status[table.wheel_index(4, 0, 0)]);
  EXPECT_EQ(copy.status[copy.wheel_index(3, 0, 0)], CaseStatus::SolverException);
  EXPECT_EQ(copy.patch.normal_force_N[copy.patch_index(4, 0, 0, 0)],
            table.patch.normal_force_N[table.patch_index(4, 0, 0, 0)]);
}

TEST(TableSweep, RowsOfAMirroredSweepMustBeMirrorClosed) {
  const TableSweep sweep(parse_table_config(kMirroredConfig, "mirrored.toml"), GeneratorInfo{});
  ASSERT_TRUE(sweep.mirrored());
  Table table = sweep.empty_table();
  EXPECT_THROW(sweep.solve_rows({0}, table), std::invalid_argument);
  EXPECT_THROW(sweep.solve_rows({0, 8, 8}, table), std::invalid_argument);
  EXPECT_THROW(sweep.solve_rows({9}, table), std::invalid_argument);
  EXPECT_NO_THROW(sweep.solve_rows({0, 8}, table));
}

TEST(TableShard, ShardsMergeIntoTheSingleRunTable) {
  for (const char* text : {kMirroredConfig, kAsymmetricConfig}) {
    const TableConfig config = parse_table_config(text, "config.toml");
    const Table single = generate_table(config, GeneratorInfo{});
    for (const std::size_t count : {1u, 2u, 3u, 5u}) {
      std::vector<ShardFile> shards = make_shards(config, count);
      std::reverse(shards.begin(), shards.end());  // any order
      Table merged = merge_shards(std::move(shards));
      merged.text_attributes["created_utc"] = single.text_attributes.at("created_utc");  // runs a second apart
      expect_same_table(merged, single);
    }
  }
}

TEST(TableShard, AShardFailsTheRowsItDoesNotHold) {
  const TableConfig config = parse_table_config(kAsymmetricConfig, "config.toml");
  const Table shard = generate_shard(config, GeneratorInfo{}, {2, 2});
  EXPECT_EQ(shard.integer_attributes.at("shard_index"), 2);
  EXPECT_EQ(shard.integer_attributes.at("shard_count"), 2);
  EXPECT_EQ(shard.text_attributes.at("shard_rows"), "8-18");
  EXPECT_EQ(shard.status[shard.wheel_index(0, 1, 0)], CaseStatus::InvalidInput);
  EXPECT_TRUE(ctab::tables::is_success(shard.status[shard.wheel_index(8, 1, 0)]));
  EXPECT_TRUE(shard.jumps.empty());
}

TEST(TableShard, MergeNamesMissingDuplicateAndForeignShards) {
  const TableConfig config = parse_table_config(kAsymmetricConfig, "config.toml");
  std::vector<ShardFile> three = make_shards(config, 3);
  EXPECT_NE(merge_error({three[0], three[2]}).find("missing shard(s) 2 of 3"), std::string::npos);
  EXPECT_NE(merge_error({three[0], three[1], three[1], three[2]}).find("shard2.h5: shard 2/3 is given twice"),
            std::string::npos);
  const std::vector<ShardFile> two = make_shards(config, 2);
  EXPECT_NE(merge_error({three[0], two[1], three[2]}).find("is not one of 3 shards"), std::string::npos);
  TableConfig other = config;
  other.strip_width_m = 0.25e-3;
  ShardFile foreign{"foreign.h5", generate_shard(other, GeneratorInfo{}, {2, 3})};
  EXPECT_NE(merge_error({three[0], foreign, three[2]})
                .find("foreign.h5: does not belong with shard1.h5: the attribute strip_width_m differs"),
            std::string::npos);
  ShardFile table{"table.h5", generate_table(config, GeneratorInfo{})};
  EXPECT_NE(merge_error({table}).find("table.h5: not a shard file"), std::string::npos);
  ShardFile tampered = three[1];
  tampered.table.text_attributes["shard_rows"] = "0-5";
  EXPECT_NE(merge_error({three[0], tampered, three[2]}).find("is not the rows of shard 2/3"), std::string::npos);
  EXPECT_NE(merge_error({}).find("no shard files"), std::string::npos);
}
