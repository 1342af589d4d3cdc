// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the gap CSV reader (generator/io gap_csv.hpp) on any text. InputError is the reader's answer
// to a bad file; anything else (another exception, a crash, a sanitizer report) is a finding.
#include <cstdint>
#include <sstream>
#include <string>

#include "ctab/core/error.hpp"
#include "ctab/io/gap_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const ctab::gen::GapProfile gap = ctab::gen::parse_gap_csv(in, "fuzz.csv");
    std::ostringstream out;
    ctab::gen::write_gap_csv(gap, out);  // what was accepted must write back
  } catch (const ctab::gen::InputError&) {
  }
  return 0;
}
