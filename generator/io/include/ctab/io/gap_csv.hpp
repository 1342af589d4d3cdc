// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Reader for gap CSV files: header `y_m,h_m,A_per_m,B_per_m` (any order, extra columns ignored), one row per
//! lateral station, SI units; h_m is the separation before loading (>= 0, to 1 nm). '#' starts a comment line. Errors
//! name file, line and field.
#include <istream>
#include <string>

#include "ctab/contact/gap_profile.hpp"

namespace ctab::gen {

//! Parses a gap CSV from a stream; `source` names it in errors. Throws InputError.
[[nodiscard]] GapProfile parse_gap_csv(std::istream& in, const std::string& source);
//! Reads and validates a gap CSV file. Throws InputError (missing file, bad line, non-finite value, ...).
[[nodiscard]] GapProfile read_gap_csv(const std::string& path);
//! Writes a gap profile as CSV (full double precision).
void write_gap_csv(const GapProfile& gap, std::ostream& out);

}  // namespace ctab::gen
