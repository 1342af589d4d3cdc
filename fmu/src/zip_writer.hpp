// SPDX-License-Identifier: Apache-2.0
#pragma once
// A minimal ZIP archive writer (PKWARE APPNOTE 6.3: local headers, central directory, end record; no ZIP64):
// entries deflated with zlib where that makes them smaller, stored otherwise, with CRC-32 and a fixed time stamp
// so that the same inputs give the same archive bytes.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ctab::fmu {

class ZipWriter {
 public:
  //! Appends a file entry; `executable` marks it 0755 (else 0644) for Unix unzippers. Throws gen::Error where the
  //! archive would need ZIP64 (an entry or the archive over 4 GiB, more than 65535 entries).
  void add(const std::string& name, const void* data, std::size_t size, bool executable = false);
  //! The archive: the entries, then the central directory and its end record.
  [[nodiscard]] std::vector<unsigned char> finish() const;
  //! The local header this writer gives a deflated entry `name`, with CRC and sizes zero (bytes 14 to 25): what an
  //! archive it wrote starts with, but for those.
  [[nodiscard]] static std::string first_header_start(const std::string& name);

 private:
  struct Entry {
    std::string name;
    std::uint32_t crc = 0, compressed_size = 0, size = 0, offset = 0;
    std::uint16_t method = 0;  // 0 stored, 8 deflated
    bool executable = false;
  };
  static void put_entry_fields(std::vector<unsigned char>& out, const Entry& e);
  static void put_local_header(std::vector<unsigned char>& out, const Entry& e);
  std::vector<unsigned char> bytes_;
  std::vector<Entry> entries_;
};

}  // namespace ctab::fmu
