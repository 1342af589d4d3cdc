// SPDX-License-Identifier: Apache-2.0
// Blob format: round trip, bit-identical answers to the in-memory load, the C-header path, corruption and version
// checks, single precision.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/open.hpp"
#include "synthetic_table.hpp"

namespace ctab::lookup {
namespace {

using test::identical;
using test::parse_c_header;

//! Answers of a table at many points, both wheels, as raw results.
std::vector<ctab_result> answers(const Table& table) {
  std::vector<ctab_result> out;
  for (double dy = -13e-3; dy <= 13e-3; dy += 0.137e-3)
    for (const double load : {55e3, 63e3, 79e3, 95e3})
      for (int wheel = 0; wheel < 2; ++wheel) {
        ctab_location where;
        table.prelookup(dy, load, where);
        ctab_result r;
        std::memset(&r, 0, sizeof r);
        table.query(where, wheel, r);
        out.push_back(r);
      }
  return out;
}

const TableData kData = test::make_synthetic({.n_second = 3, .failed_case = true});

// A locally refined dy axis: 0.25 mm steps between 5 and 7.5 mm, where the flange appears.
const TableData kRefined = test::make_synthetic(
    {.n_second = 3, .failed_case = true, .refine_from_m = 5e-3, .refine_to_m = 7.5e-3, .refine_step_m = 0.25e-3});

TEST(LookupBlob, RoundTripGivesBitIdenticalAnswers) {
  for (const TableData* data : {&kData, &kRefined})
    for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
      Table direct, from_blob, from_header;
      ASSERT_TRUE(direct.load(*data, {mode, false}).ok());
      const std::vector<unsigned char> blob = write_blob(*data, false);
      EXPECT_EQ(blob.size() % 8, 0u);
      ASSERT_TRUE(open_memory(blob.data(), blob.size(), {mode, false}, from_blob).ok());
      const std::vector<unsigned char> parsed = parse_c_header(blob_c_header(blob, "ctab_table_blob"));
      ASSERT_EQ(parsed, blob);
      ASSERT_TRUE(open_memory(parsed.data(), parsed.size(), {mode, false}, from_header).ok());
      const auto expected = answers(direct);
      EXPECT_TRUE(identical(answers(from_blob), expected));
      EXPECT_TRUE(identical(answers(from_header), expected));
    }
}

TEST(LookupBlob, ReadBackEqualsTheDescription) {
  TableData back;
  bool single = true;
  ASSERT_TRUE(read_blob(write_blob(kData, false).data(), write_blob(kData, false).size(), back, single).ok());
  EXPECT_FALSE(single);
  EXPECT_EQ(back.dy_m, kData.dy_m);
  EXPECT_EQ(back.second, kData.second);
  EXPECT_EQ(back.quantities, kData.quantities);
  EXPECT_EQ(back.strip_peak_pressure_Pa, kData.strip_peak_pressure_Pa);
  EXPECT_EQ(back.case_status, kData.case_status);
  EXPECT_EQ(back.present, kData.present);
  ASSERT_EQ(back.jumps.size(), kData.jumps.size());
  EXPECT_EQ(back.jumps[3].i_dy, kData.jumps[3].i_dy);
  EXPECT_EQ(back.jumps[3].kind, kData.jumps[3].kind);
}

TEST(LookupBlob, CorruptTruncatedAndForeignBlobsAreRefused) {
  const std::vector<unsigned char> blob = write_blob(kData, false);
  Table table;
  std::vector<unsigned char> bad = blob;
  bad[kBlobHeaderBytes + 1000] ^= 0x10;
  EXPECT_EQ(open_memory(bad.data(), bad.size(), {}, table).status, CTAB_ERR_CHECKSUM);
  EXPECT_EQ(open_memory(blob.data(), blob.size() - 8, {}, table).status, CTAB_ERR_NOT_A_TABLE);
  EXPECT_EQ(open_memory(blob.data(), 10, {}, table).status, CTAB_ERR_NOT_A_TABLE);
  EXPECT_EQ(open_memory(nullptr, 0, {}, table).status, CTAB_ERR_NOT_A_TABLE);
  bad = blob;
  bad[8] = 2;  // format version
  EXPECT_EQ(open_memory(bad.data(), bad.size(), {}, table).status, CTAB_ERR_VERSION);
  bad = blob;
  bad[12] = 1;  // table schema 1
  EXPECT_EQ(open_memory(bad.data(), bad.size(), {}, table).status, CTAB_ERR_VERSION);
  TableData with_nan = kData;
  with_nan.strip_half_length_m[7] = NAN;
  const std::vector<unsigned char> nan_blob = write_blob(with_nan, false);
  EXPECT_EQ(open_memory(nan_blob.data(), nan_blob.size(), {}, table).status, CTAB_ERR_CONTENT);
  EXPECT_FALSE(table.loaded());
  const unsigned char hdf5[16] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  EXPECT_TRUE(looks_like_hdf5(hdf5, sizeof hdf5));
}

TEST(LookupBlob, FilesLoadAndHdf5FilesNeedTheHdf5Library) {
  const std::string path = ::testing::TempDir() + "ctab_lookup_blob_test.blob";
  const std::vector<unsigned char> blob = write_blob(kData, false);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  std::fwrite(blob.data(), 1, blob.size(), f);
  std::fclose(f);
  ctab_table* table = nullptr;
  EXPECT_EQ(ctab_table_open(path.c_str(), nullptr, &table), CTAB_OK);
  EXPECT_EQ(ctab_table_dy_count(table), 25u);
  EXPECT_EQ(ctab_table_second_count(table), 3u);
  EXPECT_STREQ(ctab_table_second_axis_name(table), "vertical_load_N");
  ctab_table_close(table);
  f = std::fopen(path.c_str(), "wb");
  const unsigned char hdf5[16] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  std::fwrite(hdf5, 1, sizeof hdf5, f);
  std::fclose(f);
  EXPECT_EQ(ctab_table_open(path.c_str(), nullptr, &table), CTAB_ERR_HDF5_UNAVAILABLE);
  EXPECT_EQ(table, nullptr);
  std::remove(path.c_str());
  EXPECT_EQ(ctab_table_open(path.c_str(), nullptr, &table), CTAB_ERR_CANNOT_OPEN);
}

TEST(LookupBlob, SinglePrecisionHalvesTheValuesAndStaysClose) {
  Table full, single;
  ASSERT_TRUE(full.load(kData, {}).ok());
  const std::vector<unsigned char> blob64 = write_blob(kData, false), blob32 = write_blob(kData, true);
  EXPECT_LT(static_cast<double>(blob32.size()), 0.6 * static_cast<double>(blob64.size()));
  ASSERT_TRUE(open_memory(blob32.data(), blob32.size(), {}, single).ok());
  EXPECT_TRUE(single.single_precision()) << "a float blob loads as float";
  EXPECT_LT(static_cast<double>(single.memory_bytes()), 0.7 * static_cast<double>(full.memory_bytes()));
  const auto a = answers(full), b = answers(single);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int s = 0; s < 3; ++s) {
      EXPECT_EQ(a[i].patch[s].present, b[i].patch[s].present);
      EXPECT_NEAR(a[i].patch[s].q[CTAB_NORMAL_FORCE_N], b[i].patch[s].q[CTAB_NORMAL_FORCE_N],
                  1e-6 * std::fabs(a[i].patch[s].q[CTAB_NORMAL_FORCE_N]) + 1e-12);
    }
}

}  // namespace
}  // namespace ctab::lookup
