// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The FMU's instantiationToken: a fingerprint of the table blob it carries, written into modelDescription.xml by
//! the exporter and recomputed by the wrapper from resources/ at instantiation, so that a description and a table
//! that do not belong together are refused.
#include <cstddef>
#include <cstdio>

#include "ctab/lookup/blob.hpp"

namespace ctab::fmu {

inline constexpr std::size_t kTokenSize = 64;

inline void instantiation_token(const void* blob, std::size_t size, char (&token)[kTokenSize]) noexcept {
  std::snprintf(token, kTokenSize, "{ctab-blob-fnv1a64-%016llx-%zu}",
                static_cast<unsigned long long>(lookup::fnv1a64(blob, size)), size);
}

}  // namespace ctab::fmu
