// SPDX-License-Identifier: Apache-2.0
#pragma once
//! What `ctab solve` adds to the sweep's per-case API (gen::make_sweep_setup, gen::solve_table_case in
//! ctab/sweep/table_generator.hpp, the same code `ctab generate` runs): set-up errors that name command-line
//! options, and the geometry checks behind its messages (a wheel off its rail, why a wheel failed).
#include <cstddef>
#include <string>

#include "ctab/sweep/table_generator.hpp"

namespace ctab::cli {

//! gen::make_sweep_setup; for a config built from command-line options (source kCommandLineSource) its errors name
//! the option ("--wheel: ...") instead of the config key. Throws InputError.
[[nodiscard]] gen::SweepSetup make_case_setup(const gen::TableConfig& config);

//! True when the wheel (0 right, 1 left) has a point above its rail at the wheelset's shift and roll (track frame);
//! otherwise it is off its rail.
[[nodiscard]] bool wheel_over_rail(const gen::SweepSetup& setup, std::size_t wheel, double dy_m, double roll_rad);

//! Why a solved wheel failed, when the geometry tells ("" otherwise): roll iteration failed, wheel off the rail,
//! first contact at the end of the wheel or rail profile (a shift beyond what the profiles cover).
[[nodiscard]] std::string failure_hint(const gen::SweepSetup& setup, std::size_t wheel,
                                       const gen::CaseSolution& solution);

}  // namespace ctab::cli
