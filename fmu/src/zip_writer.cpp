// SPDX-License-Identifier: Apache-2.0
// ZIP archive writer (zip_writer.hpp).
#include "zip_writer.hpp"

#include <zlib.h>

#include <limits>

#include "ctab/core/error.hpp"

namespace ctab::fmu {

namespace {

constexpr std::uint16_t kVersionNeeded = 20;                // 2.0: deflate
constexpr std::uint16_t kVersionMadeBy = (3u << 8) | 20u;   // Unix host, 2.0 (external attributes hold the mode)
constexpr std::uint16_t kDosTime = 0, kDosDate = (0u << 9) | (1u << 5) | 1u;  // 1980-01-01 00:00
constexpr std::uint16_t kUtf8Names = 1u << 11;

void put16(std::vector<unsigned char>& out, std::uint32_t v) {
  out.push_back(static_cast<unsigned char>(v & 0xffu));
  out.push_back(static_cast<unsigned char>((v >> 8) & 0xffu));
}
void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  put16(out, v & 0xffffu);
  put16(out, v >> 16);
}
void put_bytes(std::vector<unsigned char>& out, const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  out.insert(out.end(), p, p + size);
}

std::uint32_t checked32(std::size_t n, const char* what) {
  if (n > std::numeric_limits<std::uint32_t>::max()) throw gen::Error(std::string("FMU archive: ") + what + " over 4 GiB");
  return static_cast<std::uint32_t>(n);
}

// Raw deflate (no zlib header) of `data`; empty when it does not make the data smaller.
std::vector<unsigned char> deflate_raw(const void* data, std::size_t size) {
  z_stream z{};
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -15, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw gen::Error("FMU archive: zlib deflateInit2 failed");
  std::vector<unsigned char> out(deflateBound(&z, static_cast<uLong>(size)));
  z.next_in = static_cast<Bytef*>(const_cast<void*>(data));
  z.avail_in = static_cast<uInt>(size);
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  const int result = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (result != Z_STREAM_END || out.size() >= size) out.clear();
  return out;
}

}  // namespace

// The fields a local header and a central directory entry share: version needed to extract to name length.
void ZipWriter::put_entry_fields(std::vector<unsigned char>& out, const Entry& e) {
  put16(out, kVersionNeeded);
  put16(out, kUtf8Names);
  put16(out, e.method);
  put16(out, kDosTime);
  put16(out, kDosDate);
  put32(out, e.crc);
  put32(out, e.compressed_size);
  put32(out, e.size);
  put16(out, static_cast<std::uint32_t>(e.name.size()));
}

void ZipWriter::put_local_header(std::vector<unsigned char>& out, const Entry& e) {
  put32(out, 0x04034b50u);  // local file header
  put_entry_fields(out, e);
  put16(out, 0);  // no extra field
  put_bytes(out, e.name.data(), e.name.size());
}

std::string ZipWriter::first_header_start(const std::string& name) {
  Entry e;
  e.name = name;
  e.method = 8;
  std::vector<unsigned char> out;
  put_local_header(out, e);
  return std::string(out.begin(), out.end());
}

void ZipWriter::add(const std::string& name, const void* data, std::size_t size, bool executable) {
  if (entries_.size() >= 0xffffu) throw gen::Error("FMU archive: too many entries");
  Entry e;
  e.name = name;
  e.executable = executable;
  e.size = checked32(size, "an entry");
  e.crc = static_cast<std::uint32_t>(crc32(crc32(0L, Z_NULL, 0), static_cast<const Bytef*>(data), e.size));
  e.offset = checked32(bytes_.size(), "the archive");
  const std::vector<unsigned char> packed = size > 0 ? deflate_raw(data, size) : std::vector<unsigned char>{};
  e.method = packed.empty() ? 0 : 8;
  e.compressed_size = packed.empty() ? e.size : static_cast<std::uint32_t>(packed.size());
  if (name.size() > 0xffffu) throw gen::Error("FMU archive: an entry name is too long");
  put_local_header(bytes_, e);
  if (packed.empty()) put_bytes(bytes_, data, size);
  else put_bytes(bytes_, packed.data(), packed.size());
  checked32(bytes_.size(), "the archive");
  entries_.push_back(std::move(e));
}

std::vector<unsigned char> ZipWriter::finish() const {
  std::vector<unsigned char> out = bytes_;
  const std::uint32_t directory_offset = checked32(out.size(), "the archive");
  for (const Entry& e : entries_) {
    put32(out, 0x02014b50u);  // central directory file header
    put16(out, kVersionMadeBy);
    put_entry_fields(out, e);
    put16(out, 0);  // extra field
    put16(out, 0);  // comment
    put16(out, 0);  // disk number
    put16(out, 0);  // internal attributes
    put32(out, (e.executable ? 0100755u : 0100644u) << 16);  // Unix mode: regular file
    put32(out, e.offset);
    put_bytes(out, e.name.data(), e.name.size());
  }
  const std::uint32_t directory_size = checked32(out.size() - directory_offset, "the directory");
  put32(out, 0x06054b50u);  // end of central directory
  put16(out, 0);
  put16(out, 0);
  put16(out, static_cast<std::uint32_t>(entries_.size()));
  put16(out, static_cast<std::uint32_t>(entries_.size()));
  put32(out, directory_size);
  put32(out, directory_offset);
  put16(out, 0);  // comment length
  checked32(out.size(), "the archive");
  return out;
}

}  // namespace ctab::fmu
