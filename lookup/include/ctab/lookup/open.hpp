// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Loading a ctab::lookup::Table from a blob in memory or in a file (the core's own loaders; HDF5 tables load
//! through ctab_lookup_hdf5, ctab/lookup/hdf5_table.hpp).
#include <cstddef>
#include <string>

#include "ctab/lookup/table.hpp"

namespace ctab::lookup {

//! Loads a blob held in memory (copied; the bytes may be released afterwards). A float blob loads as single
//! precision whatever `options` says.
[[nodiscard]] LoadResult open_memory(const void* bytes, std::size_t size, const LoadOptions& options, Table& table);
//! Reads a blob file and loads it; an HDF5 file gives CTAB_ERR_HDF5_UNAVAILABLE.
[[nodiscard]] LoadResult open_blob_file(const std::string& path, const LoadOptions& options, Table& table);

}  // namespace ctab::lookup
