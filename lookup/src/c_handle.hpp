// SPDX-License-Identifier: Apache-2.0
#pragma once
// The opaque C handle and the one way to create it (shared by the core's and ctab_lookup_hdf5's C loaders).
#include <new>

#include "ctab/lookup/ctab_lookup.h"
#include "ctab/lookup/table.hpp"
#include "load_guard.hpp"

struct ctab_table {
  ctab::lookup::Table table;
};

namespace ctab::lookup::detail {

inline LoadOptions load_options(const ctab_open_options* options) noexcept {
  LoadOptions result;
  if (options != nullptr) {
    result.interpolation = options->interpolation == CTAB_PCHIP ? CTAB_PCHIP : CTAB_LINEAR;
    result.single_precision = options->single_precision != 0;
  }
  return result;
}

//! Allocates a handle, runs `load(Table&)` (returning a LoadResult) and hands the handle out only on success.
template <typename Load>
ctab_status make_handle(ctab_table** out, Load&& load) noexcept {
  if (out == nullptr) return CTAB_INVALID_INPUT;
  *out = nullptr;
  auto* handle = new (std::nothrow) ctab_table;
  if (handle == nullptr) return CTAB_ERR_OUT_OF_MEMORY;
  const ctab_status status = guard_allocation([&] { return load(handle->table); }).status;
  if (status != CTAB_OK) {
    delete handle;
    return status;
  }
  *out = handle;
  return CTAB_OK;
}

}  // namespace ctab::lookup::detail
