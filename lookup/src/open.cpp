// Blob loading from memory or a file (stdio only).
#include <cstdio>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/open.hpp"
#include "ctab/tables/limits.hpp"
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

bool read_file(const std::string& path, std::string& bytes, std::string& message) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    message = path + ": cannot open";
    return false;
  }
  bytes.clear();
  // Sized once from the file's length where it has one (no doubling while reading); a blob holds at most about the
  // table size limit, so a file over twice that is refused unread.
  if (std::fseek(file, 0, SEEK_END) == 0) {
    const long length = std::ftell(file);
    if (length > 0 && static_cast<double>(length) > 2.0 * tables::kMaxTableBytes) {
      std::fclose(file);
      message = path + ": larger than any table blob (limit tables/README.md \"Limits\")";
      return false;
    }
    if (length > 0) bytes.reserve(static_cast<std::size_t>(length));
  }
  std::rewind(file);
  char buffer[65536];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) bytes.append(buffer, n);
  const bool ok = std::ferror(file) == 0;
  std::fclose(file);
  if (!ok) message = path + ": read error";
  return ok;
}

LoadResult open_blob_file(const std::string& path, const LoadOptions& options, Table& table) {
  LoadResult result = detail::guard_allocation([&] {
    std::string bytes, message;
    if (!read_file(path, bytes, message)) return LoadResult{CTAB_ERR_CANNOT_OPEN, message};
    if (looks_like_hdf5(bytes.data(), bytes.size()))
      return LoadResult{CTAB_ERR_HDF5_UNAVAILABLE, "an HDF5 table; this build loads blobs only (ctab export)"};
    TableData data;
    bool single = false;
    LoadResult parsed = read_blob(bytes.data(), bytes.size(), data, single);
    std::string{}.swap(bytes);  // the file's bytes are in `data` now: their memory back before the load
    return parsed.ok() ? load_parsed(data, single, options, table) : parsed;
  });
  if (!result.ok() && result.status != CTAB_ERR_CANNOT_OPEN) result.message = path + ": " + result.message;
  return result;
}

}  // namespace ctab::lookup
