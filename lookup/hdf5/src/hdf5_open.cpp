// SPDX-License-Identifier: Apache-2.0
// Loading HDF5 tables or blobs by the file's first bytes; the C loader ctab_table_open_hdf5.
#include <cstdio>

#include "c_handle.hpp"
#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/ctab_lookup_hdf5.h"
#include "ctab/lookup/hdf5_table.hpp"
#include "ctab/lookup/open.hpp"

namespace ctab::lookup {

namespace {

ctab_status to_status(tables::TableStatus status) noexcept {
  switch (status) {
    case tables::TableStatus::Ok: return CTAB_OK;
    case tables::TableStatus::CannotOpen: return CTAB_ERR_CANNOT_OPEN;
    case tables::TableStatus::NotATable: return CTAB_ERR_NOT_A_TABLE;
    case tables::TableStatus::WrongSchemaVersion: return CTAB_ERR_VERSION;
    case tables::TableStatus::MissingDataset:
    case tables::TableStatus::WrongShape: return CTAB_ERR_SHAPE;
    case tables::TableStatus::InvalidContent:
    case tables::TableStatus::WriteFailed: return CTAB_ERR_CONTENT;
    case tables::TableStatus::OutOfMemory: return CTAB_ERR_OUT_OF_MEMORY;
  }
  return CTAB_ERR_CONTENT;
}

}  // namespace

LoadResult read_hdf5(const std::string& path, TableData& data) {
  return detail::guard_allocation([&] {
    tables::Table table;
    const tables::TableResult read = tables::read_table(path, table);
    if (!read.ok()) return LoadResult{to_status(read.status), read.message};
    LoadResult result = from_tables(std::move(table), data);
    if (!result.ok()) result.message = path + ": " + result.message;
    return result;
  });
}

LoadResult read_any(const std::string& path, TableData& data, bool& single_precision) {
  single_precision = false;
  unsigned char signature[8] = {};
  std::size_t length = 0;
  if (std::FILE* file = std::fopen(path.c_str(), "rb")) {  // the first bytes say which reader
    length = std::fread(signature, 1, sizeof signature, file);
    std::fclose(file);
  }
  if (looks_like_hdf5(signature, length)) return read_hdf5(path, data);
  return read_blob_file(path, data, single_precision);
}

LoadResult open_file(const std::string& path, const LoadOptions& options, Table& table) {
  return detail::guard_allocation([&] {
    TableData data;
    bool single = false;
    LoadResult result = read_any(path, data, single);
    if (!result.ok()) return result;
    LoadOptions effective = options;
    effective.single_precision = options.single_precision || single;
    result = table.load(std::move(data), effective);
    if (!result.ok()) result.message = path + ": " + result.message;
    return result;
  });
}

}  // namespace ctab::lookup

extern "C" ctab_status ctab_table_open_hdf5(const char* path, const ctab_open_options* options, ctab_table** table) {
  if (path == nullptr) return table ? (*table = nullptr, CTAB_INVALID_INPUT) : CTAB_INVALID_INPUT;
  return ctab::lookup::detail::make_handle(table, [&](ctab::lookup::Table& t) {
    return ctab::lookup::open_file(path, ctab::lookup::detail::load_options(options), t);
  });
}
