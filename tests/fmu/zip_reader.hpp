// SPDX-License-Identifier: Apache-2.0
#pragma once
// A minimal ZIP reader for the FMU harness (stored and deflated entries, CRC-32 checked; no ZIP64), so that the
// test depends on no unzip tool. Throws std::runtime_error on anything it cannot read.
#include <map>
#include <string>
#include <vector>

namespace ctab::fmu::test {

//! Every file entry of the archive, by name.
std::map<std::string, std::vector<unsigned char>> read_zip(const std::vector<unsigned char>& archive);

}  // namespace ctab::fmu::test
