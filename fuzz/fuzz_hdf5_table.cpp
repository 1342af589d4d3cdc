// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: ctab's HDF5 table reader behind the trust boundary (docs/fuzzing.md). Raw bytes never reach
// libhdf5 (which may crash on a damaged file: outside the boundary). The input is decoded into a well-formed HDF5
// file instead: a small table written by ctab's writer, then edits of its values (any double, status, presence or
// method byte), its /jumps rows (any index, dy or kind), its root attributes (any name, type or value) and its
// datasets (removed, or replaced by one of another shape or element type). The reader, its validation and the
// lookup's load must refuse or accept that file cleanly, and a table that loads must answer every query.
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <string>
#include <vector>

#include "ctab/lookup/ctab_lookup_hdf5.h"
#include "ctab/tables/table.hpp"
#include "fuzz_file.hpp"
#include "hdf5_types.hpp"
#include "schema_fields.hpp"
#include "table_queries.hpp"

namespace {

namespace tables = ctab::tables;
namespace detail = ctab::tables::detail;
using detail::Handle;

constexpr int kMostEdits = 64;

double any_double(FuzzedDataProvider& in) {
  static constexpr double kSpecial[] = {0.0, -0.0, 1.0, -1.0, 1e-3, 5e4, 1e308, -1e308, 4.9e-324, 2.2e-308,
                                        1e-12, 3.5e38, __builtin_inf(), -__builtin_inf(), __builtin_nan("")};
  if (in.ConsumeBool()) return in.PickValueInArray(kSpecial);
  return in.ConsumeFloatingPoint<double>();
}

// A table that loads: n_dy x n_second cases, no patches, every case converged.
tables::Table base_table(FuzzedDataProvider& in) {
  tables::Table t;
  const std::size_t n_dy = in.ConsumeIntegralInRange<std::size_t>(1, 6);
  for (std::size_t i = 0; i < n_dy; ++i) t.lateral_displacement_m.push_back(-5e-3 + 1e-3 * static_cast<double>(i));
  static const char* const kAxes[] = {"vertical_load_N", "normal_load_N", "approach_m", "vertical_load_kN"};
  t.second_axis_name = in.PickValueInArray(kAxes);
  const bool approach = t.second_axis_name == "approach_m";
  t.second_axis_units = approach != in.ConsumeBool() ? "m" : "N";  // the wrong unit now and then
  const std::size_t n_second = in.ConsumeIntegralInRange<std::size_t>(1, 4);
  for (std::size_t k = 0; k < n_second; ++k)
    t.second_axis.push_back(approach ? 1e-5 * static_cast<double>(k + 1) : 5e4 + 1e4 * static_cast<double>(k));
  t.n_slots = in.ConsumeIntegralInRange<std::size_t>(1, 4);
  t.strip_samples = in.ConsumeIntegralInRange<std::size_t>(2, 5);
  t.allocate();
  t.integer_attributes[tables::kCompressionLevelAttribute] = in.ConsumeIntegralInRange<std::int64_t>(-1, 10);
  return t;
}

// One element of one schema array set to any value of its type.
void edit_value(FuzzedDataProvider& in, tables::Table& t) {
  const std::vector<detail::Field> fields = detail::schema_fields(t);
  const detail::Field& f = fields[in.ConsumeIntegralInRange<std::size_t>(0, fields.size() - 1)];
  if (f.size() == 0) return;
  const std::size_t i = in.ConsumeIntegralInRange<std::size_t>(0, f.size() - 1);
  if (f.doubles != nullptr) (*f.doubles)[i] = any_double(in);
  if (f.bytes != nullptr) (*f.bytes)[i] = in.ConsumeIntegral<std::uint8_t>();
  if (f.int8s != nullptr) (*f.int8s)[i] = in.ConsumeIntegral<std::int8_t>();
  if (f.statuses != nullptr) (*f.statuses)[i] = static_cast<tables::CaseStatus>(in.ConsumeIntegral<std::int8_t>());
}

// A patch made present with every quantity positive (so that edits reach tables that hold patches).
void add_patch(FuzzedDataProvider& in, tables::Table& t) {
  const std::size_t i = in.ConsumeIntegralInRange<std::size_t>(0, t.patch.present.size() - 1);
  const double value = in.PickValueInArray({1e-3, 1.0, 1e4});
  t.patch.present[i] = 1;
  for (const detail::Field& f : detail::schema_fields(t)) {
    if (!f.patch || f.doubles == nullptr) continue;
    const std::size_t per = f.extent == detail::Extent::PerSample ? t.strip_samples : 1;
    for (std::size_t k = 0; k < per; ++k) (*f.doubles)[i * per + k] = value;
  }
}

// A /jumps row: mostly within the axes, sometimes any index (0xFFFFFFFF included) or any dy.
detail::JumpRecord any_jump(FuzzedDataProvider& in, const tables::Table& t) {
  detail::JumpRecord r{};
  const bool wild = in.ConsumeBool();
  const auto index = [&](std::size_t n) {
    return wild ? in.PickValueInArray<std::uint32_t>({0u, 1u, 0x7FFFFFFFu, 0xFFFFFFFEu, 0xFFFFFFFFu,
                                                       in.ConsumeIntegral<std::uint32_t>()})
                : in.ConsumeIntegralInRange<std::uint32_t>(0, static_cast<std::uint32_t>(n));
  };
  r.i_second = index(t.n_second() - 1);
  r.wheel = static_cast<std::uint8_t>(index(tables::kWheels - 1));
  r.slot = static_cast<std::uint8_t>(index(t.n_slots - 1));
  r.i_dy = index(t.n_dy() >= 2 ? t.n_dy() - 2 : 0);
  const bool on_axis = r.i_dy + std::size_t{1} < t.n_dy() && in.ConsumeBool();
  r.dy_low_m = on_axis ? t.lateral_displacement_m[r.i_dy] : any_double(in);
  r.dy_high_m = on_axis ? t.lateral_displacement_m[r.i_dy + 1] : any_double(in);
  r.kind = in.ConsumeBool() ? in.ConsumeIntegralInRange<std::uint8_t>(1, 3) : in.ConsumeIntegral<std::uint8_t>();
  return r;
}

void write_jumps(hid_t file, const std::vector<detail::JumpRecord>& rows) {
  H5Ldelete(file, detail::kJumpsPath, H5P_DEFAULT);
  const hsize_t n = rows.size();
  const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  const Handle file_type(detail::make_jump_file_type(), H5Tclose);
  const Handle kind(detail::make_jump_kind_type(), H5Tclose);
  const Handle memory(detail::make_jump_type(kind.get()), H5Tclose);
  const Handle dataset(H5Dcreate2(file, detail::kJumpsPath, file_type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                                  H5P_DEFAULT),
                       H5Dclose);
  if (n > 0) H5Dwrite(dataset.get(), memory.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data());
}

// A root attribute of the schema (or another name) replaced by a scalar of any type, or by a 2-element array.
void edit_attribute(FuzzedDataProvider& in, hid_t file) {
  static const char* const kNames[] = {"schema_version", "strip_samples", "n_slots", "second_axis_name",
                                       "compression_level", "created_utc", "poisson_ratio"};
  const char* name = in.PickValueInArray(kNames);
  const Handle root(H5Gopen2(file, "/", H5P_DEFAULT), H5Gclose);
  H5Adelete(root.get(), name);
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0: static_cast<void>(detail::write_integer_attribute(root.get(), name, in.ConsumeIntegral<std::int64_t>())); break;
    case 1: static_cast<void>(detail::write_number_attribute(root.get(), name, any_double(in))); break;
    case 2: static_cast<void>(detail::write_text_attribute(root.get(), name, in.ConsumeRandomLengthString(64))); break;
    default: {
      const hsize_t two = 2;
      const std::int64_t values[2] = {2, 2};
      const Handle space(H5Screate_simple(1, &two, nullptr), H5Sclose);
      const Handle a(H5Acreate2(root.get(), name, H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
      H5Awrite(a.get(), H5T_NATIVE_INT64, values);
    }
  }
}

// A dataset of the schema (or /jumps) removed, or replaced by one of any small shape and another element type.
void edit_dataset(FuzzedDataProvider& in, hid_t file, tables::Table& t) {
  const std::vector<detail::Field> fields = detail::schema_fields(t);
  const std::size_t pick = in.ConsumeIntegralInRange<std::size_t>(0, fields.size());
  const char* path = pick < fields.size() ? fields[pick].path : detail::kJumpsPath;
  H5Ldelete(file, path, H5P_DEFAULT);
  if (in.ConsumeBool()) return;
  const int rank = in.ConsumeIntegralInRange(0, 5);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  hsize_t count = 1;
  for (hsize_t& d : dims) count *= (d = in.ConsumeIntegralInRange<hsize_t>(0, 7));
  const hid_t types[] = {H5T_IEEE_F64LE, H5T_IEEE_F32LE, H5T_STD_I8LE, H5T_STD_U8LE, H5T_STD_I32LE, H5T_STD_I64BE};
  const hid_t type = in.PickValueInArray(types);
  const Handle space(rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, dims.data(), nullptr), H5Sclose);
  const Handle dataset(H5Dcreate2(file, path, type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  std::vector<double> values(count);
  for (double& v : values) v = any_double(in);
  if (count > 0) H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
}

// The edits that need the written file: /jumps, root attributes, datasets.
void edit_file(FuzzedDataProvider& in, const std::string& path, tables::Table& t) {
  std::vector<detail::JumpRecord> jumps;
  const int n_jumps = in.ConsumeIntegralInRange(0, 4);
  for (int j = 0; j < n_jumps; ++j) jumps.push_back(any_jump(in, t));
  const int edits = in.ConsumeIntegralInRange(0, 3);
  if (jumps.empty() && edits == 0) return;  // the writer's file as it is (an open costs a third of an execution)
  const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) return;
  write_jumps(file.get(), jumps);
  for (int e = 0; e < edits && in.remaining_bytes() > 0; ++e) {
    if (in.ConsumeBool())
      edit_attribute(in, file.get());
    else
      edit_dataset(in, file.get(), t);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  tables::Table table = base_table(in);
  const int edits = in.ConsumeIntegralInRange(0, kMostEdits);
  for (int e = 0; e < edits && in.remaining_bytes() > 0; ++e) {
    if (in.ConsumeIntegralInRange(0, 7) == 0)
      add_patch(in, table);
    else
      edit_value(in, table);
  }
  static const std::string path = ctab::fuzz::scratch_path(".h5");
  if (!tables::write_table(table, path).ok()) return 0;
  edit_file(in, path, table);
  ctab_open_options options{};
  options.interpolation = in.ConsumeBool() ? CTAB_PCHIP : CTAB_LINEAR;
  options.single_precision = in.ConsumeBool() ? 1 : 0;
  ctab_table* loaded = nullptr;
  if (ctab_table_open_hdf5(path.c_str(), &options, &loaded) == CTAB_OK) ctab::fuzz::query_everywhere(loaded);
  ctab_table_close(loaded);
  return 0;
}
