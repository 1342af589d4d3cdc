// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Numbers in messages and text output of the generator: 6 significant digits (printf %.6g), the one spelling of
//! a value across error messages, option descriptions and the benches' CSV files.
#include <string>

namespace ctab::gen {

//! `value` as printf's %.6g writes it ("0.0785", "1e-06", "inf", "nan").
[[nodiscard]] std::string number_text(double value);

}  // namespace ctab::gen
