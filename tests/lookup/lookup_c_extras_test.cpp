// SPDX-License-Identifier: Apache-2.0
// The C calls beside the query: the version (ctab_version, ctab_version_numbers), a blob's header before loading
// it (ctab_blob_info_*), and n queries in one call (ctab_query_batch) against ctab_query point by point.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/ctab_lookup.h"
#include "synthetic_table.hpp"

namespace {

using ctab::lookup::test::make_synthetic;

std::vector<unsigned char> synthetic_blob(std::size_t n_second) {
  return ctab::lookup::write_blob(make_synthetic({.n_second = n_second, .failed_case = true}), false);
}

ctab_table* open(const std::vector<unsigned char>& blob) {
  ctab_table* table = nullptr;
  EXPECT_EQ(ctab_table_open_memory(blob.data(), blob.size(), nullptr, &table), CTAB_OK);
  return table;
}

TEST(LookupVersion, StringAndNumbersAgreeWithTheHeader) {
  int32_t major = -1, minor = -1, patch = -1;
  ctab_version_numbers(&major, &minor, &patch);
  ctab_version_numbers(nullptr, nullptr, nullptr);
  EXPECT_EQ(std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch), ctab_version());
  EXPECT_STREQ(ctab_version(), CTAB_VERSION_STRING);
  EXPECT_EQ(major, CTAB_VERSION_MAJOR);
}

TEST(LookupBlobInfo, ReadsTheHeaderAndSaysWhetherItLoads) {
  std::vector<unsigned char> blob = synthetic_blob(1);
  ctab_blob_info info;
  ASSERT_EQ(ctab_blob_info_memory(blob.data(), blob.size(), &info), CTAB_OK);
  EXPECT_EQ(info.format_version, static_cast<uint32_t>(CTAB_BLOB_FORMAT_VERSION));
  EXPECT_EQ(info.schema_version, static_cast<uint32_t>(CTAB_TABLE_SCHEMA_VERSION));
  EXPECT_EQ(info.value_bytes, 8u);
  EXPECT_EQ(info.payload_bytes + 64, blob.size());

  blob[8] = 7;  // a later format: described, not loadable
  EXPECT_EQ(ctab_blob_info_memory(blob.data(), blob.size(), &info), CTAB_ERR_VERSION);
  EXPECT_EQ(info.format_version, 7u);
  blob[8] = 1;
  blob[12] = 3;  // a later schema
  EXPECT_EQ(ctab_blob_info_memory(blob.data(), blob.size(), &info), CTAB_ERR_VERSION);
  EXPECT_EQ(info.schema_version, 3u);

  EXPECT_EQ(ctab_blob_info_memory(blob.data(), 63, &info), CTAB_ERR_NOT_A_TABLE);
  EXPECT_EQ(info.payload_bytes, 0u);
  const unsigned char hdf5[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  EXPECT_EQ(ctab_blob_info_memory(hdf5, sizeof hdf5, &info), CTAB_ERR_HDF5_UNAVAILABLE);
  EXPECT_EQ(ctab_blob_info_memory(nullptr, 64, &info), CTAB_INVALID_INPUT);
  EXPECT_EQ(ctab_blob_info_memory(blob.data(), blob.size(), nullptr), CTAB_INVALID_INPUT);
  EXPECT_EQ(ctab_blob_info_file("/nonexistent.blob", &info), CTAB_ERR_CANNOT_OPEN);
  EXPECT_EQ(ctab_blob_info_file(nullptr, &info), CTAB_INVALID_INPUT);
}

TEST(LookupBlobInfo, FromAFile) {
  const std::vector<unsigned char> blob = synthetic_blob(3);
  const std::string path = ::testing::TempDir() + "lookup_c_extras.blob";
  std::FILE* file = std::fopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  ASSERT_EQ(std::fwrite(blob.data(), 1, blob.size(), file), blob.size());
  std::fclose(file);
  ctab_blob_info info;
  ASSERT_EQ(ctab_blob_info_file(path.c_str(), &info), CTAB_OK);
  EXPECT_EQ(info.payload_bytes + 64, blob.size());
  std::remove(path.c_str());
}

TEST(LookupBatch, EqualsQueryPointByPoint) {
  ctab_table* table = open(synthetic_blob(3));
  ASSERT_NE(table, nullptr);
  const uint32_t slots = ctab_table_slot_count(table);
  std::vector<double> dy, load;
  for (double x = -13e-3; x <= 13e-3; x += 0.173e-3)
    for (const double l : {55e3, 70e3, 120e3}) dy.push_back(x), load.push_back(l);
  dy.push_back(std::numeric_limits<double>::quiet_NaN()), load.push_back(60e3);
  const std::size_t n = dy.size();
  std::vector<int32_t> status(n);
  std::vector<double> q(n * slots * CTAB_QUANTITIES);
  std::vector<int8_t> present(n * slots);
  for (int32_t wheel = 0; wheel < 2; ++wheel) {
    EXPECT_EQ(ctab_query_batch(table, dy.data(), load.data(), n, wheel, status.data(), q.data(), present.data()),
              CTAB_INVALID_INPUT);  // the NaN point is the most severe
    for (std::size_t i = 0; i < n; ++i) {
      ctab_result r;
      ASSERT_EQ(ctab_query(table, dy[i], load[i], wheel, &r), status[i]) << i;
      for (uint32_t s = 0; s < slots; ++s) {
        EXPECT_EQ(present[i * slots + s], r.patch[s].present) << i;
        EXPECT_EQ(std::memcmp(&q[(i * slots + s) * CTAB_QUANTITIES], r.patch[s].q, sizeof r.patch[s].q), 0) << i;
      }
    }
  }
  EXPECT_EQ(ctab_query_batch(table, dy.data(), load.data(), n - 1, 0, nullptr, nullptr, nullptr), CTAB_CLAMPED);
  const double inside_dy = 1e-3, inside_load = 70e3;
  EXPECT_EQ(ctab_query_batch(table, &inside_dy, &inside_load, 1, 0, nullptr, nullptr, nullptr), CTAB_OK);
  // Without the second axis, a table with several values refuses every point.
  EXPECT_EQ(ctab_query_batch(table, dy.data(), nullptr, 2, 0, status.data(), nullptr, nullptr), CTAB_INVALID_INPUT);
  EXPECT_EQ(status[0], CTAB_INVALID_INPUT);
  EXPECT_EQ(ctab_query_batch(table, nullptr, nullptr, 1, 0, nullptr, nullptr, nullptr), CTAB_INVALID_INPUT);
  EXPECT_EQ(ctab_query_batch(table, nullptr, nullptr, 0, 0, nullptr, nullptr, nullptr), CTAB_OK);
  EXPECT_EQ(ctab_query_batch(nullptr, dy.data(), load.data(), 1, 0, status.data(), nullptr, nullptr), CTAB_NOT_LOADED);
  ctab_table_close(table);
}

TEST(LookupBatch, SecondMayBeOmittedForOneValue) {
  ctab_table* table = open(synthetic_blob(1));
  ASSERT_NE(table, nullptr);
  const double dy[] = {-2e-3, 3e-3};
  int32_t status[2];
  EXPECT_EQ(ctab_query_batch(table, dy, nullptr, 2, 1, status, nullptr, nullptr), CTAB_OK);
  ctab_table_close(table);
}

}  // namespace
