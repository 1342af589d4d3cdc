// SPDX-License-Identifier: Apache-2.0
#include "ctab/core/number_text.hpp"

#include <cstdio>

namespace ctab::gen {

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace ctab::gen
