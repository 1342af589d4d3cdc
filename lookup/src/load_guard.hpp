// SPDX-License-Identifier: Apache-2.0
#pragma once
// Loading is the only part of the lookup that allocates (query and strip profiles are built without exceptions):
// an allocation that fails there becomes CTAB_ERR_OUT_OF_MEMORY instead of an exception through the C API.
#include <exception>

#include "ctab/lookup/table_data.hpp"

namespace ctab::lookup::detail {

//! Runs `load()` (returning a LoadResult); a failed allocation (std::bad_alloc, or std::length_error for a size
//! beyond what a vector can hold) gives CTAB_ERR_OUT_OF_MEMORY. The message fits the string's own buffer, so that
//! making it allocates nothing.
template <typename Load>
LoadResult guard_allocation(Load&& load) noexcept {
  try {
    return load();
  } catch (const std::exception&) {
    LoadResult out;
    out.status = CTAB_ERR_OUT_OF_MEMORY;
    out.message = "out of memory";
    return out;
  }
}

}  // namespace ctab::lookup::detail
