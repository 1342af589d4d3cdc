// SPDX-License-Identifier: Apache-2.0
// [output] compression: the config key, the root attribute compression_level, and the writer's deflate level
// (deterministic bytes at every level; level 0 writes no filters).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <functional>
#include <string>
#include <thread>

#include "ctab/core/error.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/tables/table.hpp"

namespace {

using namespace ctab::gen;
namespace tables = ctab::tables;

const std::string kAxes =
    "[axes]\nlateral_displacement_m = { start = -3e-3, stop = 3e-3, step = 0.5e-3 }\nvertical_load_N = 78.5e3\n";

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string temp_file(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / ("ctab_compression_" + name)).string();
}

TEST(Compression, ConfigKeyDefaultAndRange) {
  EXPECT_EQ(parse_table_config(kAxes, "c.toml").compression_level,
            static_cast<std::size_t>(tables::kDefaultCompressionLevel));
  EXPECT_EQ(parse_table_config(kAxes + "[output]\ncompression = 0\n", "c.toml").compression_level, 0u);
  EXPECT_EQ(parse_table_config(kAxes + "[output]\ncompression = 9\n", "c.toml").compression_level, 9u);
  for (const char* bad : {"10", "-1", "\"fast\""}) {
    try {
      (void)parse_table_config(kAxes + "[output]\ncompression = " + bad + "\n", "c.toml");
      ADD_FAILURE() << "accepted compression = " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("c.toml:"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("output.compression"), std::string::npos) << e.what();
    }
  }
}

TEST(Compression, LevelFromAttributeClamped) {
  tables::Table table;
  EXPECT_EQ(tables::compression_level(table), tables::kDefaultCompressionLevel);
  table.integer_attributes[tables::kCompressionLevelAttribute] = 12;
  EXPECT_EQ(tables::compression_level(table), 9);
  table.integer_attributes[tables::kCompressionLevelAttribute] = -3;
  EXPECT_EQ(tables::compression_level(table), 0);
}

// Each level: the table reads back equal, the same table written twice gives the same bytes; level 0 gives the
// largest file and 9 the smallest.
TEST(Compression, LevelsWriteDeterministicReadableFiles) {
  GeneratorInfo info;
  info.threads = 2;
  std::uintmax_t size_0 = 0, size_9 = 0;
  for (const int level : {0, 1, 9}) {
    const TableConfig config =
        parse_table_config(kAxes + "[output]\ncompression = " + std::to_string(level) + "\n", "c.toml");
    const tables::Table table = generate_table(config, info, {});
    EXPECT_EQ(table.integer_attributes.at(tables::kCompressionLevelAttribute), level);
    const std::string first = temp_file("a.h5"), second = temp_file("b.h5");
    ASSERT_TRUE(tables::write_table(table, first).ok());
    ASSERT_TRUE(tables::write_table(table, second).ok());
    EXPECT_EQ(bytes_of(first), bytes_of(second)) << "level " << level;
    tables::Table back;
    ASSERT_TRUE(tables::read_table(first, back).ok());
    EXPECT_EQ(back.roll_rad, table.roll_rad);
    EXPECT_EQ(back.patch.normal_force_N, table.patch.normal_force_N);
    EXPECT_EQ(back.patch.strip_peak_pressure_Pa, table.patch.strip_peak_pressure_Pa);
    EXPECT_EQ(back.integer_attributes.at(tables::kCompressionLevelAttribute), level);
    if (level == 0) size_0 = std::filesystem::file_size(first);
    if (level == 9) size_9 = std::filesystem::file_size(first);
    std::filesystem::remove(first);
    std::filesystem::remove(second);
  }
  EXPECT_GT(size_0, size_9);
}

// Chunks compressed in parallel (write_table's ParallelFor) give the serial write's file, byte for byte: tasks run
// in reverse order or on two threads; and the chunks read back through HDF5's own filters.
// The strip fields span several chunks, a partial edge chunk included (121 rows x 9 loads x 2 wheels x 3 slots x 32
// samples: 209 088 values, chunks of at most 65 536).
TEST(Compression, ParallelChunksGiveTheSerialWritesBytes) {
  GeneratorInfo info;
  info.threads = 2;
  const std::string axes = "[axes]\nlateral_displacement_m = { start = -6e-3, stop = 6e-3, step = 0.1e-3 }\n"
                           "vertical_load_N = { start = 40e3, stop = 120e3, step = 10e3 }\n";
  const tables::ParallelFor reversed = [](std::size_t count, const std::function<void(std::size_t)>& task) {
    for (std::size_t i = count; i-- > 0;) task(i);
  };
  const tables::ParallelFor two_threads = [](std::size_t count, const std::function<void(std::size_t)>& task) {
    std::thread other([&] {
      for (std::size_t i = 1; i < count; i += 2) task(i);
    });
    for (std::size_t i = 0; i < count; i += 2) task(i);
    other.join();
  };
  for (const int level : {1, 9}) {
    const TableConfig config =
        parse_table_config(axes + "[output]\ncompression = " + std::to_string(level) + "\n", "c.toml");
    const tables::Table table = generate_table(config, info, {});
    ASSERT_GT(table.patch.strip_peak_pressure_Pa.size(), 2u * 65536u);  // several chunks
    const std::string serial = temp_file("serial.h5"), parallel = temp_file("parallel.h5");
    ASSERT_TRUE(tables::write_table(table, serial).ok());
    for (const tables::ParallelFor& parallel_for : {reversed, two_threads}) {
      ASSERT_TRUE(tables::write_table(table, parallel, parallel_for).ok());
      EXPECT_EQ(bytes_of(parallel), bytes_of(serial)) << "level " << level;
      tables::Table back;
      ASSERT_TRUE(tables::read_table(parallel, back).ok());
      EXPECT_EQ(back.patch.strip_peak_pressure_Pa, table.patch.strip_peak_pressure_Pa);
    }
    std::filesystem::remove(serial);
    std::filesystem::remove(parallel);
  }
}

}  // namespace
