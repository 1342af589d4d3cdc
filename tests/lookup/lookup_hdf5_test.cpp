// SPDX-License-Identifier: Apache-2.0
// The HDF5 path (ctab_lookup_hdf5): a generated schema-2 table written to HDF5 and loaded from it gives answers
// bit-identical to its blob and to its C header; the C loader accepts HDF5 files, the core refuses them.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/ctab_lookup_hdf5.h"
#include "ctab/lookup/hdf5_table.hpp"
#include "ctab/lookup/open.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "synthetic_table.hpp"

namespace ctab::lookup {
namespace {

using test::identical;
using test::parse_c_header;

std::vector<ctab_result> answers(const Table& table) {
  std::vector<ctab_result> out;
  for (double dy = -12.5e-3; dy <= 12.5e-3; dy += 0.0173e-3)
    for (int wheel = 0; wheel < 2; ++wheel) {
      ctab_location where;
      table.prelookup(dy, 0.0, where);
      ctab_result r;
      std::memset(&r, 0, sizeof r);
      table.query(where, wheel, r);
      out.push_back(r);
    }
  return out;
}

TEST(LookupHdf5, Hdf5BlobAndCHeaderPathsGiveBitIdenticalAnswers) {
  const gen::TableConfig config = gen::parse_table_config(gen::kDefaultTableConfig, "default config");
  const tables::Table generated = gen::generate_table(config, gen::GeneratorInfo{});
  const std::string path = ::testing::TempDir() + "ctab_lookup_hdf5_test.h5";
  ASSERT_TRUE(tables::write_table(generated, path).ok());
  for (const ctab_interpolation mode : {CTAB_LINEAR, CTAB_PCHIP}) {
    Table from_hdf5, from_blob, from_header;
    const LoadResult loaded = open_file(path, {mode, false}, from_hdf5);
    ASSERT_TRUE(loaded.ok()) << loaded.message;
    TableData data;
    ASSERT_TRUE(from_tables(generated, data).ok());
    const std::vector<unsigned char> blob = write_blob(data, false);
    ASSERT_TRUE(open_memory(blob.data(), blob.size(), {mode, false}, from_blob).ok());
    const std::vector<unsigned char> header_bytes = parse_c_header(blob_c_header(blob, "table"));
    ASSERT_TRUE(open_memory(header_bytes.data(), header_bytes.size(), {mode, false}, from_header).ok());
    const auto expected = answers(from_hdf5);
    EXPECT_TRUE(identical(answers(from_blob), expected));
    EXPECT_TRUE(identical(answers(from_header), expected));
  }
  ctab_table* table = nullptr;
  EXPECT_EQ(ctab_table_open_hdf5(path.c_str(), nullptr, &table), CTAB_OK);
  EXPECT_EQ(ctab_table_dy_count(table), 265u);
  EXPECT_EQ(ctab_table_slot_count(table), generated.n_slots);
  ctab_table_close(table);
  EXPECT_EQ(ctab_table_open(path.c_str(), nullptr, &table), CTAB_ERR_HDF5_UNAVAILABLE) << "the core loads blobs only";
  std::remove(path.c_str());
  EXPECT_EQ(ctab_table_open_hdf5(path.c_str(), nullptr, &table), CTAB_ERR_CANNOT_OPEN);
}

// Located jumps (1 um cells on an adaptive axis, at different dy per load row) pass through HDF5 to the lookup: the
// axis and the jumps read back as written, and a query between the rows takes the load-interpolated side.
TEST(LookupHdf5, LocatedJumpsSurviveTheHdf5Path) {
  const TableData located = test::make_located();
  tables::Table t;
  t.lateral_displacement_m = located.dy_m;
  t.second_axis = located.second;
  t.second_axis_name = "vertical_load_N";
  t.second_axis_units = "N";
  t.strip_samples = located.strip_samples;
  t.allocate();
  for (std::size_t p = 0; p < located.present.size(); ++p) {
    t.patch.present[p] = located.present[p];
    t.patch.normal_force_N[p] = located.quantities[p * kQuantities + CTAB_NORMAL_FORCE_N];
    t.patch.y_rail_m[p] = located.quantities[p * kQuantities + CTAB_Y_RAIL_M];
    for (auto* positive : {&t.patch.force_vertical_N, &t.patch.area_m2, &t.patch.max_pressure_Pa,
                           &t.patch.rolling_radius_m, &t.patch.semi_axis_a_m, &t.patch.semi_axis_b_m})
      (*positive)[p] = located.present[p] ? 1.0 : 0.0;  // the reader's checks of a present patch
  }
  for (const Jump& j : located.jumps)
    t.jumps.push_back({j.i_second, j.wheel, j.slot, j.i_dy, static_cast<tables::JumpKind>(j.kind)});
  const std::string path = testing::TempDir() + "located_jumps.h5";
  ASSERT_TRUE(tables::write_table(t, path).ok());
  TableData back;
  const LoadResult read = read_hdf5(path, back);
  std::remove(path.c_str());
  ASSERT_TRUE(read.ok()) << read.message;
  EXPECT_EQ(back.dy_m, located.dy_m);
  ASSERT_EQ(back.jumps.size(), located.jumps.size());
  Table table;
  ASSERT_TRUE(table.load(back, {}).ok());
  EXPECT_EQ(table.jump_bands(), 10u);
  // The flange (slot 1) appears at 1.234 mm at 60 kN and at 2.071 mm at 80 kN: at 1.5 mm it is there up to 66.36 kN.
  for (const auto& [second, present] : {std::pair{66e3, 1}, std::pair{66.7e3, 0}}) {
    ctab_location where;
    table.prelookup(1.5e-3, second, where);
    ctab_result r;
    table.query(where, 0, r);
    EXPECT_EQ(r.patch[1].present, present) << second;
  }
}

TEST(LookupHdf5, ConversionRefusesAnUnknownSecondAxis) {
  tables::Table t;
  t.lateral_displacement_m = {0.0, 1e-3};
  t.second_axis = {1.0};
  t.second_axis_name = "speed_m_per_s";
  t.strip_samples = 2;
  t.allocate();
  TableData data;
  EXPECT_EQ(from_tables(t, data).status, CTAB_ERR_AXES);
  t.second_axis_name = "approach_m";
  EXPECT_TRUE(from_tables(t, data).ok());
  EXPECT_EQ(data.second_axis, SecondAxis::Approach);
}

}  // namespace
}  // namespace ctab::lookup
