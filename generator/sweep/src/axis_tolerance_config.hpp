// SPDX-License-Identifier: Apache-2.0
#pragma once
// [axes] tolerance of a table config (TableConfig::axis_tolerance): parsed and checked here. Private to the sweep
// library; throws InputError naming the file, line and key.
#include <optional>
#include <string>
#include <toml++/toml.h>

#include "ctab/sweep/table_config.hpp"

namespace ctab::gen::detail {

//! The [axes] tolerance table of `root`, or nullopt without one. `source` names the file in errors.
[[nodiscard]] std::optional<AxisTolerance> read_axis_tolerance(const toml::table& root, const std::string& source);

}  // namespace ctab::gen::detail
