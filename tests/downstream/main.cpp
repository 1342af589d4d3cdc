// SPDX-License-Identifier: Apache-2.0
// Uses the installed ctab: headers, the static ctab::tables and its HDF5 link, ctab::lookup (and the generator
// libraries when CTAB_DOWNSTREAM_WITH_GENERATOR). Exit code 0 when every call behaves as documented.
#include <iostream>
#include <string>

#include "ctab/lookup/ctab_lookup.h"
#include "ctab/tables/table.hpp"
#ifdef CTAB_DOWNSTREAM_WITH_GENERATOR
#include "ctab/contact/material.hpp"
#endif

int main() {
  const std::string path = "/nonexistent/ctab_downstream.h5";
  ctab::tables::Table table;
  const ctab::tables::TableResult result = ctab::tables::read_table(path, table);
  std::cout << "ctab tables schema " << ctab::tables::kSchemaVersion << "; reading " << path << ": " << result.message
            << "\n";
  if (result.ok() || result.message.find(path) == std::string::npos) {
    std::cerr << "expected a failed read naming " << path << "\n";
    return 1;
  }
  // The lookup core (ctab::lookup, no dependencies): a missing file is a status, never a crash.
  ctab_table* lookup = nullptr;
  const ctab_status opened = ctab_table_open(path.c_str(), nullptr, &lookup);
  std::cout << "ctab lookup: " << ctab_status_message(opened) << "\n";
  if (opened != CTAB_ERR_CANNOT_OPEN || lookup != nullptr) {
    std::cerr << "expected CTAB_ERR_CANNOT_OPEN from ctab_table_open\n";
    return 1;
  }
#ifdef CTAB_DOWNSTREAM_WITH_GENERATOR
  // Steel on steel: E* = E / (2 (1 - nu^2)) = 114.3 GPa (paper Eq. 3).
  const double e_star_Pa = ctab::gen::effective_modulus(ctab::gen::kSteel, ctab::gen::kSteel);
  std::cout << "effective modulus of steel on steel: " << e_star_Pa << " Pa\n";
  if (!(e_star_Pa > 114.2e9 && e_star_Pa < 114.4e9)) return 1;
#endif
  return 0;
}
