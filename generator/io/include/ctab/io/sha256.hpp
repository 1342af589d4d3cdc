#pragma once
//! SHA-256 (FIPS 180-4) of a byte buffer, as 64 lower-case hex digits. For table provenance.
#include <cstddef>
#include <string>

namespace ctab::gen {

[[nodiscard]] std::string sha256_hex(const void* data, std::size_t size);

}  // namespace ctab::gen
