// SPDX-License-Identifier: Apache-2.0
#pragma once
//! SHA-256 (FIPS 180-4) of a byte buffer, as 64 lower-case hex digits. For table provenance.
#include <cstddef>
#include <string>

namespace ctab::gen {

//! With the CPU's SHA extensions where it has them (x86-64), else portable C++: the same digest.
[[nodiscard]] std::string sha256_hex(const void* data, std::size_t size);
//! Portable C++ only (the reference the SHA-extension path is tested against).
[[nodiscard]] std::string sha256_hex_portable(const void* data, std::size_t size);
//! True where sha256_hex uses the CPU's SHA extensions.
[[nodiscard]] bool sha256_has_cpu_extensions() noexcept;

}  // namespace ctab::gen
