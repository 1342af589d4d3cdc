// SPDX-License-Identifier: Apache-2.0
#pragma once
//! `ctab bench accuracy --creep DIR`: the tangential ladder against CONTACT (ctab/validation/creep_validation.hpp)
//! into OUT/creep.csv and a summary on stdout (chart: scripts/creep_chart.py OUT/creep.csv OUT/creep).
#include <string>

namespace ctab::cli {

//! Runs the ladder on CONTACT's tangential references under `reference_dir` (creep_zfix.csv; the profiles in
//! ../../../../profiles as the README there says). Returns the exit code.
int run_creep_accuracy(const std::string& out_dir, const std::string& reference_dir);

}  // namespace ctab::cli
