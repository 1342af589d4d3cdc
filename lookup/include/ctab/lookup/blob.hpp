// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The ctab table blob: a versioned, checksummed, little-endian serialisation of a TableData, loadable without
//! HDF5 or a file system (ctab_table_open_memory). Layout: lookup/README.md "Blob format".
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ctab/lookup/table_data.hpp"

namespace ctab::lookup {

inline constexpr char kBlobMagic[8] = {'C', 'T', 'A', 'B', 'B', 'L', 'O', 'B'};
inline constexpr std::uint32_t kBlobVersion = 1;
inline constexpr std::size_t kBlobHeaderBytes = 64;

inline constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ull;
//! One byte of FNV-1a, 64 bit.
[[nodiscard]] constexpr std::uint64_t fnv1a64_step(std::uint64_t hash, unsigned char byte) noexcept {
  return (hash ^ byte) * 1099511628211ull;  // FNV prime
}
//! The little-endian unsigned integer of `bytes` bytes at `at`.
[[nodiscard]] constexpr std::uint64_t load_le(const unsigned char* at, int bytes) noexcept {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(at[i]) << (8 * i);
  return v;
}
//! FNV-1a, 64 bit, of `size` bytes.
[[nodiscard]] std::uint64_t fnv1a64(const void* data, std::size_t size) noexcept;

//! Serialises `data` into `blob` after the checks of a load (validate(), and with `single_precision` every stored
//! value within the float range): a blob this writes, its loader accepts. On failure `blob` is empty and the result
//! names what is wrong.
[[nodiscard]] LoadResult write_blob(const TableData& data, bool single_precision, std::vector<unsigned char>& blob);
//! Serialises `data`, which the caller has checked (validate(), and check_float_range() with `single_precision`);
//! values stored as float when `single_precision`.
[[nodiscard]] std::vector<unsigned char> write_blob(const TableData& data, bool single_precision);

//! Parses and checks a blob (magic, versions, reserved header bytes zero, sizes and the size limit before
//! allocating, checksum; contents are checked by the load). On success `single_precision` says whether the blob
//! stores floats. A failed allocation gives CTAB_ERR_OUT_OF_MEMORY.
[[nodiscard]] LoadResult read_blob(const void* bytes, std::size_t size, TableData& data, bool& single_precision);
//! The same checks for a blob file, read in chunks straight into `data` (the file's bytes are never held whole):
//! CTAB_ERR_CANNOT_OPEN if it cannot be opened or read, CTAB_ERR_HDF5_UNAVAILABLE for an HDF5 file.
[[nodiscard]] LoadResult read_blob_file(const std::string& path, TableData& data, bool& single_precision);

//! True if the bytes start like an HDF5 file (signature at offset 0).
[[nodiscard]] bool looks_like_hdf5(const void* bytes, std::size_t size) noexcept;

}  // namespace ctab::lookup

namespace ctab::lookup {

//! A C header holding `blob` as `static const unsigned char NAME[]` (8-byte aligned) and `NAME_size`, for
//! ctab_table_open_memory(NAME, NAME_size, ...) on targets without a file system. `name` must be a C identifier.
[[nodiscard]] std::string blob_c_header(const std::vector<unsigned char>& blob, const std::string& name);

}  // namespace ctab::lookup
