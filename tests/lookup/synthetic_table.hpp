#pragma once
// Synthetic contact tables built in memory for the lookup tests: every patch quantity is linear in dy and in the
// second axis (so linear interpolation is exact inside interpolable cells), a flange slot that appears in one
// cell (with its jump), a spare slot whose contact point moves (a Moves jump), and optionally a failed case.
#include <cstddef>
#include <string>
#include <vector>

#include "ctab/lookup/ctab_lookup.h"
#include "ctab/lookup/table_data.hpp"

namespace ctab::lookup::test {

struct SyntheticOptions {
  double dy_min_m = -12e-3, dy_max_m = 12e-3, dy_step_m = 1e-3;
  std::size_t n_second = 1;  //!< vertical loads 60, 80, 100 ... kN
  std::size_t strip_samples = 5;
  double flange_from_m = 6.5e-3;         //!< flange slot present for dy >= this (not a grid point: jump inside a cell)
  double moves_at_m = -4.5e-3;           //!< spare slot's y_rail jumps by 5 mm here
  bool failed_case = false;              //!< right wheel at dy = -8 mm (first row) fails: MaxIterations
  bool second_row_flange_later = false;  //!< with n_second > 1: rows >= 1 get the flange 1 mm later
  //! A refined zone of the dy axis: nodes from refine_from_m to refine_to_m every refine_step_m between the
  //! uniform ones (0: none).
  double refine_from_m = 0.0, refine_to_m = 0.0, refine_step_m = 0.0;
};

//! The value of quantity q of slot s, wheel w, at (dy, second) where the patch exists (linear in both).
double synthetic_value(std::size_t q, std::size_t s, std::size_t w, double dy_m, double second);

TableData make_synthetic(const SyntheticOptions& options = {});

//! True when two answer lists are byte-identical.
bool identical(const std::vector<ctab_result>& a, const std::vector<ctab_result>& b);
//! The bytes of a C header written by blob_c_header (`ctab export --format c-header`), parsed back.
std::vector<unsigned char> parse_c_header(const std::string& text);

}  // namespace ctab::lookup::test
