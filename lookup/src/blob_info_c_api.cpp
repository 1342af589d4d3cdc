// SPDX-License-Identifier: Apache-2.0
// The C query of a blob's header (ctab_blob_info_*): which format and schema a blob carries, before loading it.
#include <cstdio>
#include <cstring>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/ctab_lookup.h"

static_assert(CTAB_BLOB_FORMAT_VERSION == ctab::lookup::kBlobVersion, "ctab_lookup.h names the blob format read");
static_assert(CTAB_TABLE_SCHEMA_VERSION == ctab::lookup::kSchemaVersion, "ctab_lookup.h names the schema read");

namespace {

ctab_status fail(ctab_status status, ctab_blob_info* info) {
  if (info != nullptr) *info = ctab_blob_info{};
  return status;
}

// `bytes` of the header (at most 64); `size` the whole blob's.
ctab_status read_header(const unsigned char* p, std::size_t bytes, ctab_blob_info* info) {
  using namespace ctab::lookup;
  if (looks_like_hdf5(p, bytes)) return fail(CTAB_ERR_HDF5_UNAVAILABLE, info);
  if (bytes < kBlobHeaderBytes || std::memcmp(p, kBlobMagic, sizeof kBlobMagic) != 0)
    return fail(CTAB_ERR_NOT_A_TABLE, info);
  info->format_version = static_cast<uint32_t>(load_le(p + 8, 4));
  info->schema_version = static_cast<uint32_t>(load_le(p + 12, 4));
  info->value_bytes = static_cast<uint32_t>(load_le(p + 16, 4));
  info->reserved = 0;
  info->payload_bytes = load_le(p + 24, 8);
  const bool readable = info->format_version == kBlobVersion && info->schema_version == kSchemaVersion;
  return readable ? CTAB_OK : CTAB_ERR_VERSION;
}

}  // namespace

extern "C" {

ctab_status ctab_blob_info_memory(const void* data, size_t size, ctab_blob_info* info) {
  if (info == nullptr || data == nullptr) return fail(CTAB_INVALID_INPUT, info);
  const std::size_t bytes = size < ctab::lookup::kBlobHeaderBytes ? size : ctab::lookup::kBlobHeaderBytes;
  return read_header(static_cast<const unsigned char*>(data), bytes, info);
}

ctab_status ctab_blob_info_file(const char* path, ctab_blob_info* info) {
  if (info == nullptr || path == nullptr) return fail(CTAB_INVALID_INPUT, info);
  std::FILE* file = std::fopen(path, "rb");
  if (file == nullptr) return fail(CTAB_ERR_CANNOT_OPEN, info);
  unsigned char header[ctab::lookup::kBlobHeaderBytes] = {};
  const std::size_t got = std::fread(header, 1, sizeof header, file);
  const bool read_error = std::ferror(file) != 0;
  std::fclose(file);
  if (read_error) return fail(CTAB_ERR_CANNOT_OPEN, info);
  return read_header(header, got, info);
}

}  // extern "C"
