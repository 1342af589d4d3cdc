// SPDX-License-Identifier: Apache-2.0
#pragma once
// modelDescription.xml of a table's FMU (FMI 3.0, section 2.4 "FMI Description Schema"): Co-Simulation, the units
// the variables use, the variables of variables.hpp for this table, and the model structure.
#include <string>

#include "ctab/lookup/ctab_lookup.h"

namespace ctab::fmu {

struct DescriptionInfo {
  std::string token;            //!< instantiationToken (token.hpp)
  std::string generation_tool;  //!< "ctab 0.2.0"
  std::string source;           //!< the table file the FMU was exported from (its name only)
};

[[nodiscard]] std::string model_description(const ctab_table* table, const DescriptionInfo& info);

}  // namespace ctab::fmu
