// SPDX-License-Identifier: Apache-2.0
// ZIP reader of the FMU harness (zip_reader.hpp): end record, central directory, local headers, inflate.
#include "zip_reader.hpp"

#include <zlib.h>

#include <cstdint>
#include <stdexcept>

namespace ctab::fmu::test {

namespace {

std::uint32_t get(const std::vector<unsigned char>& b, std::size_t at, int bytes) {
  if (at + static_cast<std::size_t>(bytes) > b.size()) throw std::runtime_error("zip: truncated");
  std::uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | b[at + static_cast<std::size_t>(i)];
  return v;
}

std::vector<unsigned char> inflate_raw(const unsigned char* data, std::size_t size, std::size_t expected) {
  std::vector<unsigned char> out(expected);
  z_stream z{};
  if (inflateInit2(&z, -15) != Z_OK) throw std::runtime_error("zip: inflateInit2");
  z.next_in = const_cast<unsigned char*>(data);
  z.avail_in = static_cast<uInt>(size);
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  const int result = inflate(&z, Z_FINISH);
  const std::size_t produced = z.total_out;
  inflateEnd(&z);
  if (result != Z_STREAM_END || produced != expected) throw std::runtime_error("zip: bad deflate stream");
  return out;
}

}  // namespace

std::map<std::string, std::vector<unsigned char>> read_zip(const std::vector<unsigned char>& b) {
  if (b.size() < 22) throw std::runtime_error("zip: too short");
  std::size_t end = b.size() - 22;
  while (get(b, end, 4) != 0x06054b50u) {
    if (end == 0 || b.size() - end > 22 + 0xffff) throw std::runtime_error("zip: no end of central directory");
    --end;
  }
  const std::uint32_t count = get(b, end + 10, 2);
  std::size_t at = get(b, end + 16, 4);
  std::map<std::string, std::vector<unsigned char>> files;
  for (std::uint32_t i = 0; i < count; ++i) {
    if (get(b, at, 4) != 0x02014b50u) throw std::runtime_error("zip: bad central directory entry");
    const std::uint32_t method = get(b, at + 10, 2), crc = get(b, at + 16, 4), packed = get(b, at + 20, 4),
                        size = get(b, at + 24, 4), name_length = get(b, at + 28, 2);
    const std::size_t local = get(b, at + 42, 4);
    const std::string name(b.begin() + static_cast<std::ptrdiff_t>(at + 46),
                           b.begin() + static_cast<std::ptrdiff_t>(at + 46 + name_length));
    at += 46 + name_length + get(b, at + 30, 2) + get(b, at + 32, 2);
    if (get(b, local, 4) != 0x04034b50u) throw std::runtime_error("zip: bad local header of " + name);
    const std::size_t data = local + 30 + get(b, local + 26, 2) + get(b, local + 28, 2);
    if (data + packed > b.size()) throw std::runtime_error("zip: truncated entry " + name);
    std::vector<unsigned char> content;
    if (method == 0 && packed == size) content.assign(b.begin() + static_cast<std::ptrdiff_t>(data),
                                                      b.begin() + static_cast<std::ptrdiff_t>(data + size));
    else if (method == 8) content = inflate_raw(b.data() + data, packed, size);
    else throw std::runtime_error("zip: unsupported method of " + name);
    if (crc32(crc32(0L, Z_NULL, 0), content.data(), static_cast<uInt>(content.size())) != crc)
      throw std::runtime_error("zip: CRC-32 mismatch in " + name);
    files[name] = std::move(content);
  }
  return files;
}

}  // namespace ctab::fmu::test
