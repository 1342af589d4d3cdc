// Blob loading from memory or a file (stdio only).
#include <cstdio>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/open.hpp"

namespace ctab::lookup {

LoadResult open_memory(const void* bytes, std::size_t size, const LoadOptions& options, Table& table) {
  TableData data;
  bool single = false;
  LoadResult result = read_blob(bytes, size, data, single);
  if (!result.ok()) return result;
  LoadOptions effective = options;
  effective.single_precision = options.single_precision || single;
  return table.load(data, effective);
}

bool read_file(const std::string& path, std::string& bytes, std::string& message) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    message = path + ": cannot open";
    return false;
  }
  bytes.clear();
  char buffer[65536];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) bytes.append(buffer, n);
  const bool ok = std::ferror(file) == 0;
  std::fclose(file);
  if (!ok) message = path + ": read error";
  return ok;
}

LoadResult open_blob_file(const std::string& path, const LoadOptions& options, Table& table) {
  std::string bytes, message;
  if (!read_file(path, bytes, message)) return {CTAB_ERR_CANNOT_OPEN, message};
  if (looks_like_hdf5(bytes.data(), bytes.size()))
    return {CTAB_ERR_HDF5_UNAVAILABLE, path + ": an HDF5 table; this build loads blobs only (ctab export)"};
  LoadResult result = open_memory(bytes.data(), bytes.size(), options, table);
  if (!result.ok()) result.message = path + ": " + result.message;
  return result;
}

}  // namespace ctab::lookup
