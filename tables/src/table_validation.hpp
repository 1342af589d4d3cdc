// SPDX-License-Identifier: Apache-2.0
#pragma once
// Content checks of a table that has been read (private header): axes, finite values, signs, status values,
// presence flags, zeros where a slot is empty, failed cases without patches, jumps in range.
#include <string>

#include "ctab/tables/table.hpp"

namespace ctab::tables::detail {

//! Ok, or InvalidContent with a message naming `path`, the dataset and the first bad index.
[[nodiscard]] TableResult validate_contents(Table& table, const std::string& path);

}  // namespace ctab::tables::detail
