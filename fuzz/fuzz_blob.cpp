// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the blob loader (ctab_table_open_memory) and queries on whatever loads. Each input is loaded
// twice: as given (header, sizes and checksum checks), and with its header's payload size and checksum made to
// match (so that mutations reach the checks of the contents behind the checksum). A table that loads is queried
// at its axes' ends, inside, outside and at non-finite points, for both wheels and every slot's strip profile:
// no query may crash or read out of bounds, whatever the table holds.
#include <cstdint>
#include <cstring>
#include <vector>

#include "ctab/lookup/blob.hpp"
#include "ctab/lookup/ctab_lookup.h"
#include "table_queries.hpp"

namespace {

void store_le64(unsigned char* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<unsigned char>(v >> (8 * i));
}

void load_and_query(const unsigned char* bytes, std::size_t size, const ctab_open_options& options) {
  ctab_table* table = nullptr;
  if (ctab_table_open_memory(bytes, size, &options, &table) == CTAB_OK) ctab::fuzz::query_everywhere(table);
  ctab_table_close(table);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ctab_open_options options;
  std::memset(&options, 0, sizeof options);
  options.interpolation = CTAB_LINEAR;
  load_and_query(data, size, options);
  if (size < ctab::lookup::kBlobHeaderBytes) return 0;
  std::vector<unsigned char> fixed(data, data + size);
  const std::size_t payload = size - ctab::lookup::kBlobHeaderBytes;
  store_le64(fixed.data() + 24, payload);
  store_le64(fixed.data() + 32, ctab::lookup::fnv1a64(fixed.data() + ctab::lookup::kBlobHeaderBytes, payload));
  // The second load picks PCHIP and single precision by the checksum's two lowest bits.
  options.interpolation = (fixed[32] & 1) ? CTAB_PCHIP : CTAB_LINEAR;
  options.single_precision = (fixed[32] & 2) ? 1 : 0;
  load_and_query(fixed.data(), fixed.size(), options);
  return 0;
}
