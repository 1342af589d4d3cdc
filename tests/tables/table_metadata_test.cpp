// SPDX-License-Identifier: Apache-2.0
// The table's self-description read with the HDF5 C API alone: dimension scales named dy, second, wheel, slot,
// sample on every array dataset (the HDF5 Dimension Scale Specification's attributes), /wheels/method an enum of the
// method names, dimensionless units "1", `mirrored` a boolean; and tables in the older forms (method int8, mirrored
// a sentence, units "-", no scales) still read with the same values.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstring>
#include <string>
#include <vector>

#include "ctab/tables/table.hpp"

using namespace ctab::tables;

namespace {

std::string temp_path(const std::string& name) { return ::testing::TempDir() + "metadata_" + name; }

// 3 shifts x 2 loads, 2 slots, 3 samples; one patch per wheel; methods mim1d and bem2d; mirrored.
Table small_table() {
  Table t;
  t.lateral_displacement_m = {-1e-3, 0.0, 1e-3};
  t.second_axis_name = "vertical_load_N";
  t.second_axis_units = "N";
  t.second_axis = {50e3, 80e3};
  t.n_slots = 2;
  t.strip_samples = 3;
  t.allocate();
  for (std::size_t i = 0; i < t.n_dy(); ++i)
    for (std::size_t j = 0; j < t.n_second(); ++j)
      for (std::size_t wheel = 0; wheel < kWheels; ++wheel) {
        t.method[t.wheel_index(i, j, wheel)] = static_cast<std::int8_t>(wheel == 0 ? 0 : 4);
        t.strip_width_m[t.wheel_index(i, j, wheel)] = 0.4e-3;
        const std::size_t k = t.patch_index(i, j, wheel, 0);
        auto& p = t.patch;
        p.present[k] = 1;
        p.normal_force_N[k] = p.force_vertical_N[k] = t.second_axis[j];
        p.area_m2[k] = 1e-4;
        p.max_pressure_Pa[k] = 1e9;
        p.rolling_radius_m[k] = 0.46;
        p.semi_axis_a_m[k] = 7e-3;
        p.semi_axis_b_m[k] = 5e-3;
        p.s_min_m[k] = -4e-3;
        p.s_max_m[k] = 4e-3;
        p.strip_half_length_m[k * t.strip_samples + 1] = 6e-3;
        p.strip_peak_pressure_Pa[k * t.strip_samples + 1] = 9e8;
      }
  t.text_attributes["mirrored"] = "true";
  return t;
}

const std::string& written_file() {
  static const std::string path = [] {
    const std::string p = temp_path("small.h5");
    const TableResult r = write_table(small_table(), p);
    EXPECT_TRUE(r.ok()) << r.message;
    return p;
  }();
  return path;
}

std::string read_string_attribute(hid_t object, const char* name) {
  const hid_t attribute = H5Aopen(object, name, H5P_DEFAULT);
  if (attribute < 0) return "<missing>";
  const hid_t type = H5Aget_type(attribute);
  std::string value;
  if (H5Tis_variable_str(type) > 0) {
    char* text = nullptr;
    H5Aread(attribute, type, &text);
    value = text != nullptr ? text : "";
    H5free_memory(text);
  } else {
    value.assign(H5Tget_size(type), '\0');
    H5Aread(attribute, type, value.data());
    value.resize(std::strlen(value.c_str()));
  }
  H5Tclose(type);
  H5Aclose(attribute);
  return value;
}

std::vector<std::string> labels_of(hid_t dataset) {
  const hid_t attribute = H5Aopen(dataset, "DIMENSION_LABELS", H5P_DEFAULT);
  if (attribute < 0) return {};
  const hid_t space = H5Aget_space(attribute);
  std::vector<char*> raw(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  const hid_t type = H5Aget_type(attribute);
  H5Aread(attribute, type, raw.data());
  std::vector<std::string> labels;
  for (char* text : raw) {
    labels.emplace_back(text != nullptr ? text : "");
    H5free_memory(text);
  }
  H5Tclose(type);
  H5Sclose(space);
  H5Aclose(attribute);
  return labels;
}

// The NAME of the one scale attached to each dimension of `dataset`, through DIMENSION_LIST's object references.
std::vector<std::string> scale_names_of(hid_t dataset) {
  const hid_t attribute = H5Aopen(dataset, "DIMENSION_LIST", H5P_DEFAULT);
  if (attribute < 0) return {};
  const hid_t space = H5Aget_space(attribute);
  std::vector<hvl_t> lists(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  const hid_t type = H5Tvlen_create(H5T_STD_REF_OBJ);
  H5Aread(attribute, type, lists.data());
  std::vector<std::string> names;
  for (const hvl_t& list : lists) {
    EXPECT_EQ(list.len, 1u);
    const hid_t scale = H5Rdereference2(dataset, H5P_DEFAULT, H5R_OBJECT, list.p);
    EXPECT_EQ(read_string_attribute(scale, "CLASS"), "DIMENSION_SCALE");
    names.push_back(read_string_attribute(scale, "NAME"));
    H5Dclose(scale);
  }
  H5Dvlen_reclaim(type, space, H5P_DEFAULT, lists.data());
  H5Tclose(type);
  H5Sclose(space);
  H5Aclose(attribute);
  return names;
}

}  // namespace

TEST(TableMetadata, EveryArrayDatasetHasNamedDimensionScales) {
  const hid_t file = H5Fopen(written_file().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const std::vector<std::string> patch = {"dy", "second", "wheel", "slot"};
  const struct {
    const char* path;
    std::vector<std::string> dims;
  } expected[] = {{"/cases/roll_rad", {"dy", "second"}},
                  {"/wheels/status", {"dy", "second", "wheel"}},
                  {"/wheels/method", {"dy", "second", "wheel"}},
                  {"/patches/present", patch},
                  {"/patches/normal_force_N", patch},
                  {"/patches/strip_peak_pressure_Pa", {"dy", "second", "wheel", "slot", "sample"}}};
  for (const auto& e : expected) {
    const hid_t dataset = H5Dopen2(file, e.path, H5P_DEFAULT);
    ASSERT_GE(dataset, 0) << e.path;
    EXPECT_EQ(labels_of(dataset), e.dims) << e.path;
    EXPECT_EQ(scale_names_of(dataset), e.dims) << e.path;
    H5Dclose(dataset);
  }
  // The axes are the scales themselves (labelled, nothing attached); the index scales hold their indices.
  const hid_t dy = H5Dopen2(file, "/axes/lateral_displacement_m", H5P_DEFAULT);
  EXPECT_EQ(labels_of(dy), std::vector<std::string>{"dy"});
  EXPECT_EQ(read_string_attribute(dy, "NAME"), "dy");
  EXPECT_LT(H5Aexists(dy, "DIMENSION_LIST"), 1);
  H5Dclose(dy);
  const hid_t wheel = H5Dopen2(file, "/axes/wheel", H5P_DEFAULT);
  std::uint8_t wheels[2] = {9, 9};
  ASSERT_GE(H5Dread(wheel, H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, wheels), 0);
  EXPECT_EQ(wheels[0], 0);
  EXPECT_EQ(wheels[1], 1);
  EXPECT_NE(read_string_attribute(wheel, "description").find("0 right wheel, 1 left wheel"), std::string::npos);
  H5Dclose(wheel);
  const hid_t jumps = H5Dopen2(file, "/jumps", H5P_DEFAULT);
  EXPECT_EQ(labels_of(jumps), std::vector<std::string>{"jump"});
  H5Dclose(jumps);
  H5Fclose(file);
}

TEST(TableMetadata, MethodIsAnEnumUnitsOneMirroredABoolean) {
  const hid_t file = H5Fopen(written_file().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t method = H5Dopen2(file, "/wheels/method", H5P_DEFAULT);
  const hid_t type = H5Dget_type(method);
  ASSERT_EQ(H5Tget_class(type), H5T_ENUM);
  const char* names[] = {"not_recorded", "mim1d", "hertz", "kp", "analyn", "bem2d"};
  for (int v = -1; v <= kMaxMethodValue; ++v) {
    const auto value = static_cast<std::int8_t>(v);
    char name[32] = {};
    ASSERT_GE(H5Tenum_nameof(type, &value, name, sizeof name), 0) << v;
    EXPECT_STREQ(name, names[v + 1]);
  }
  H5Tclose(type);
  EXPECT_EQ(read_string_attribute(method, "units"), "1");
  H5Dclose(method);
  for (const char* path : {"/wheels/status", "/patches/present", "/jumps", "/axes/sample"}) {
    const hid_t dataset = H5Dopen2(file, path, H5P_DEFAULT);
    EXPECT_EQ(read_string_attribute(dataset, "units"), "1") << path;
    H5Dclose(dataset);
  }
  const hid_t mirrored = H5Aopen(file, "mirrored", H5P_DEFAULT);
  const hid_t bool_type = H5Aget_type(mirrored);
  EXPECT_EQ(H5Tget_class(bool_type), H5T_ENUM);
  std::int8_t value = 0;
  ASSERT_GE(H5Aread(mirrored, bool_type, &value), 0);
  char name[8] = {};
  ASSERT_GE(H5Tenum_nameof(bool_type, &value, name, sizeof name), 0);
  EXPECT_STREQ(name, "TRUE");  // h5py's boolean: numpy.bool_ True
  H5Tclose(bool_type);
  H5Aclose(mirrored);
  H5Fclose(file);
  Table back;
  const TableResult r = read_table(written_file(), back);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(back.text_attributes["mirrored"], "true");
  EXPECT_EQ(back.method, small_table().method);
}

// A table in the form written before the metadata: method int8 with units "-", `mirrored` a sentence, no scales.
TEST(TableMetadata, OlderFormsReadWithTheSameValues) {
  const Table t = small_table();
  const std::string path = temp_path("older.h5");
  ASSERT_TRUE(write_table(t, path).ok());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(H5Ldelete(file, "/wheels/method", H5P_DEFAULT), 0);
  const hsize_t dims[3] = {t.n_dy(), t.n_second(), kWheels};
  const hid_t space = H5Screate_simple(3, dims, nullptr);
  const hid_t method = H5Dcreate2(file, "/wheels/method", H5T_STD_I8LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(H5Dwrite(method, H5T_NATIVE_INT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, t.method.data()), 0);
  H5Dclose(method);
  H5Sclose(space);
  const std::string sentence = "true: left wheel at dy = right wheel at -dy (mirror-image sides)";
  ASSERT_GE(H5Adelete(file, "mirrored"), 0);
  const hid_t text_type = H5Tcopy(H5T_C_S1);
  H5Tset_size(text_type, sentence.size() + 1);
  const hid_t scalar = H5Screate(H5S_SCALAR);
  const hid_t attribute = H5Acreate2(file, "mirrored", text_type, scalar, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(H5Awrite(attribute, text_type, sentence.c_str()), 0);
  H5Aclose(attribute);
  H5Sclose(scalar);
  H5Tclose(text_type);
  for (const char* scale : {"/axes/wheel", "/axes/slot", "/axes/sample"}) H5Ldelete(file, scale, H5P_DEFAULT);
  H5Fclose(file);
  Table back;
  const TableResult r = read_table(path, back);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(back.method, t.method);
  EXPECT_EQ(back.text_attributes["mirrored"], sentence);
  EXPECT_EQ(back.patch.normal_force_N, t.patch.normal_force_N);
}

TEST(TableMetadata, MethodEnumWithForeignNamesIsRefused) {
  const std::string path = temp_path("foreign_method.h5");
  const Table t = small_table();
  ASSERT_TRUE(write_table(t, path).ok());
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(H5Ldelete(file, "/wheels/method", H5P_DEFAULT), 0);
  const hid_t type = H5Tenum_create(H5T_STD_I8LE);
  const std::int8_t zero = 0, four = 4;
  H5Tenum_insert(type, "hertz", &zero);  // the names do not match the values
  H5Tenum_insert(type, "bem2d", &four);
  const hsize_t dims[3] = {t.n_dy(), t.n_second(), kWheels};
  const hid_t space = H5Screate_simple(3, dims, nullptr);
  const hid_t method = H5Dcreate2(file, "/wheels/method", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(H5Dwrite(method, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, t.method.data()), 0);
  H5Dclose(method);
  H5Sclose(space);
  H5Tclose(type);
  H5Fclose(file);
  Table back;
  const TableResult r = read_table(path, back);
  EXPECT_EQ(r.status, TableStatus::InvalidContent) << r.message;
  EXPECT_NE(r.message.find("/wheels/method"), std::string::npos) << r.message;
}
