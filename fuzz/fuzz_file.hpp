// SPDX-License-Identifier: Apache-2.0
#pragma once
// Fuzz targets' scratch file: readers that take a path get the fuzz input through one file per process, in
// $TMPDIR (/dev/shm when unset, so that a million executions write to memory, not to a disk).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace ctab::fuzz {

//! `<dir>/ctab-fuzz-<pid><suffix>`; the same path for every call of this process with the same suffix.
inline std::string scratch_path(const std::string& suffix) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir != nullptr && *dir != '\0' ? dir : "/dev/shm") + "/ctab-fuzz-" + std::to_string(getpid()) +
         suffix;
}

//! Writes `size` bytes to `path`; aborts (a harness fault, not a finding) when the file cannot be written.
inline void write_scratch(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::FILE* out = std::fopen(path.c_str(), "wb");
  if (out == nullptr || (size > 0 && std::fwrite(data, 1, size, out) != size) || std::fclose(out) != 0) {
    std::perror(path.c_str());
    std::abort();
  }
}

}  // namespace ctab::fuzz
