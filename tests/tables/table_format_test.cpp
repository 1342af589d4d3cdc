// SPDX-License-Identifier: Apache-2.0
// The schema-2 table format alone (links only ctab::tables, plus the HDF5 C API to corrupt files): round trip of
// a small synthetic table with jumps, the status enum, UTF-8 strings and integer attributes; deterministic bytes;
// every validation failure named with its file, dataset and index.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include "ctab/tables/table.hpp"

using namespace ctab::tables;

namespace {

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "tables_" + name; }

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// 6 shifts x 2 loads, 3 slots, 4 samples: a tread patch everywhere on the right wheel, a flange patch from the
// fourth shift on, the left wheel failed at one case.
Table synthetic_table() {
  Table t;
  t.lateral_displacement_m = {-2e-3, -1e-3, 0.0, 1e-3, 2e-3, 3e-3};
  t.second_axis_name = "vertical_load_N";
  t.second_axis_units = "N";
  t.second_axis = {50e3, 80e3};
  t.n_slots = 3;
  t.strip_samples = 4;
  t.allocate();
  for (std::size_t i = 0; i < t.n_dy(); ++i)
    for (std::size_t j = 0; j < t.n_second(); ++j) {
      t.roll_rad[i * t.n_second() + j] = 1e-4 * static_cast<double>(i);
      for (std::size_t wheel = 0; wheel < kWheels; ++wheel) {  // the least model's choices (ladder widths)
        t.method[t.wheel_index(i, j, wheel)] = static_cast<std::int8_t>(i % 2 == 0 ? 0 : 4);
        t.strip_width_m[t.wheel_index(i, j, wheel)] = 0.8e-3 / static_cast<double>(1u << (i % 4));
      }
      for (std::size_t wheel = 0; wheel < kWheels; ++wheel)
        for (std::size_t slot = 0; slot < 2; ++slot) {
          if (slot == 1 && i < 3) continue;
          if (wheel == 1 && i == 2 && j == 1) {
            t.status[t.wheel_index(i, j, wheel)] = CaseStatus::SlotOverflow;
            continue;
          }
          const std::size_t k = t.patch_index(i, j, wheel, slot);
          auto& p = t.patch;
          p.present[k] = 1;
          p.normal_force_N[k] = t.second_axis[j] * (slot ? 0.4 : 0.6);
          p.plane_angle_rad[k] = slot ? -1.0 : 0.02;
          p.force_vertical_N[k] = p.normal_force_N[k] * std::cos(p.plane_angle_rad[k]);
          p.force_lateral_N[k] = -p.normal_force_N[k] * std::sin(p.plane_angle_rad[k]);
          p.area_m2[k] = 1e-4;
          p.max_pressure_Pa[k] = 1e9;
          p.approach_m[k] = 5e-5;
          p.contact_angle_rad[k] = p.plane_angle_rad[k];
          p.s_origin_y_rail_m[k] = slot ? -0.03 : 0.001 * static_cast<double>(i);
          p.s_origin_z_rail_m[k] = slot ? 0.01 : 1e-5;
          p.y_wheel_m[k] = slot ? -0.04 : 0.0;
          p.y_rail_m[k] = p.s_origin_y_rail_m[k];
          p.y_cop_rail_m[k] = p.y_rail_m[k];
          p.rolling_radius_m[k] = 0.46;
          p.semi_axis_a_m[k] = 7e-3;
          p.semi_axis_b_m[k] = 5e-3;
          p.s_min_m[k] = -4e-3;
          p.s_max_m[k] = 4e-3;
          for (std::size_t s = 0; s < t.strip_samples; ++s) {
            p.strip_half_length_m[k * t.strip_samples + s] = s == 0 || s == 3 ? 0.0 : 6e-3;
            p.strip_peak_pressure_Pa[k * t.strip_samples + s] = s == 0 || s == 3 ? 0.0 : 9e8;
          }
        }
    }
  t.status[t.wheel_index(3, 0, 1)] = CaseStatus::UnderResolved;  // usable: its patches stay
  t.jumps = detect_jumps(t);
  t.text_attributes["generator"] = "ctab";
  t.text_attributes["note"] = "UTF-8: 0.1 µm — Zürich";
  t.number_attributes["youngs_modulus_Pa"] = 2.08e11;
  t.integer_attributes["threads"] = 2;
  return t;
}

const std::string& good_file() {
  static const std::string path = [] {
    const std::string p = temp_path("good.h5");
    const TableResult r = write_table(synthetic_table(), p);
    EXPECT_TRUE(r.ok()) << r.message;
    return p;
  }();
  return path;
}

// A copy of the good file, edited with the HDF5 C API, then read.
TableResult read_edited(const std::string& name, const std::function<void(hid_t)>& edit) {
  const std::string path = temp_path(name);
  std::filesystem::copy_file(good_file(), path, std::filesystem::copy_options::overwrite_existing);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  EXPECT_GE(file, 0);
  edit(file);
  H5Fclose(file);
  Table t;
  return read_table(path, t);
}

// Writes one element of a dataset in the dataset's own type (raw bytes: no conversion hides the value).
void poke(hid_t file, const char* dataset_path, hsize_t index, const void* value) {
  const hid_t dataset = H5Dopen2(file, dataset_path, H5P_DEFAULT);
  const hid_t type = H5Dget_type(dataset);
  const hid_t space = H5Dget_space(dataset);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank)), start(dims.size()), count(dims.size(), 1);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  for (std::size_t d = dims.size(); d-- > 0;) {
    start[d] = index % dims[d];
    index /= dims[d];
  }
  H5Sselect_hyperslab(space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
  const hsize_t one = 1;
  const hid_t memory_space = H5Screate_simple(1, &one, nullptr);
  EXPECT_GE(H5Dwrite(dataset, type, memory_space, space, H5P_DEFAULT, value), 0) << dataset_path;
  H5Sclose(memory_space);
  H5Sclose(space);
  H5Tclose(type);
  H5Dclose(dataset);
}

void replace_attribute(hid_t file, const char* name, hid_t file_type, hid_t memory_type, const void* value) {
  H5Adelete(file, name);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(file, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT);
  H5Awrite(attribute, memory_type, value);
  H5Aclose(attribute);
  H5Sclose(space);
}

void expect_failure(const TableResult& r, TableStatus status, std::initializer_list<const char*> words) {
  EXPECT_EQ(r.status, status) << r.message;
  for (const char* word : words)
    EXPECT_NE(r.message.find(word), std::string::npos) << "'" << word << "' not in: " << r.message;
}

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

}  // namespace

TEST(TableFormat, RoundTripKeepsEveryValue) {
  const Table t = synthetic_table();
  ASSERT_FALSE(t.jumps.empty());
  Table back;
  const TableResult r = read_table(good_file(), back);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(back.n_slots, 3u);
  EXPECT_EQ(back.strip_samples, 4u);
  EXPECT_EQ(back.second_axis_name, "vertical_load_N");
  EXPECT_EQ(back.second_axis_units, "N");
  EXPECT_TRUE(bitwise_equal(back.lateral_displacement_m, t.lateral_displacement_m));
  EXPECT_TRUE(bitwise_equal(back.second_axis, t.second_axis));
  EXPECT_TRUE(bitwise_equal(back.roll_rad, t.roll_rad));
  EXPECT_TRUE(bitwise_equal(back.status, t.status));
  EXPECT_TRUE(bitwise_equal(back.method, t.method));
  EXPECT_TRUE(bitwise_equal(back.strip_width_m, t.strip_width_m));
  EXPECT_TRUE(bitwise_equal(back.patch.present, t.patch.present));
  EXPECT_TRUE(bitwise_equal(back.patch.force_lateral_N, t.patch.force_lateral_N));
  EXPECT_TRUE(bitwise_equal(back.patch.force_vertical_N, t.patch.force_vertical_N));
  EXPECT_TRUE(bitwise_equal(back.patch.plane_angle_rad, t.patch.plane_angle_rad));
  EXPECT_TRUE(bitwise_equal(back.patch.s_origin_y_rail_m, t.patch.s_origin_y_rail_m));
  EXPECT_TRUE(bitwise_equal(back.patch.s_origin_z_rail_m, t.patch.s_origin_z_rail_m));
  EXPECT_TRUE(bitwise_equal(back.patch.strip_peak_pressure_Pa, t.patch.strip_peak_pressure_Pa));
  ASSERT_EQ(back.jumps.size(), t.jumps.size());
  for (std::size_t i = 0; i < t.jumps.size(); ++i) {
    EXPECT_EQ(back.jumps[i].i_dy, t.jumps[i].i_dy);
    EXPECT_EQ(back.jumps[i].slot, t.jumps[i].slot);
    EXPECT_EQ(back.jumps[i].wheel, t.jumps[i].wheel);
    EXPECT_EQ(back.jumps[i].kind, t.jumps[i].kind);
  }
  EXPECT_EQ(back.text_attributes, t.text_attributes);
  EXPECT_EQ(back.number_attributes, t.number_attributes);
  EXPECT_EQ(back.integer_attributes, t.integer_attributes);
}

TEST(TableFormat, DetectJumpsFindsAppearAndMove) {
  Table t = synthetic_table();
  // Flange (slot 1) appears between dy[2] and dy[3] on both wheels at both loads, except the failed left case.
  std::size_t appears = 0;
  for (const Jump& j : t.jumps) appears += j.kind == JumpKind::Appears && j.slot == 1 && j.i_dy == 2;
  EXPECT_EQ(appears, 4u);
  // Moving the tread contact point by 1.5 mm between dy[4] and dy[5] (threshold max(1 mm, 10 steps) = 10 mm here): no
  // jump.
  const std::size_t k = t.patch_index(5, 0, 0, 0);
  t.patch.y_rail_m[k] += 1.5e-3;
  EXPECT_EQ(detect_jumps(t).size(), t.jumps.size());
  t.patch.y_rail_m[k] += 10e-3;
  const auto jumps = detect_jumps(t);
  ASSERT_EQ(jumps.size(), t.jumps.size() + 1);
  bool moved = false;
  for (const Jump& j : jumps)
    moved |= j.kind == JumpKind::Moves && j.i_dy == 4 && j.slot == 0 && j.wheel == 0 && j.i_second == 0;
  EXPECT_TRUE(moved);
}

// Tables written before /wheels/method and /wheels/strip_width_m existed, and before under-resolved (2) was
// appended to the status enum, still read: the method reads as not recorded, the width as 0.
TEST(TableFormat, OlderTableWithoutMethodDatasetsAndUnderResolvedReads) {
  const std::string path = temp_path("older.h5");
  Table older = synthetic_table();
  older.status[older.wheel_index(3, 0, 1)] = CaseStatus::Converged;
  ASSERT_TRUE(write_table(older, path).ok());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(H5Ldelete(file, "/wheels/method", H5P_DEFAULT), 0);
  ASSERT_GE(H5Ldelete(file, "/wheels/strip_width_m", H5P_DEFAULT), 0);
  ASSERT_GE(H5Ldelete(file, "/wheels/status", H5P_DEFAULT), 0);
  const hid_t type = H5Tenum_create(H5T_NATIVE_INT8);  // the status enum as schema 2 had it: values -6 .. 1
  for (int v = kCaseStatusMin; v <= 1; ++v) {
    const auto value = static_cast<std::int8_t>(v);
    H5Tenum_insert(type, case_status_name(static_cast<CaseStatus>(v)), &value);
  }
  const hsize_t dims[3] = {older.n_dy(), older.n_second(), kWheels};
  const hid_t space = H5Screate_simple(3, dims, nullptr);
  const hid_t dataset = H5Dcreate2(file, "/wheels/status", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, older.status.data()), 0);
  H5Dclose(dataset);
  H5Sclose(space);
  H5Tclose(type);
  H5Fclose(file);
  Table back;
  const TableResult r = read_table(path, back);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(bitwise_equal(back.status, older.status));
  ASSERT_EQ(back.method.size(), older.status.size());
  for (std::size_t w = 0; w < back.method.size(); ++w) {
    EXPECT_EQ(back.method[w], kMethodNotRecorded);
    EXPECT_EQ(back.strip_width_m[w], 0.0);
  }
}

TEST(TableFormat, MethodOutOfRangeIsRefused) {
  Table t = synthetic_table();
  t.method[1] = 5;
  const std::string path = temp_path("bad_method.h5");
  const TableResult written = write_table(t, path);
  Table back;
  const TableResult r = written.ok() ? read_table(path, back) : written;
  EXPECT_EQ(r.status, TableStatus::InvalidContent) << r.message;
  EXPECT_NE(r.message.find("/wheels/method"), std::string::npos) << r.message;
}

TEST(TableFormat, StatusIsAnEnumWithTheCaseStatusNames) {
  const hid_t file = H5Fopen(good_file().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t dataset = H5Dopen2(file, "/wheels/status", H5P_DEFAULT);
  const hid_t type = H5Dget_type(dataset);
  EXPECT_EQ(H5Tget_class(type), H5T_ENUM);
  for (int v = kCaseStatusMin; v <= kCaseStatusMax; ++v) {
    const auto value = static_cast<std::int8_t>(v);
    char name[64] = {};
    ASSERT_GE(H5Tenum_nameof(type, &value, name, sizeof name), 0) << v;
    EXPECT_STREQ(name, case_status_name(static_cast<CaseStatus>(v)));
  }
  EXPECT_STREQ(case_status_name(static_cast<CaseStatus>(7)), "unknown");
  H5Tclose(type);
  H5Dclose(dataset);
  // Strings are UTF-8, integer attributes integers.
  const hid_t attribute = H5Aopen(file, "note", H5P_DEFAULT);
  const hid_t text_type = H5Aget_type(attribute);
  EXPECT_EQ(H5Tget_cset(text_type), H5T_CSET_UTF8);
  H5Tclose(text_type);
  H5Aclose(attribute);
  for (const char* name : {"schema_version", "strip_samples", "n_slots", "threads"}) {
    const hid_t a = H5Aopen(file, name, H5P_DEFAULT);
    const hid_t t = H5Aget_type(a);
    EXPECT_EQ(H5Tget_class(t), H5T_INTEGER) << name;
    H5Tclose(t);
    H5Aclose(a);
  }
  H5Fclose(file);
}

TEST(TableFormat, SameTableSameBytesAndEmptyJumps) {
  Table t = synthetic_table();
  t.jumps.clear();  // a 0-row /jumps dataset
  const std::string a = temp_path("a.h5"), b = temp_path("b.h5");
  ASSERT_TRUE(write_table(t, a).ok());
  ASSERT_TRUE(write_table(t, b).ok());
  EXPECT_TRUE(file_bytes(a) == file_bytes(b));
  Table back;
  const TableResult r = read_table(a, back);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(back.jumps.empty());
}

TEST(TableFormat, CorruptContentsAreRejectedWithFileDatasetAndIndex) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), negative = -5.0, stray = 1.0;
  const std::int8_t status7 = 7;
  const std::uint8_t presence7 = 7;
  // Index of (i_dy 1, i_2 0, wheel 0, slot 0) = 4 * ... in the per-slot arrays: ((1*2+0)*2+0)*3+0 = 12.
  expect_failure(read_edited("nan.h5", [&](hid_t f) { poke(f, "/patches/normal_force_N", 12, &nan); }),
                 TableStatus::InvalidContent,
                 {"tables_nan.h5", "/patches/normal_force_N", "i_dy=1, i_2=0, wheel=0, slot=0", "finite"});
  expect_failure(read_edited("negative.h5", [&](hid_t f) { poke(f, "/patches/normal_force_N", 12, &negative); }),
                 TableStatus::InvalidContent, {"/patches/normal_force_N", "i_dy=1", "> 0"});
  expect_failure(read_edited("negative_strip.h5",
                             [&](hid_t f) { poke(f, "/patches/strip_peak_pressure_Pa", 12 * 4 + 1, &negative); }),
                 TableStatus::InvalidContent, {"/patches/strip_peak_pressure_Pa", "sample=1", ">= 0"});
  expect_failure(read_edited("status7.h5", [&](hid_t f) { poke(f, "/wheels/status", 3, &status7); }),
                 TableStatus::InvalidContent, {"/wheels/status", "i_dy=0, i_2=1, wheel=1", "unknown case status 7"});
  expect_failure(read_edited("presence7.h5", [&](hid_t f) { poke(f, "/patches/present", 12, &presence7); }),
                 TableStatus::InvalidContent, {"/patches/present", "presence 7"});
  // Slot 2 is empty everywhere: a value there is corruption.
  expect_failure(read_edited("stray.h5", [&](hid_t f) { poke(f, "/patches/area_m2", 14, &stray); }),
                 TableStatus::InvalidContent, {"/patches/area_m2", "slot=2", "empty slot"});
  // A patch in a failed case.
  const std::uint8_t one = 1;
  expect_failure(read_edited("failed_with_patch.h5",
                             [&](hid_t f) {
                               poke(f, "/patches/present", ((2 * 2 + 1) * 2 + 1) * 3 + 2,
                                    &one);  // also checked before: area 0 there
                             }),
                 TableStatus::InvalidContent, {"/patches/"});
  const std::uint32_t far = 99;
  expect_failure(read_edited("jump_index.h5",
                             [&](hid_t f) {
                               const hid_t d = H5Dopen2(f, "/jumps", H5P_DEFAULT);
                               const hid_t memory = H5Tcreate(H5T_COMPOUND, sizeof far);
                               H5Tinsert(memory, "i_dy", 0, H5T_NATIVE_UINT32);
                               const hid_t space = H5Dget_space(d);
                               const hsize_t start = 0, count = 1;
                               H5Sselect_hyperslab(space, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
                               const hid_t memory_space = H5Screate_simple(1, &count, nullptr);
                               H5Dwrite(d, memory, memory_space, space, H5P_DEFAULT, &far);
                               H5Sclose(memory_space);
                               H5Sclose(space);
                               H5Tclose(memory);
                               H5Dclose(d);
                             }),
                 TableStatus::InvalidContent, {"/jumps[0]"});
}

// The dy axis may be adaptive (steps down to tables::kMinDyStep = 0.1 um, a located jump's cell), never repeat or go
// backwards.
TEST(TableFormat, RefinedDyAxisReadsAndBadOnesAreRejected) {
  // dy[4] of -2 ... 3 mm in 1 mm steps
  const double refined = 1.5e-3, located = 1e-3 + 1e-7, repeated = 1e-3, too_fine = 1e-3 + 0.5e-7;
  EXPECT_TRUE(read_edited("refined.h5", [&](hid_t f) { poke(f, "/axes/lateral_displacement_m", 4, &refined); }).ok());
  EXPECT_TRUE(read_edited("located.h5", [&](hid_t f) { poke(f, "/axes/lateral_displacement_m", 4, &located); }).ok());
  expect_failure(read_edited("repeated.h5", [&](hid_t f) { poke(f, "/axes/lateral_displacement_m", 4, &repeated); }),
                 TableStatus::InvalidContent, {"/axes/lateral_displacement_m[4]", "strictly increasing"});
  expect_failure(read_edited("too_fine.h5", [&](hid_t f) { poke(f, "/axes/lateral_displacement_m", 4, &too_fine); }),
                 TableStatus::InvalidContent, {"/axes/lateral_displacement_m[4]", "finer than 1e-7 m"});
}

TEST(TableFormat, BadAttributesAreRejectedBeforeAllocating) {
  const std::int64_t huge = 200000, zero = 0, one = 1;
  const double one_and_a_half = 1.5, one_float = 1.0;
  expect_failure(read_edited("samples.h5",
                             [&](hid_t f) {
                               replace_attribute(f, "strip_samples", H5T_STD_I64LE, H5T_NATIVE_INT64, &huge);
                             }),
                 TableStatus::InvalidContent, {"tables_samples.h5", "strip_samples = 200000", "[2, 4096]"});
  expect_failure(read_edited("slots.h5",
                             [&](hid_t f) { replace_attribute(f, "n_slots", H5T_STD_I64LE, H5T_NATIVE_INT64, &zero); }),
                 TableStatus::InvalidContent, {"n_slots = 0"});
  expect_failure(read_edited("float_samples.h5",
                             [&](hid_t f) {
                               replace_attribute(f, "strip_samples", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                                                 &one_and_a_half);
                             }),
                 TableStatus::InvalidContent, {"strip_samples", "integer"});
  expect_failure(read_edited("version15.h5",
                             [&](hid_t f) {
                               replace_attribute(f, "schema_version", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                                                 &one_and_a_half);
                             }),
                 TableStatus::InvalidContent, {"schema_version", "1.5", "integer"});
  for (const bool as_float : {true, false}) {
    const auto r = read_edited("schema1.h5", [&](hid_t f) {
      if (as_float)
        replace_attribute(f, "schema_version", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &one_float);  // as schema 1 wrote it
      else replace_attribute(f, "schema_version", H5T_STD_I64LE, H5T_NATIVE_INT64, &one);
    });
    expect_failure(r, TableStatus::WrongSchemaVersion,
                   {"schema 1 table: regenerate it with this ctab: ctab generate CONFIG -o FILE"});
  }
  const std::int64_t three = 3;
  expect_failure(read_edited("version3.h5",
                             [&](hid_t f) {
                               replace_attribute(f, "schema_version", H5T_STD_I64LE, H5T_NATIVE_INT64, &three);
                             }),
                 TableStatus::WrongSchemaVersion, {"schema version 3"});
}

TEST(TableFormat, MissingAndMisshapenDatasets) {
  expect_failure(read_edited("missing.h5", [](hid_t f) { H5Ldelete(f, "/patches/plane_angle_rad", H5P_DEFAULT); }),
                 TableStatus::MissingDataset, {"/patches/plane_angle_rad"});
  expect_failure(read_edited("missing_jumps.h5", [](hid_t f) { H5Ldelete(f, "/jumps", H5P_DEFAULT); }),
                 TableStatus::MissingDataset, {"/jumps"});
  expect_failure(read_edited("shape.h5",
                             [](hid_t f) {
                               H5Ldelete(f, "/patches/force_lateral_N", H5P_DEFAULT);
                               const hsize_t dims[4] = {6, 2, 2, 4};
                               const hid_t space = H5Screate_simple(4, dims, nullptr);
                               H5Dclose(H5Dcreate2(f, "/patches/force_lateral_N", H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                                   H5P_DEFAULT, H5P_DEFAULT));
                               H5Sclose(space);
                             }),
                 TableStatus::WrongShape, {"/patches/force_lateral_N", "(6, 2, 2, 4)", "expected (6, 2, 2, 3)"});
  Table t;
  EXPECT_EQ(read_table(temp_path("does_not_exist.h5"), t).status, TableStatus::CannotOpen);
}

TEST(TableFormat, WriteIsAtomic) {
  Table broken = synthetic_table();
  broken.patch.force_vertical_N.pop_back();
  const std::string path = temp_path("broken.h5");
  std::filesystem::remove(path);
  EXPECT_EQ(write_table(broken, path).status, TableStatus::WriteFailed);
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(temporary_path(path)));
}

// A jump whose i_dy is 0xFFFFFFFF: i_dy + 1 wraps to 0 in 32 bits, so a check written as i_dy + 1 < n_dy would let
// it index the dy axis far out of range.
TEST(TableFormat, JumpCellIndexThatWrapsIn32BitsIsRefused) {
  const std::uint32_t wrapping = 0xFFFFFFFFu;
  expect_failure(read_edited("jump_wraps.h5",
                             [&](hid_t f) {
                               const hid_t d = H5Dopen2(f, "/jumps", H5P_DEFAULT);
                               const hid_t memory = H5Tcreate(H5T_COMPOUND, sizeof wrapping);
                               H5Tinsert(memory, "i_dy", 0, H5T_NATIVE_UINT32);
                               const hid_t space = H5Dget_space(d);
                               const hsize_t start = 0, count = 1;
                               H5Sselect_hyperslab(space, H5S_SELECT_SET, &start, nullptr, &count, nullptr);
                               const hid_t memory_space = H5Screate_simple(1, &count, nullptr);
                               EXPECT_GE(H5Dwrite(d, memory, memory_space, space, H5P_DEFAULT, &wrapping), 0);
                               H5Sclose(memory_space);
                               H5Sclose(space);
                               H5Tclose(memory);
                               H5Dclose(d);
                             }),
                 TableStatus::InvalidContent, {"/jumps[0]", "i_dy"});
  EXPECT_FALSE(cell_in_range(0xFFFFFFFFu, 6));
  EXPECT_TRUE(cell_in_range(4, 6));
  EXPECT_FALSE(cell_in_range(5, 6));
  EXPECT_FALSE(cell_in_range(0, 1));
}

// The one size limit (kMaxTableBytes), from the axis lengths and attributes, before anything is allocated; the
// writer refuses what no reader would read.
TEST(TableFormat, TablesBeyondTheSizeLimitAreRefused) {
  const std::int64_t samples = 4096;
  expect_failure(read_edited("huge.h5",
                             [&](hid_t f) {
                               replace_attribute(f, "strip_samples", H5T_STD_I64LE, H5T_NATIVE_INT64, &samples);
                               H5Ldelete(f, "/axes/lateral_displacement_m", H5P_DEFAULT);
                               const hsize_t n = hsize_t{1} << 20;
                               const hid_t space = H5Screate_simple(1, &n, nullptr);
                               H5Dclose(H5Dcreate2(f, "/axes/lateral_displacement_m", H5T_IEEE_F64LE, space,
                                                   H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
                               H5Sclose(space);
                             }),
                 TableStatus::InvalidContent, {"GiB in memory", "limit 2.0"});
  EXPECT_GT(table_bytes(1 << 20, 1, 3, 4096), kMaxTableBytes);
  Table big;
  big.lateral_displacement_m.assign(40000, 0.0);
  big.second_axis.assign(1, 1.0);
  big.n_slots = 16;
  big.strip_samples = 4096;  // 40000 x 2 x 16 x 8212 x 8 bytes: 84 GB declared, nothing allocated
  const TableResult written = write_table(big, temp_path("too_big.h5"));
  expect_failure(written, TableStatus::WriteFailed, {"GiB in memory", "limit"});
  EXPECT_FALSE(std::filesystem::exists(temp_path("too_big.h5")));
}

// /axes/cell_error (an adaptive axis): kept bit for bit; a table without it (written by a fixed-axis generator, or
// before the dataset existed) reads with an empty Table::cell_error; values below 0 other than -1 are refused.
TEST(TableFormat, CellErrorRoundTripAndTablesWithoutIt) {
  Table without;
  const TableResult plain = read_table(good_file(), without);
  ASSERT_TRUE(plain.ok()) << plain.message;
  EXPECT_TRUE(without.cell_error.empty());

  Table t = synthetic_table();
  t.cell_error.resize((t.n_dy() - 1) * t.n_second() * kCellErrorQuantities);
  for (std::size_t i = 0; i < t.cell_error.size(); ++i) t.cell_error[i] = 1e-4 * static_cast<double>(i);
  t.cell_error[5] = kCellNotMeasured;
  for (std::size_t q = 0; q < kCellErrorQuantities; ++q) t.number_attributes[kToleranceAttributes[q]] = 0.005;
  const std::string path = temp_path("cell_error.h5");
  ASSERT_TRUE(write_table(t, path).ok());
  Table back;
  const TableResult r = read_table(path, back);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(bitwise_equal(back.cell_error, t.cell_error));
  EXPECT_EQ(back.number_attributes, t.number_attributes);

  t.cell_error[7] = -0.5;
  const std::string bad = temp_path("cell_error_bad.h5");
  ASSERT_TRUE(write_table(t, bad).ok());
  Table refused;
  expect_failure(read_table(bad, refused), TableStatus::InvalidContent, {"/axes/cell_error[", "not measured"});
}

// The located jumps of an adaptive axis: only in cells of at most kJumpCellWidth_m not measured; detect_jumps'
// threshold rule for tables without cell_error.
TEST(TableFormat, LocatedJumpsOnlyInNarrowUnmeasuredCells) {
  Table t = synthetic_table();  // the flange patch appears between dy[2] and dy[3] (1 mm apart)
  EXPECT_FALSE(table_jumps(t).empty());
  t.cell_error.assign((t.n_dy() - 1) * t.n_second() * kCellErrorQuantities, 0.0);
  EXPECT_TRUE(table_jumps(t).empty()) << "a 1 mm cell is never a located jump";
  t.lateral_displacement_m = {-2e-3, -1e-3, 0.0, 0.5e-6, 2e-3, 3e-3};
  for (std::size_t j = 0; j < t.n_second(); ++j)
    for (std::size_t q = 0; q < kCellErrorQuantities; ++q)
      t.cell_error[(2 * t.n_second() + j) * kCellErrorQuantities + q] = kCellNotMeasured;
  const std::vector<Jump> jumps = table_jumps(t);
  ASSERT_FALSE(jumps.empty());
  for (const Jump& j : jumps) {
    EXPECT_EQ(j.i_dy, 2u);
    EXPECT_EQ(j.kind, JumpKind::Appears);
  }
}
