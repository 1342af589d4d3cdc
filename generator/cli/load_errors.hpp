// SPDX-License-Identifier: Apache-2.0
#pragma once
//! A failed table load as the CLI reports it: out of memory is a resource failure (exit 3), anything else is an
//! input error (exit 2); the message is the loader's.
#include "ctab/core/error.hpp"
#include "ctab/lookup/table_data.hpp"
#include "exit_codes.hpp"

namespace ctab::cli {

inline void throw_if_failed(const lookup::LoadResult& result) {
  if (result.ok()) return;
  if (result.status == CTAB_ERR_OUT_OF_MEMORY) throw IoError(result.message + " (out of memory)");
  throw gen::Error(result.message);
}

}  // namespace ctab::cli
