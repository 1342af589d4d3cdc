// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text shared by the benches' CSV files: numbers and the names of bem2d references.
#include <cmath>
#include <cstdio>
#include <string>

#include "ctab/core/number_text.hpp"

namespace ctab::gen::detail {

//! A CSV field: number_text, empty for NaN and infinities.
inline std::string csv_number(double v) { return std::isfinite(v) ? number_text(v) : ""; }

//! "bem2d_0.1mm": bem2d at element size `width_m` [m] as a reference.
inline std::string bem2d_reference_name(double width_m) {
  char name[32];
  std::snprintf(name, sizeof name, "bem2d_%gmm", width_m * 1e3);
  return name;
}

}  // namespace ctab::gen::detail
