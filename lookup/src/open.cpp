// SPDX-License-Identifier: Apache-2.0
// Blob loading from memory or a file.
#include <utility>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/open.hpp"
#include "load_guard.hpp"

namespace ctab::lookup {

namespace {

// A blob parsed into `data`, then loaded taking data's arrays (the table's peak: the description and the records).
LoadResult load_parsed(TableData& data, bool single, const LoadOptions& options, Table& table) {
  LoadOptions effective = options;
  effective.single_precision = options.single_precision || single;
  return table.load(std::move(data), effective);
}

}  // namespace

LoadResult open_memory(const void* bytes, std::size_t size, const LoadOptions& options, Table& table) {
  return detail::guard_allocation([&] {
    TableData data;
    bool single = false;
    LoadResult result = read_blob(bytes, size, data, single);
    return result.ok() ? load_parsed(data, single, options, table) : result;
  });
}

LoadResult open_blob_file(const std::string& path, const LoadOptions& options, Table& table) {
  return detail::guard_allocation([&] {
    TableData data;
    bool single = false;
    LoadResult result = read_blob_file(path, data, single);
    if (!result.ok()) return result;
    result = load_parsed(data, single, options, table);
    if (!result.ok()) result.message = path + ": " + result.message;
    return result;
  });
}

}  // namespace ctab::lookup
