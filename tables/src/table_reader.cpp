// SPDX-License-Identifier: Apache-2.0
// Reads a schema-2 table: attributes and shapes are checked before anything is allocated from them, then the
// arrays are read and their contents validated (table_validation.cpp).
#include <cmath>
#include <cstdio>
#include <exception>
#include <set>

#include "ctab/tables/table.hpp"
#include "hdf5_types.hpp"
#include "schema_fields.hpp"
#include "table_validation.hpp"

namespace ctab::tables {

namespace {

using detail::Handle;


struct RootAttributes {
  std::map<std::string, std::string> text;
  std::map<std::string, double> number;
  std::map<std::string, std::int64_t> integer;
};

herr_t collect_attribute(hid_t object, const char* name, const H5A_info_t*, void* data) {
  auto& out = *static_cast<RootAttributes*>(data);
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  const Handle type(H5Aget_type(attribute.get()), H5Tclose);
  const Handle space(H5Aget_space(attribute.get()), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1) return 0;  // only scalars belong to the schema
  switch (H5Tget_class(type.get())) {
    case H5T_STRING: {
      std::string value;
      if (detail::read_text_attribute(attribute.get(), value)) out.text[name] = value;
      break;
    }
    case H5T_INTEGER: {
      std::int64_t value = 0;
      if (H5Aread(attribute.get(), H5T_NATIVE_INT64, &value) >= 0) out.integer[name] = value;
      break;
    }
    case H5T_FLOAT: {
      double value = 0.0;
      if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) >= 0) out.number[name] = value;
      break;
    }
    case H5T_ENUM: {  // booleans (h5py's FALSE/TRUE enum) arrive as the text "true" or "false"
      const Handle boolean(detail::make_bool_type(), H5Tclose);
      std::int8_t value = 0;
      if (detail::same_enum(type.get(), boolean.get()) && H5Aread(attribute.get(), type.get(), &value) >= 0)
        out.text[name] = value != 0 ? "true" : "false";
      break;
    }
    default: break;
  }
  return 0;
}

TableResult fail(TableStatus status, const std::string& message) { return {status, message}; }

TableResult check_schema_version(const RootAttributes& a, const std::string& path) {
  const std::string schema_1 = path + ": schema 1 table: regenerate it with this ctab: ctab generate CONFIG -o FILE";
  if (const auto f = a.number.find("schema_version"); f != a.number.end()) {
    if (f->second == 1.0) return fail(TableStatus::WrongSchemaVersion, schema_1);
    char value[32];
    std::snprintf(value, sizeof value, "%g", f->second);
    return fail(TableStatus::InvalidContent, path + ": attribute schema_version is the float " + value +
                                                 ": it must be an integer (this build reads 2)");
  }
  const auto i = a.integer.find("schema_version");
  if (i == a.integer.end())
    return fail(TableStatus::NotATable, path + ": no schema_version attribute: not a ctab table");
  if (i->second == 1) return fail(TableStatus::WrongSchemaVersion, schema_1);
  if (i->second != kSchemaVersion)
    return fail(TableStatus::WrongSchemaVersion, path + ": schema version " + std::to_string(i->second) +
                                                     ", this build reads version " + std::to_string(kSchemaVersion));
  return {};
}

// An integer root attribute within [low, high].
TableResult integer_in_range(const RootAttributes& a, const std::string& path, const char* name, std::int64_t low,
                             std::int64_t high, std::size_t& out) {
  const auto i = a.integer.find(name);
  if (i == a.integer.end())
    return fail(TableStatus::InvalidContent, path + ": root attribute " + name + " missing or not an integer");
  if (i->second < low || i->second > high)
    return fail(TableStatus::InvalidContent, path + ": root attribute " + name + " = " + std::to_string(i->second) +
                                                 " is outside [" + std::to_string(low) + ", " + std::to_string(high) +
                                                 "]");
  out = static_cast<std::size_t>(i->second);
  return {};
}

TableResult read_root(hid_t file, const std::string& path, Table& table) {
  RootAttributes a;
  const Handle root(H5Gopen2(file, "/", H5P_DEFAULT), H5Gclose);
  hsize_t index = 0;
  if (!root.valid() || H5Aiterate2(root.get(), H5_INDEX_NAME, H5_ITER_NATIVE, &index, collect_attribute, &a) < 0)
    return fail(TableStatus::NotATable, path + ": cannot read the root attributes (truncated or damaged)");
  if (TableResult r = check_schema_version(a, path); !r.ok()) return r;
  if (TableResult r = integer_in_range(a, path, "strip_samples", 2, static_cast<std::int64_t>(kMaxStripSamples),
                                       table.strip_samples);
      !r.ok())
    return r;
  if (TableResult r = integer_in_range(a, path, "n_slots", 1, static_cast<std::int64_t>(kMaxSlots), table.n_slots);
      !r.ok())
    return r;
  table.second_axis_name = a.text["second_axis_name"];
  static const std::set<std::string> names = {"vertical_load_N", "normal_load_N", "approach_m"};
  if (names.count(table.second_axis_name) == 0)
    return fail(TableStatus::InvalidContent, path + ": root attribute second_axis_name '" + table.second_axis_name +
                                                 "' is not vertical_load_N, normal_load_N or approach_m");
  a.integer.erase("schema_version");
  a.integer.erase("strip_samples");
  a.integer.erase("n_slots");
  a.text.erase("second_axis_name");
  table.text_attributes = std::move(a.text);
  table.number_attributes = std::move(a.number);
  table.integer_attributes = std::move(a.integer);
  return {};
}

// Dimensions of a dataset, or a MissingDataset / NotATable result.
TableResult dataset_dims(hid_t file, const std::string& path, const char* name, std::vector<hsize_t>& dims) {
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0)
    return fail(TableStatus::MissingDataset, path + ": missing dataset " + name);
  const Handle dataset(H5Dopen2(file, name, H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) return fail(TableStatus::MissingDataset, path + ": missing dataset " + name);
  const Handle space(H5Dget_space(dataset.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) return fail(TableStatus::NotATable, path + ": cannot read the shape of " + name);
  dims.assign(static_cast<std::size_t>(rank), 0);
  if (H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    return fail(TableStatus::NotATable, path + ": cannot read the shape of " + name);
  return {};
}

std::string shape_text(const std::vector<hsize_t>& dims) {
  std::string text = "(";
  for (std::size_t i = 0; i < dims.size(); ++i) text += (i ? ", " : "") + std::to_string(dims[i]);
  return text + ")";
}

// Axis lengths from the axis datasets, then every dataset's shape and element type, and the total size:
// all before anything is allocated.
TableResult check_shapes(hid_t file, const std::string& path, Table& table) {
  hsize_t lengths[2] = {0, 0};
  const char* axes[2] = {"/axes/lateral_displacement_m", "/axes/second"};
  for (int i = 0; i < 2; ++i) {
    std::vector<hsize_t> dims;
    if (TableResult r = dataset_dims(file, path, axes[i], dims); !r.ok()) return r;
    if (dims.size() != 1 || dims[0] == 0 || dims[0] > static_cast<hsize_t>(kMaxAxisLength))
      return fail(TableStatus::WrongShape, path + ": " + axes[i] + " has shape " + shape_text(dims) +
                                               ": it must be 1-D with 1 to " + std::to_string(kMaxAxisLength) +
                                               " values");
    lengths[i] = dims[0];
  }
  const double bytes = table_bytes(static_cast<double>(lengths[0]), static_cast<double>(lengths[1]),
                                   static_cast<double>(table.n_slots), static_cast<double>(table.strip_samples));
  if (bytes > kMaxTableBytes)
    return fail(TableStatus::InvalidContent, path + ": the table would take " + std::to_string(bytes / (1u << 30)) +
                                                 " GiB in memory (limit " + std::to_string(kMaxTableBytes / (1u << 30)) +
                                                 " GiB, tables/README.md \"Limits\")");
  const Handle status_type(detail::make_case_status_type(), H5Tclose);
  const Handle method_type(detail::make_method_type(), H5Tclose);
  for (const detail::Field& f : detail::schema_fields(table)) {
    if (f.optional && H5Lexists(file, f.path, H5P_DEFAULT) <= 0) continue;  // an older table: filled on read
    const std::vector<hsize_t> want =
        detail::shape_of(f.extent, lengths[0], lengths[1], table.n_slots, table.strip_samples);
    std::vector<hsize_t> dims;
    if (TableResult r = dataset_dims(file, path, f.path, dims); !r.ok()) return r;
    if (dims != want)
      return fail(TableStatus::WrongShape,
                  path + ": dataset " + f.path + " has shape " + shape_text(dims) + ", expected " + shape_text(want));
    const Handle dataset(H5Dopen2(file, f.path, H5P_DEFAULT), H5Dclose);
    const Handle type(H5Dget_type(dataset.get()), H5Tclose);
    // /wheels/method: the method enum, or int8 (tables written before it was an enum).
    const bool byte = H5Tget_class(type.get()) == H5T_INTEGER && H5Tget_size(type.get()) == 1;
    const bool type_ok = f.element == detail::Element::Float64  ? H5Tget_class(type.get()) == H5T_FLOAT
                         : f.element == detail::Element::Presence ? byte
                         : f.element == detail::Element::Int8
                             ? byte || detail::same_enum(type.get(), method_type.get())
                             : detail::same_enum(type.get(), status_type.get());
    if (!type_ok)
      return fail(TableStatus::InvalidContent,
                  path + ": dataset " + f.path + " has the wrong element type (" +
                      (f.element == detail::Element::Status ? "expected the CaseStatus enum" : "see tables/README.md") +
                      ")");
  }
  table.lateral_displacement_m.assign(lengths[0], 0.0);
  table.second_axis.assign(lengths[1], 0.0);
  return {};
}

TableResult read_arrays(hid_t file, const std::string& path, Table& table) {
  for (const detail::Field& f : detail::schema_fields(table)) {
    if (f.optional && H5Lexists(file, f.path, H5P_DEFAULT) <= 0) {
      if (f.empty_when_missing) f.resize(0);
      f.fill_missing();
      continue;
    }
    if (f.empty_when_missing) {  // not allocated with the table: sized from its (checked) shape
      std::size_t count = 1;
      for (const hsize_t d : detail::shape_of(f.extent, table.n_dy(), table.n_second(), table.n_slots,
                                              table.strip_samples))
        count *= d;
      f.resize(count);
    }
    const Handle dataset(H5Dopen2(file, f.path, H5P_DEFAULT), H5Dclose);
    // Enums (status, method): read with the file's own type (checked equal to ours), so unknown values arrive
    // unchanged (HDF5 converts no enum to an integer).
    const Handle file_type(H5Dget_type(dataset.get()), H5Tclose);
    const bool enumeration = H5Tget_class(file_type.get()) == H5T_ENUM;
    const hid_t memory = f.element == detail::Element::Float64                ? H5T_NATIVE_DOUBLE
                         : f.element == detail::Element::Presence             ? H5T_NATIVE_UINT8
                         : f.element == detail::Element::Int8 && !enumeration ? H5T_NATIVE_INT8
                                                                              : file_type.get();
    if (f.size() > 0 && H5Dread(dataset.get(), memory, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.data()) < 0)
      return fail(TableStatus::NotATable, path + ": cannot read " + f.path + " (truncated or damaged)");
    if (f.extent == detail::Extent::SecondAxis) {
      const Handle units(H5Aopen(dataset.get(), "units", H5P_DEFAULT), H5Aclose);
      if (!units.valid() || !detail::read_text_attribute(units.get(), table.second_axis_units))
        return fail(TableStatus::InvalidContent, path + ": /axes/second has no units attribute");
      const std::string want = table.second_axis_name == "approach_m" ? "m" : "N";
      if (table.second_axis_units != want)
        return fail(TableStatus::InvalidContent, path + ": /axes/second has units '" + table.second_axis_units +
                                                     "', expected '" + want + "' for " + table.second_axis_name);
    }
  }
  return {};
}

TableResult read_jumps(hid_t file, const std::string& path, Table& table) {
  std::vector<hsize_t> dims;
  if (TableResult r = dataset_dims(file, path, detail::kJumpsPath, dims); !r.ok()) return r;
  const hsize_t most = static_cast<hsize_t>(table.cases() * kWheels * table.n_slots);
  if (dims.size() != 1 || dims[0] > most)
    return fail(TableStatus::WrongShape, path + ": /jumps has shape " + shape_text(dims) +
                                             ": expected 1-D with at most " + std::to_string(most) + " rows");
  const Handle dataset(H5Dopen2(file, detail::kJumpsPath, H5P_DEFAULT), H5Dclose);
  const Handle file_type(H5Dget_type(dataset.get()), H5Tclose);
  const Handle expected_kind(detail::make_jump_kind_type(), H5Tclose);
  const int kind_member = H5Tget_member_index(file_type.get(), "kind");
  const Handle kind(kind_member >= 0 ? H5Tget_member_type(file_type.get(), static_cast<unsigned>(kind_member)) : -1,
                    H5Tclose);
  if (H5Tget_class(file_type.get()) != H5T_COMPOUND || !kind.valid() ||
      !detail::same_enum(kind.get(), expected_kind.get()))
    return fail(TableStatus::InvalidContent, path + ": /jumps has the wrong element type (see tables/README.md)");
  std::vector<detail::JumpRecord> rows(dims[0]);
  const Handle memory(detail::make_jump_type(kind.get()), H5Tclose);  // kind read raw: unknown values arrive unchanged
  if (!rows.empty() && H5Dread(dataset.get(), memory.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data()) < 0)
    return fail(TableStatus::NotATable, path + ": cannot read /jumps (truncated or damaged)");
  table.jumps.clear();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const detail::JumpRecord& r = rows[i];
    if (!cell_in_range(r.i_dy, table.n_dy()) || r.dy_low_m != table.lateral_displacement_m[r.i_dy] ||
        r.dy_high_m != table.lateral_displacement_m[r.i_dy + 1])
      return fail(TableStatus::InvalidContent,
                  path + ": /jumps[" + std::to_string(i) + "]: i_dy or dy_low_m/dy_high_m do not match the dy axis");
    table.jumps.push_back({r.i_second, r.wheel, r.slot, r.i_dy, static_cast<JumpKind>(r.kind)});
  }
  return {};
}

TableResult read_file(hid_t file, const std::string& path, Table& table) {
  if (TableResult r = read_root(file, path, table); !r.ok()) return r;
  if (TableResult r = check_shapes(file, path, table); !r.ok()) return r;
  table.allocate();
  if (TableResult r = read_arrays(file, path, table); !r.ok()) return r;
  if (TableResult r = read_jumps(file, path, table); !r.ok()) return r;
  return detail::validate_contents(table, path);
}

}  // namespace

TableResult read_table(const std::string& path, Table& table) {
  detail::silence_hdf5_errors();
  table = Table{};
  if (FILE* probe = std::fopen(path.c_str(), "rb")) {
    std::fclose(probe);
  } else {
    return fail(TableStatus::CannotOpen, path + ": cannot open table file");
  }
  if (H5Fis_hdf5(path.c_str()) <= 0)
    return fail(TableStatus::NotATable, path + ": not an HDF5 contact table (or truncated)");
  const Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) return fail(TableStatus::NotATable, path + ": cannot be opened as HDF5 (truncated or damaged)");
  TableResult result;
  try {
    result = read_file(file.get(), path, table);
  } catch (const std::exception&) {  // a failed allocation (bad_alloc, length_error): the table fits, memory not
    result = fail(TableStatus::OutOfMemory, path + ": out of memory while reading the table");
  }
  if (!result.ok()) table = Table{};
  return result;
}

}  // namespace ctab::tables
