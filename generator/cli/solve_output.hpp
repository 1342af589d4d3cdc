// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Output of `ctab solve`: readable summaries and JSON of a gap-profile solution and of a wheel-rail case, and the
//! one-line stderr report of every wheel that did not succeed.
#include <nlohmann/json.hpp>

#include "ctab/contact/normal_solution.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"

namespace ctab::cli {

void print_summary(const gen::NormalSolution& solution);
//! A header line (set-up, dy, roll, load), then each solved wheel with its patches and near misses.
void print_summary(const gen::TableConfig& config, const gen::CaseSolution& solution);
//! {"mode", "method", "dy_m", "roll_rad", "roll_converged", "load_kind", "load_value", "config_source",
//!  "right": {...}, "left": {...}} with each wheel as gen::to_json(WheelContact) with the wheelset's dy and roll
//! (track frame) and the table's status name; only solved wheels appear.
[[nodiscard]] nlohmann::json to_json(const gen::TableConfig& config, const gen::CaseSolution& solution);
//! Adds "wheel_profile_smoothing" and "rail_profile_smoothing" ({automatic, length_m, length_near_jumps_m, noise_sigma_m}) for the
//! profiles read from point files (built-in profiles are analytic and have none).
void add_smoothing(nlohmann::json& json, const gen::SweepSetup& setup);
//! One line on stderr per solved wheel whose status is not a success, with the geometry's hint; true if any.
bool report_failures(const gen::TableConfig& config, const gen::SweepSetup& setup, const gen::CaseSolution& solution);

}  // namespace ctab::cli
