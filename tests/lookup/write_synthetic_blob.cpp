// SPDX-License-Identifier: Apache-2.0
// Test helper: writes a synthetic table blob (flange jump at 6.5 mm, 3 loads) and the C library's answers to a
// fixed list of queries (raw ctab_result records), for the Python wrapper test and the HIL loop smoke test.
//   lookup_write_synthetic_blob OUT.blob OUT.results [OUT.h]   (OUT.h: the blob as a C header, ctab export's format)
//   lookup_write_synthetic_blob --adaptive OUT.blob   (the adaptive axis of test::adaptive_options, for ctab bench)
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "ctab/lookup/blob.hpp"
#include "synthetic_table.hpp"

namespace {

bool write_file(const char* path, const std::vector<unsigned char>& bytes) {
  std::FILE* out = std::fopen(path, "wb");
  return out != nullptr && std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size() && std::fclose(out) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ctab::lookup;
  if (argc == 3 && std::strcmp(argv[1], "--adaptive") == 0)
    return write_file(argv[2], write_blob(test::make_synthetic(test::adaptive_options()), false)) ? 0 : 1;
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: lookup_write_synthetic_blob OUT.blob OUT.results [OUT.h]\n");
    return 2;
  }
  const std::vector<unsigned char> blob = write_blob(test::make_synthetic({.n_second = 3, .failed_case = true}), false);
  if (!write_file(argv[1], blob)) return 1;
  if (argc == 4) {
    const std::string header = blob_c_header(blob, "ctab_synthetic_blob");
    if (!write_file(argv[3], std::vector<unsigned char>(header.begin(), header.end()))) return 1;
  }
  ctab_table* table = nullptr;
  if (ctab_table_open_memory(blob.data(), blob.size(), nullptr, &table) != CTAB_OK) return 1;
  // The queries (same list in lookup/python/tests/check_wrapper.py): dy from -13 to 13 mm, loads, both wheels.
  std::FILE* out = std::fopen(argv[2], "wb");
  if (out == nullptr) return 1;
  for (int i = 0; i <= 260; ++i)
    for (int k = 0; k < 3; ++k)
      for (int wheel = 0; wheel < 2; ++wheel) {
        ctab_result r;
        std::memset(&r, 0, sizeof r);
        ctab_query(table, -13e-3 + 0.1e-3 * i, 50e3 + 27e3 * k, wheel, &r);
        if (std::fwrite(&r, sizeof r, 1, out) != 1) return 1;
      }
  ctab_table_close(table);
  return std::fclose(out) == 0 ? 0 : 1;
}
