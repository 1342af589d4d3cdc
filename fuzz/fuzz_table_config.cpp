// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the TOML table config (generator/sweep parse_table_config) on any text. InputError is the
// parser's answer to a bad config; anything else is a finding.
#include <cstdint>
#include <string>

#include "ctab/core/error.hpp"
#include "ctab/sweep/table_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const ctab::gen::TableConfig config =
        ctab::gen::parse_table_config(std::string(reinterpret_cast<const char*>(data), size), "fuzz.toml");
    static_cast<void>(ctab::gen::table_memory_bytes(config));
  } catch (const ctab::gen::InputError&) {
  }
  return 0;
}
