// SPDX-License-Identifier: Apache-2.0
// Writes a schema-2 table: groups, array datasets, /jumps, root attributes; into a temporary file renamed at the end.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <utility>

#include "ctab/tables/table.hpp"
#include "chunk_deflate.hpp"
#include "dimension_scales.hpp"
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

// One dataset of the file: shape, file and memory types, data, attributes. `direct` datasets store chunks
// compressed outside the library (compress_chunk); the others go through H5Dwrite.
struct DatasetWrite {
  const char* path;
  std::vector<hsize_t> shape;
  hid_t file_type, memory_type;
  const void* data;
  const char* units;
  const char* description;
  const std::string* axis_name = nullptr;  // /axes/second's "name" attribute: its quantity
  bool direct = false;
  std::size_t element_size = 0;  // bytes of an element in the file
  std::size_t first_chunk = 0;   // the position of its first chunk among all datasets' chunks
};

hsize_t element_count(const std::vector<hsize_t>& shape) {
  hsize_t count = 1;
  for (const hsize_t d : shape) count *= d;
  return count;
}

// Everything a table's file holds, planned before anything is written: its types, datasets and chunks.
class FilePlan {
 public:
  FilePlan(const Table& table, std::int64_t level)
      : table_(const_cast<Table&>(table)),  // schema_fields binds non-const members; nothing is modified
        level_(level), status_type_(detail::make_case_status_type(), H5Tclose),
        method_type_(detail::make_method_type(), H5Tclose),
        jump_kind_(detail::make_jump_kind_type(), H5Tclose),
        jump_memory_(detail::make_jump_type(jump_kind_.get()), H5Tclose),
        jump_file_(detail::make_jump_file_type(), H5Tclose) {}

  // The datasets of the table (the schema's arrays, then /jumps) and their chunks; an error message, or "".
  std::string plan() {
    for (const detail::Field& f : detail::schema_fields(table_)) {
      if (f.empty_when_missing && f.size() == 0) continue;
      DatasetWrite write{
          f.path,
          detail::shape_of(f.extent, table_.n_dy(), table_.n_second(), table_.n_slots, table_.strip_samples),
          H5T_IEEE_F64LE,
          H5T_NATIVE_DOUBLE,
          f.data(),
          f.units,
          f.description};
      if (element_count(write.shape) != f.size()) return std::string(f.path) + ": size does not match its shape";
      if (f.element == detail::Element::Presence) write.file_type = H5T_STD_U8LE, write.memory_type = H5T_NATIVE_UINT8;
      if (f.element == detail::Element::Int8) write.file_type = write.memory_type = method_type_.get();
      if (f.element == detail::Element::Status) write.file_type = write.memory_type = status_type_.get();
      if (f.extent == detail::Extent::SecondAxis) {
        write.units = table_.second_axis_units.c_str();
        write.axis_name = &table_.second_axis_name;
      }
      add(write);
      dimensioned_.push_back({f.path, f.extent});
    }
    jump_rows_.reserve(table_.jumps.size());
    for (const Jump& j : table_.jumps) {
      if (j.i_dy + 1 >= table_.n_dy()) return "/jumps: i_dy out of range";
      jump_rows_.push_back({j.i_second, j.wheel, j.slot, j.i_dy, table_.lateral_displacement_m[j.i_dy],
                            table_.lateral_displacement_m[j.i_dy + 1], static_cast<std::uint8_t>(j.kind)});
    }
    add({detail::kJumpsPath,
         {static_cast<hsize_t>(jump_rows_.size())},
         jump_file_.get(),
         jump_memory_.get(),
         jump_rows_.data(),
         "1",
         "contact jumps: a slot appears, disappears or moves between dy_low_m and dy_high_m"});
    compressed_.resize(chunks_.size());
    return "";
  }

  [[nodiscard]] std::size_t chunk_count() const noexcept { return chunks_.size(); }

  // Shuffles and deflates chunk `index` (of all datasets' chunks); false when zlib fails. No HDF5 call: safe on any
  // thread, beside create().
  bool compress_chunk(std::size_t index) {
    const DatasetWrite& write = writes_[chunks_[index].write];
    std::vector<unsigned char> chunk, scratch;
    grids_[chunks_[index].write]->gather(static_cast<const unsigned char*>(write.data), write.element_size,
                                         chunks_[index].index, chunk);
    return detail::shuffle_and_deflate(chunk, write.element_size, static_cast<int>(level_), scratch,
                                       compressed_[index]);
  }

  // Creates the file's groups and datasets with their attributes, writes the datasets that are not direct and the
  // root attributes; the direct datasets stay open for store_chunks. HDF5 on one thread at a time: the caller's
  // threads meanwhile compress the chunks (a fixed order of HDF5 calls: the same bytes however they are shared out).
  std::string create(hid_t file) {
    const Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
    H5Pset_obj_track_times(gcpl.get(), false);
    for (const char* group : detail::kGroups) {
      const Handle g(H5Gcreate2(file, group, H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
      if (!g.valid()) return std::string("cannot create group ") + group;
    }
    for (const DatasetWrite& write : writes_)
      if (!create_dataset(file, write)) return std::string("cannot write ") + write.path;
    if (!detail::write_dimension_scales(file, dimensioned_, table_.n_slots, table_.strip_samples))
      return "cannot write the dimension scales";
    if (!write_root_attributes(file)) return "cannot write the root attributes (a provenance name used twice?)";
    return "";
  }

  // Stores the compressed chunks in row-major chunk order per dataset (the order H5Dwrite allocates them in).
  std::string store_chunks() {
    for (std::size_t w = 0; w < writes_.size(); ++w) {
      if (!writes_[w].direct) continue;
      for (std::size_t index = 0; index < grids_[w]->count(); ++index) {
        const std::vector<hsize_t> offset = grids_[w]->offset(index);
        const std::vector<unsigned char>& chunk = compressed_[writes_[w].first_chunk + index];
        if (H5Dwrite_chunk(open_[w].get(), H5P_DEFAULT, 0, offset.data(), chunk.size(), chunk.data()) < 0)
          return std::string("cannot write ") + writes_[w].path;
      }
    }
    return "";
  }

 private:
  struct Chunk {
    std::size_t write, index;
  };

  // Deflated datasets store their chunks directly, so the file's bytes do not depend on whether or how the chunks
  // were shared out. The chunks' bytes are the file type's: the memory layout must be it (little-endian hosts; else
  // the library converts them, serially).
  void add(DatasetWrite write) {
    write.direct = element_count(write.shape) > 0 && level_ > 0 && H5Tequal(write.file_type, write.memory_type) > 0;
    write.element_size = H5Tget_size(write.file_type);
    write.first_chunk = chunks_.size();
    grids_.emplace_back();
    if (write.direct) {
      grids_.back().emplace(write.shape, chunk_shape(write.shape));
      for (std::size_t index = 0; index < grids_.back()->count(); ++index) chunks_.push_back({writes_.size(), index});
    }
    writes_.push_back(write);
  }

  bool create_dataset(hid_t file, const DatasetWrite& write) {
    const hsize_t count = element_count(write.shape);
    const Handle space(H5Screate_simple(static_cast<int>(write.shape.size()), write.shape.data(), nullptr), H5Sclose);
    const Handle dcpl = dataset_properties(write.shape, count, level_);
    Handle dataset(H5Dcreate2(file, write.path, write.file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                   H5Dclose);
    if (!dataset.valid()) return false;
    if (!write.direct && count > 0 &&
        H5Dwrite(dataset.get(), write.memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, write.data) < 0)
      return false;
    const bool attributes =
        detail::write_text_attribute(dataset.get(), "units", write.units) &&
        detail::write_text_attribute(dataset.get(), "description", write.description) &&
        (write.axis_name == nullptr || detail::write_text_attribute(dataset.get(), "name", *write.axis_name));
    // In the order of writes_; the others close here (the file's layout depends on when a dataset closes).
    open_.push_back(write.direct ? std::move(dataset) : Handle(-1, H5Dclose));
    return attributes;
  }

  bool write_root_attributes(hid_t file) const {
    const Handle root(H5Gopen2(file, "/", H5P_DEFAULT), H5Gclose);
    bool ok =
        detail::write_integer_attribute(root.get(), "schema_version", kSchemaVersion) &&
        detail::write_integer_attribute(root.get(), "strip_samples", static_cast<std::int64_t>(table_.strip_samples)) &&
        detail::write_integer_attribute(root.get(), "n_slots", static_cast<std::int64_t>(table_.n_slots)) &&
        detail::write_text_attribute(root.get(), "second_axis_name", table_.second_axis_name);
    for (const auto& [name, value] : table_.text_attributes)
      ok = ok && (name == detail::kMirroredAttribute  // a boolean: true when its text starts with "true"
                      ? detail::write_bool_attribute(root.get(), name.c_str(), value.rfind("true", 0) == 0)
                      : detail::write_text_attribute(root.get(), name.c_str(), value));
    for (const auto& [name, value] : table_.number_attributes)
      ok = ok && detail::write_number_attribute(root.get(), name.c_str(), value);
    for (const auto& [name, value] : table_.integer_attributes)
      ok = ok && detail::write_integer_attribute(root.get(), name.c_str(), value);
    return ok;
  }

  Table& table_;
  std::int64_t level_;
  Handle status_type_, method_type_, jump_kind_, jump_memory_, jump_file_;
  std::vector<detail::JumpRecord> jump_rows_;
  std::vector<DatasetWrite> writes_;
  std::vector<detail::DimensionedDataset> dimensioned_;  // the schema's arrays, for their dimension scales
  std::vector<std::optional<detail::ChunkGrid>> grids_;  // the direct datasets' chunk grids
  std::vector<Chunk> chunks_;
  std::vector<std::vector<unsigned char>> compressed_;
  std::vector<Handle> open_;  // the direct datasets, open from create to the end (store_chunks)
};

// Task 0 creates the file's structure (FilePlan::create, HDF5), tasks 1... compress one chunk each: one wake-up of
// the caller's threads for the whole table, and the library's serial work beside the compression.
TableResult write_file(const Table& table, const std::string& path, const ParallelFor& parallel_for) {
  const Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) return fail(path + ": cannot create file");
  FilePlan plan(table, compression_level(table));  // closes its datasets before `file` closes
  if (const std::string error = plan.plan(); !error.empty()) return fail(path + ": " + error);
  std::string create_error;
  std::vector<unsigned char> failed(plan.chunk_count(), 0);
  const auto task = [&](std::size_t index) {
    try {  // nothing may escape a task (an OpenMP loop would terminate)
      if (index == 0) {
        detail::silence_hdf5_errors();  // per thread in a thread-safe HDF5 build
        create_error = plan.create(file.get());
      } else if (!plan.compress_chunk(index - 1)) {
        failed[index - 1] = 1;
      }
    } catch (...) {
      if (index == 0) create_error = "cannot create the datasets";
      else failed[index - 1] = 1;
    }
  };
  const std::size_t tasks = plan.chunk_count() + 1;
  if (parallel_for) parallel_for(tasks, task);
  else
    for (std::size_t index = 0; index < tasks; ++index) task(index);
  if (!create_error.empty()) return fail(path + ": " + create_error);
  if (std::find(failed.begin(), failed.end(), 1) != failed.end()) return fail(path + ": cannot compress the datasets");
  if (const std::string error = plan.store_chunks(); !error.empty()) return fail(path + ": " + error);
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) return fail(path + ": cannot flush");
  return {};
}

}  // namespace

std::int64_t compression_level(const Table& table) noexcept {
  const auto found = table.integer_attributes.find(kCompressionLevelAttribute);
  if (found == table.integer_attributes.end()) return kDefaultCompressionLevel;
  return std::clamp(found->second, kMinCompressionLevel, kMaxCompressionLevel);
}

void start_hdf5() noexcept {
  detail::silence_hdf5_errors();
  H5open();
}

std::string temporary_path(const std::string& path) { return path + ".tmp-" + std::to_string(::getpid()); }

TableResult write_table(const Table& table, const std::string& path, const ParallelFor& parallel_for) {
  detail::silence_hdf5_errors();
  const double bytes = table_bytes(static_cast<double>(table.n_dy()), static_cast<double>(table.n_second()),
                                   static_cast<double>(table.n_slots), static_cast<double>(table.strip_samples));
  if (bytes > kMaxTableBytes)  // a table no reader would accept
    return fail(path + ": the table takes " + std::to_string(bytes / (1u << 30)) + " GiB in memory (limit " +
                std::to_string(kMaxTableBytes / (1u << 30)) + " GiB, tables/README.md \"Limits\")");
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
