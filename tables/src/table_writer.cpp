// Writes a schema-2 table: groups, array datasets, /jumps, root attributes; into a temporary file renamed at the end.
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "ctab/tables/table.hpp"
#include "chunk_deflate.hpp"
#include "hdf5_types.hpp"
#include "schema_fields.hpp"

namespace ctab::tables {

namespace {

using detail::Handle;

TableResult fail(const std::string& message) { return {TableStatus::WriteFailed, message}; }

// Chunks of at most kChunkElements elements: the leading dimension halved until the chunk fits.
constexpr hsize_t kChunkElements = 65536;

std::vector<hsize_t> chunk_shape(const std::vector<hsize_t>& shape) {
  std::vector<hsize_t> chunk = shape;
  auto elements = [&] {
    hsize_t n = 1;
    for (const hsize_t c : chunk) n *= c;
    return n;
  };
  while (chunk.size() > 1 && elements() > kChunkElements && chunk[0] > 1) chunk[0] = std::max<hsize_t>(1, chunk[0] / 2);
  return chunk;
}

// Chunked; shuffled and deflated at `level` (compression_level) unless it is 0; no timestamps, so the same table
// gives the same bytes at any level (zlib's output depends only on its input and level).
Handle dataset_properties(const std::vector<hsize_t>& shape, hsize_t count, std::int64_t level) {
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_obj_track_times(dcpl.get(), false);
  if (count > 0) {
    const std::vector<hsize_t> chunk = chunk_shape(shape);
    H5Pset_chunk(dcpl.get(), static_cast<int>(chunk.size()), chunk.data());
    if (level > 0) {
      H5Pset_shuffle(dcpl.get());
      H5Pset_deflate(dcpl.get(), static_cast<unsigned>(level));
    }
  }
  return dcpl;
}

// The chunks of `data` shuffled and deflated on parallel_for's threads, then stored in row-major chunk order (the
// order H5Dwrite allocates them in, so the file's bytes match its). False when zlib or HDF5 fails.
bool write_chunks_in_parallel(hid_t dataset, const std::vector<hsize_t>& shape, std::size_t element_size,
                              const void* data, std::int64_t level, const ParallelFor& parallel_for) {
  const detail::ChunkGrid grid(shape, chunk_shape(shape));
  std::vector<std::vector<unsigned char>> compressed(grid.count());
  std::vector<unsigned char> failed(grid.count(), 0);
  const auto compress = [&](std::size_t index) {
    try {  // nothing may escape a task (an OpenMP loop would terminate)
      std::vector<unsigned char> chunk, scratch;
      grid.gather(static_cast<const unsigned char*>(data), element_size, index, chunk);
      if (!detail::shuffle_and_deflate(chunk, element_size, static_cast<int>(level), scratch, compressed[index]))
        failed[index] = 1;
    } catch (...) {
      failed[index] = 1;
    }
  };
  // One chunk: here (waking the threads for it cost more than it saved: the default table's write 0.010 -> 0.021 s).
  if (grid.count() == 1) compress(0);
  else parallel_for(grid.count(), compress);
  if (std::find(failed.begin(), failed.end(), 1) != failed.end()) return false;
  for (std::size_t index = 0; index < grid.count(); ++index) {
    const std::vector<hsize_t> offset = grid.offset(index);
    if (H5Dwrite_chunk(dataset, H5P_DEFAULT, 0, offset.data(), compressed[index].size(), compressed[index].data()) < 0)
      return false;
  }
  return true;
}

bool write_dataset(hid_t file, const char* path, const std::vector<hsize_t>& shape, hid_t file_type, hid_t memory_type,
                   const void* data, const char* units, const char* description, std::int64_t level,
                   const ParallelFor& parallel_for) {
  hsize_t count = 1;
  for (const hsize_t d : shape) count *= d;
  const Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose);
  const Handle dcpl = dataset_properties(shape, count, level);
  const Handle dataset(H5Dcreate2(file, path, file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT), H5Dclose);
  if (!dataset.valid()) return false;
  // Deflated datasets store their chunks directly (compressed here, on parallel_for's threads when given), so the
  // file's bytes do not depend on whether or how the chunks were shared out. The chunks' bytes are the file type's:
  // the memory layout must be it (little-endian hosts; else the library converts them, serially).
  const bool direct = count > 0 && level > 0 && H5Tequal(file_type, memory_type) > 0;
  static const ParallelFor serial = [](std::size_t n, const std::function<void(std::size_t)>& task) {
    for (std::size_t i = 0; i < n; ++i) task(i);
  };
  const bool written =
      count == 0 || (direct ? write_chunks_in_parallel(dataset.get(), shape, H5Tget_size(file_type), data, level,
                                                       parallel_for ? parallel_for : serial)
                            : H5Dwrite(dataset.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0);
  return written && detail::write_text_attribute(dataset.get(), "units", units) &&
         detail::write_text_attribute(dataset.get(), "description", description);
}

TableResult write_arrays(hid_t file, const Table& const_table, const std::string& path,
                         const ParallelFor& parallel_for) {
  Table& table = const_cast<Table&>(const_table);  // schema_fields binds non-const members; nothing is modified
  const Handle status_file(detail::make_case_status_type(), H5Tclose);
  const Handle status_memory(detail::make_case_status_type(), H5Tclose);
  for (const detail::Field& f : detail::schema_fields(table)) {
    const std::vector<hsize_t> shape =
        detail::shape_of(f.extent, table.n_dy(), table.n_second(), table.n_slots, table.strip_samples);
    hsize_t count = 1;
    for (const hsize_t d : shape) count *= d;
    if (count != f.size()) return fail(path + ": " + f.path + ": size does not match its shape");
    hid_t file_type = H5T_IEEE_F64LE, memory_type = H5T_NATIVE_DOUBLE;
    if (f.element == detail::Element::Presence) file_type = H5T_STD_U8LE, memory_type = H5T_NATIVE_UINT8;
    if (f.element == detail::Element::Int8) file_type = H5T_STD_I8LE, memory_type = H5T_NATIVE_INT8;
    if (f.element == detail::Element::Status) file_type = status_file.get(), memory_type = status_memory.get();
    const bool second = f.extent == detail::Extent::SecondAxis;
    if (!write_dataset(file, f.path, shape, file_type, memory_type, f.data(),
                       second ? table.second_axis_units.c_str() : f.units, f.description, compression_level(table),
                       parallel_for))
      return fail(path + ": cannot write " + f.path);
    if (second) {
      const Handle dataset(H5Dopen2(file, f.path, H5P_DEFAULT), H5Dclose);
      if (!detail::write_text_attribute(dataset.get(), "name", table.second_axis_name))
        return fail(path + ": cannot write the name of /axes/second");
    }
  }
  return {};
}

TableResult write_jumps(hid_t file, const Table& table, const std::string& path) {
  std::vector<detail::JumpRecord> rows;
  rows.reserve(table.jumps.size());
  for (const Jump& j : table.jumps) {
    if (j.i_dy + 1 >= table.n_dy()) return fail(path + ": /jumps: i_dy out of range");
    rows.push_back({j.i_second, j.wheel, j.slot, j.i_dy, table.lateral_displacement_m[j.i_dy],
                    table.lateral_displacement_m[j.i_dy + 1], static_cast<std::uint8_t>(j.kind)});
  }
  const Handle kind(detail::make_jump_kind_type(), H5Tclose);
  const Handle memory(detail::make_jump_type(kind.get()), H5Tclose);
  const Handle file_type(detail::make_jump_file_type(), H5Tclose);
  if (!write_dataset(file, detail::kJumpsPath, {static_cast<hsize_t>(rows.size())}, file_type.get(), memory.get(),
                     rows.data(), "-",
                     "contact jumps: a slot appears, disappears or moves between dy_low_m and dy_high_m",
                     compression_level(table), {}))
    return fail(path + ": cannot write /jumps");
  return {};
}

TableResult write_root_attributes(hid_t file, const Table& table, const std::string& path) {
  const Handle root(H5Gopen2(file, "/", H5P_DEFAULT), H5Gclose);
  bool ok =
      detail::write_integer_attribute(root.get(), "schema_version", kSchemaVersion) &&
      detail::write_integer_attribute(root.get(), "strip_samples", static_cast<std::int64_t>(table.strip_samples)) &&
      detail::write_integer_attribute(root.get(), "n_slots", static_cast<std::int64_t>(table.n_slots)) &&
      detail::write_text_attribute(root.get(), "second_axis_name", table.second_axis_name);
  for (const auto& [name, value] : table.text_attributes)
    ok = ok && detail::write_text_attribute(root.get(), name.c_str(), value);
  for (const auto& [name, value] : table.number_attributes)
    ok = ok && detail::write_number_attribute(root.get(), name.c_str(), value);
  for (const auto& [name, value] : table.integer_attributes)
    ok = ok && detail::write_integer_attribute(root.get(), name.c_str(), value);
  return ok ? TableResult{} : fail(path + ": cannot write the root attributes (a provenance name used twice?)");
}

TableResult write_file(const Table& table, const std::string& path, const ParallelFor& parallel_for) {
  const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) return fail(path + ": cannot create file");
  const Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  H5Pset_obj_track_times(gcpl.get(), false);
  for (const char* group : detail::kGroups) {
    const Handle g(H5Gcreate2(file.get(), group, H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
    if (!g.valid()) return fail(path + ": cannot create group " + group);
  }
  if (TableResult r = write_arrays(file.get(), table, path, parallel_for); !r.ok()) return r;
  for (const auto& step : {write_jumps, write_root_attributes})
    if (TableResult r = step(file.get(), table, path); !r.ok()) return r;
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) return fail(path + ": cannot flush");
  return {};
}

}  // namespace

std::int64_t compression_level(const Table& table) noexcept {
  const auto found = table.integer_attributes.find(kCompressionLevelAttribute);
  if (found == table.integer_attributes.end()) return kDefaultCompressionLevel;
  return std::clamp(found->second, kMinCompressionLevel, kMaxCompressionLevel);
}

std::string temporary_path(const std::string& path) { return path + ".tmp-" + std::to_string(::getpid()); }

TableResult write_table(const Table& table, const std::string& path, const ParallelFor& parallel_for) {
  detail::silence_hdf5_errors();
  const std::string temporary = temporary_path(path);
  const TableResult result = write_file(table, temporary, parallel_for);
  if (!result.ok()) {
    std::remove(temporary.c_str());
    return result;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return fail(path + ": cannot rename the finished table into place");
  }
  return {};
}

}  // namespace ctab::tables
