// HDF5 reader and writer of contact tables (HDF5 C API; the only translation unit that includes hdf5.h).
#include "ctab/tables/table.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

namespace ctab::tables {

void Table::allocate() {
  const std::size_t cases = this->cases(), wheels = cases * kWheels, slots = wheels * kSlots;
  roll_rad.assign(cases, 0.0);
  rolling_radius_difference_m.assign(cases, 0.0);
  status.assign(wheels, 0);
  patch.present.assign(slots, 0);
  for (std::vector<double>* v : {&patch.normal_force_N, &patch.area_m2, &patch.max_pressure_Pa, &patch.approach_m,
                                 &patch.contact_angle_rad, &patch.y_wheel_m, &patch.y_rail_m, &patch.y_cop_rail_m,
                                 &patch.rolling_radius_m, &patch.semi_axis_a_m, &patch.semi_axis_b_m, &patch.s_min_m,
                                 &patch.s_max_m})
    v->assign(slots, 0.0);
  patch.strip_half_length_m.assign(slots * strip_samples, 0.0);
  patch.strip_peak_pressure_Pa.assign(slots * strip_samples, 0.0);
}

namespace {

// RAII for hid_t: one choke point that closes every handle.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  [[nodiscard]] hid_t get() const noexcept { return id_; }
  [[nodiscard]] bool valid() const noexcept { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void silence_hdf5_errors() {
  static const bool done = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)done;
}

// One dataset of the schema: its path, element type, shape, units and description, and where its data lives.
struct Field {
  const char* path;
  const char* units;
  const char* description;
  std::vector<hsize_t> shape;
  hid_t memory_type;
  void* data;
  std::size_t size;
  std::function<void(std::size_t)> resize;
};

template <class T>
Field field(const char* path, const char* units, const char* description, std::vector<hsize_t> shape, hid_t type,
            std::vector<T>& v) {
  return {path, units, description, std::move(shape), type, v.data(), v.size(), [&v](std::size_t n) { v.resize(n); }};
}

std::vector<Field> schema(Table& t) {
  const auto dy = static_cast<hsize_t>(t.n_dy()), second = static_cast<hsize_t>(t.n_second());
  const hsize_t wheels = kWheels, slots = kSlots, samples = t.strip_samples;
  const std::vector<hsize_t> per_case = {dy, second}, per_wheel = {dy, second, wheels}, per_slot = {dy, second, wheels, slots},
                             per_sample = {dy, second, wheels, slots, samples};
  auto& p = t.patch;
  return {
      field("/axes/lateral_displacement_m", "m", "wheelset lateral shift dy, + moves the right flange to its rail", {dy},
            H5T_NATIVE_DOUBLE, t.lateral_displacement_m),
      field("/axes/second", "see attribute name", "second axis: load or approach (one value when fixed)", {second},
            H5T_NATIVE_DOUBLE, t.second_axis),
      field("/cases/roll_rad", "rad", "wheelset roll angle (0 in single-wheel mode)", per_case, H5T_NATIVE_DOUBLE, t.roll_rad),
      field("/cases/rolling_radius_difference_m", "m", "r_right - r_left at the first patch of each wheel", per_case,
            H5T_NATIVE_DOUBLE, t.rolling_radius_difference_m),
      field("/wheels/status", "-", "solve status (0 converged, 1 no contact, <0 failure; see README)", per_wheel,
            H5T_NATIVE_INT8, t.status),
      field("/patches/present", "-", "1 where the slot (tread, flange, spare) holds a patch", per_slot, H5T_NATIVE_UINT8, p.present),
      field("/patches/normal_force_N", "N", "normal force", per_slot, H5T_NATIVE_DOUBLE, p.normal_force_N),
      field("/patches/area_m2", "m^2", "contact area", per_slot, H5T_NATIVE_DOUBLE, p.area_m2),
      field("/patches/max_pressure_Pa", "Pa", "maximum pressure", per_slot, H5T_NATIVE_DOUBLE, p.max_pressure_Pa),
      field("/patches/approach_m", "m", "normal approach of the patch", per_slot, H5T_NATIVE_DOUBLE, p.approach_m),
      field("/patches/contact_angle_rad", "rad", "direction of the resultant normal force (negative on the gauge side)",
            per_slot, H5T_NATIVE_DOUBLE, p.contact_angle_rad),
      field("/patches/y_wheel_m", "m", "contact point on the wheel profile, origin at the tape circle", per_slot,
            H5T_NATIVE_DOUBLE, p.y_wheel_m),
      field("/patches/y_rail_m", "m", "contact point on the rail profile, origin at the top of the inclined head",
            per_slot, H5T_NATIVE_DOUBLE, p.y_rail_m),
      field("/patches/y_cop_rail_m", "m", "centre of pressure on the rail profile", per_slot, H5T_NATIVE_DOUBLE, p.y_cop_rail_m),
      field("/patches/rolling_radius_m", "m", "wheel rolling radius at the contact point", per_slot, H5T_NATIVE_DOUBLE,
            p.rolling_radius_m),
      field("/patches/semi_axis_a_m", "m", "equivalent ellipse semi-axis, rolling direction (area and length/width kept)",
            per_slot, H5T_NATIVE_DOUBLE, p.semi_axis_a_m),
      field("/patches/semi_axis_b_m", "m", "equivalent ellipse semi-axis, lateral", per_slot, H5T_NATIVE_DOUBLE, p.semi_axis_b_m),
      field("/patches/s_min_m", "m", "lower end of the patch in its contact plane", per_slot, H5T_NATIVE_DOUBLE, p.s_min_m),
      field("/patches/s_max_m", "m", "upper end of the patch in its contact plane", per_slot, H5T_NATIVE_DOUBLE, p.s_max_m),
      field("/patches/strip_half_length_m", "m", "strip half-length a(s) on strip_samples points over [s_min, s_max]",
            per_sample, H5T_NATIVE_DOUBLE, p.strip_half_length_m),
      field("/patches/strip_peak_pressure_Pa", "Pa", "strip peak pressure p0(s) on strip_samples points over [s_min, s_max]",
            per_sample, H5T_NATIVE_DOUBLE, p.strip_peak_pressure_Pa),
  };
}

bool write_text_attribute(hid_t object, const char* name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  if (!type.valid() || H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1)) < 0) return false;
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute.get(), type.get(), value.empty() ? "" : value.data()) >= 0;
}

bool write_number_attribute(hid_t object, const char* name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attribute(H5Acreate2(object, name, H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  return attribute.valid() && H5Awrite(attribute.get(), H5T_NATIVE_DOUBLE, &value) >= 0;
}

hid_t file_type_of(hid_t memory_type) {
  if (H5Tequal(memory_type, H5T_NATIVE_DOUBLE) > 0) return H5T_IEEE_F64LE;
  if (H5Tequal(memory_type, H5T_NATIVE_INT8) > 0) return H5T_STD_I8LE;
  return H5T_STD_U8LE;
}

TableResult fail(TableStatus status, const std::string& message) { return {status, message}; }

TableResult write_file(const Table& const_table, const std::string& path) {
  Table& table = const_cast<Table&>(const_table);  // schema() binds non-const vectors; nothing is modified
  // No timestamps in object headers: the same table gives the same bytes.
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), H5Fclose);
  if (!file.valid()) return fail(TableStatus::WriteFailed, path + ": cannot create file");
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  H5Pset_obj_track_times(gcpl.get(), false);
  for (const char* group : {"/axes", "/cases", "/wheels", "/patches"}) {
    Handle g(H5Gcreate2(file.get(), group, H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
    if (!g.valid()) return fail(TableStatus::WriteFailed, path + ": cannot create group " + group);
  }
  for (const Field& f : schema(table)) {
    hsize_t count = 1;
    for (const hsize_t d : f.shape) count *= d;
    if (count != f.size) return fail(TableStatus::WriteFailed, std::string(f.path) + ": size does not match its shape");
    Handle space(H5Screate_simple(static_cast<int>(f.shape.size()), f.shape.data(), nullptr), H5Sclose);
    Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    H5Pset_obj_track_times(dcpl.get(), false);
    if (count > 0) {
      std::vector<hsize_t> chunk = f.shape;
      for (hsize_t& c : chunk) c = std::max<hsize_t>(c, 1);
      while (chunk.size() > 1 && [&] { hsize_t n = 1; for (auto c : chunk) n *= c; return n > 65536; }()) chunk[0] = std::max<hsize_t>(1, chunk[0] / 2);
      H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data());
      H5Pset_shuffle(dcpl.get());
      H5Pset_deflate(dcpl.get(), 4);
    }
    Handle dataset(H5Dcreate2(file.get(), f.path, file_type_of(f.memory_type), space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                   H5Dclose);
    if (!dataset.valid() || (count > 0 && H5Dwrite(dataset.get(), f.memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.data) < 0) ||
        !write_text_attribute(dataset.get(), "units", f.units) || !write_text_attribute(dataset.get(), "description", f.description))
      return fail(TableStatus::WriteFailed, path + ": cannot write " + f.path);
  }
  Handle root(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose);
  bool ok = write_number_attribute(root.get(), "schema_version", kSchemaVersion) &&
            write_number_attribute(root.get(), "strip_samples", static_cast<double>(table.strip_samples)) &&
            write_text_attribute(root.get(), "second_axis_name", table.second_axis_name);
  for (const auto& [name, value] : table.text_attributes) ok = ok && write_text_attribute(root.get(), name.c_str(), value);
  for (const auto& [name, value] : table.number_attributes) ok = ok && write_number_attribute(root.get(), name.c_str(), value);
  if (!ok) return fail(TableStatus::WriteFailed, path + ": cannot write the root attributes");
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) return fail(TableStatus::WriteFailed, path + ": cannot flush");
  return {};
}

herr_t collect_attribute(hid_t object, const char* name, const H5A_info_t*, void* data) {
  Table& table = *static_cast<Table*>(data);
  Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attribute.get()), H5Tclose);
  if (H5Tget_class(type.get()) == H5T_STRING) {
    std::string value(H5Tget_size(type.get()), '\0');
    Handle memory(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(memory.get(), value.size());
    if (H5Aread(attribute.get(), memory.get(), value.data()) >= 0) {
      while (!value.empty() && value.back() == '\0') value.pop_back();
      table.text_attributes[name] = value;
    }
  } else {
    double value = 0.0;
    if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) >= 0) table.number_attributes[name] = value;
  }
  return 0;
}

}  // namespace

TableResult write_table(const Table& table, const std::string& path) {
  silence_hdf5_errors();
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  const TableResult result = write_file(table, temporary);
  if (!result.ok()) {
    std::remove(temporary.c_str());
    return result;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return fail(TableStatus::WriteFailed, path + ": cannot rename the finished table into place");
  }
  return {};
}

TableResult read_table(const std::string& path, Table& table) {
  silence_hdf5_errors();
  table = Table{};
  if (FILE* probe = std::fopen(path.c_str(), "rb")) {
    std::fclose(probe);
  } else {
    return fail(TableStatus::CannotOpen, path + ": cannot open table file");
  }
  if (H5Fis_hdf5(path.c_str()) <= 0) return fail(TableStatus::NotATable, path + ": not an HDF5 contact table (or truncated)");
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) return fail(TableStatus::NotATable, path + ": cannot be opened as HDF5 (truncated or damaged)");
  Handle root(H5Gopen2(file.get(), "/", H5P_DEFAULT), H5Gclose);
  hsize_t index = 0;
  H5Aiterate2(root.get(), H5_INDEX_NAME, H5_ITER_NATIVE, &index, collect_attribute, &table);
  const auto version = table.number_attributes.find("schema_version");
  if (version == table.number_attributes.end())
    return fail(TableStatus::NotATable, path + ": no schema_version attribute: not a ctab table");
  if (version->second != kSchemaVersion)
    return fail(TableStatus::WrongSchemaVersion, path + ": schema version " + std::to_string(static_cast<int>(version->second)) +
                                                     ", this build reads version " + std::to_string(kSchemaVersion));
  table.strip_samples = static_cast<std::size_t>(table.number_attributes["strip_samples"]);
  table.second_axis_name = table.text_attributes["second_axis_name"];
  table.number_attributes.erase("schema_version");
  table.number_attributes.erase("strip_samples");
  table.text_attributes.erase("second_axis_name");
  // The axes fix every other shape.
  for (const char* axis : {"/axes/lateral_displacement_m", "/axes/second"}) {
    Handle dataset(H5Dopen2(file.get(), axis, H5P_DEFAULT), H5Dclose);
    if (!dataset.valid()) return fail(TableStatus::MissingDataset, path + ": missing dataset " + axis);
    Handle space(H5Dget_space(dataset.get()), H5Sclose);
    hsize_t n = 0;
    if (H5Sget_simple_extent_ndims(space.get()) != 1 || H5Sget_simple_extent_dims(space.get(), &n, nullptr) < 0 || n == 0)
      return fail(TableStatus::WrongShape, path + ": " + axis + " must be a non-empty 1-D array");
    (std::string(axis) == "/axes/second" ? table.second_axis : table.lateral_displacement_m).resize(n);
  }
  table.allocate();
  for (const Field& f : schema(table)) {
    Handle dataset(H5Dopen2(file.get(), f.path, H5P_DEFAULT), H5Dclose);
    if (!dataset.valid()) return fail(TableStatus::MissingDataset, path + ": missing dataset " + f.path);
    Handle space(H5Dget_space(dataset.get()), H5Sclose);
    const int rank = H5Sget_simple_extent_ndims(space.get());
    std::vector<hsize_t> dims(static_cast<std::size_t>(std::max(rank, 0)));
    if (rank < 0 || H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0 || dims != f.shape)
      return fail(TableStatus::WrongShape, path + ": dataset " + f.path + " has the wrong shape");
    if (f.size > 0 && H5Dread(dataset.get(), f.memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, f.data) < 0)
      return fail(TableStatus::NotATable, path + ": cannot read " + f.path + " (truncated or damaged)");
  }
  const auto& dy = table.lateral_displacement_m;
  for (std::size_t i = 1; i < dy.size(); ++i) {
    const double step = dy[1] - dy[0];
    if (!(dy[i] > dy[i - 1]) || std::abs((dy[i] - dy[i - 1]) - step) > 1e-9 * std::abs(step) + 1e-15)
      return fail(TableStatus::InvalidContent, path + ": /axes/lateral_displacement_m must be uniform and increasing");
  }
  return {};
}

}  // namespace ctab::tables
