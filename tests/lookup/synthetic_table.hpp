// SPDX-License-Identifier: Apache-2.0
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
  //! More nodes of the dy axis (merged in; a node within 0.2 um of the one before it is dropped).
  std::vector<double> extra_dy_m = {};
};

//! An adaptive axis as the generator writes one: 0.5 mm steps over -12 .. 12 mm and 34 clusters graded from 1 um to
//! 0.6 mm (nodes at +-0.5, 1.5, 4, 10, 25, 60, 150 and 300 um about each centre): 593 nodes, the default table's
//! shape otherwise (one load, 3 slots, 32 strip samples).
SyntheticOptions adaptive_options();

//! The value of quantity q of slot s, wheel w, at (dy, second) where the patch exists (linear in both).
double synthetic_value(std::size_t q, std::size_t s, std::size_t w, double dy_m, double second);

TableData make_synthetic(const SyntheticOptions& options = {});

//! A table in the format of located jumps: an adaptive dy axis (0.5 mm coarse steps, graded down to a 1 um cell at
//! each jump: nodes at x +- 0.5, 3, 20 and 100 um) whose jump cells' ends hold the one-sided values. Per second-axis
//! row (60, 80, 100 ... kN, one per entry of the lists) slot 0 disappears at disappears_at_m, slot 1 appears at
//! appears_at_m, and slot 2's values move by kLocatedMove x the quantity's weight at moves_at_m, both wheels alike.
//! On each side of a jump every value is synthetic_value (linear in dy and load).
struct LocatedOptions {
  std::vector<double> disappears_at_m = {-3.21e-3, -3.21e-3, -2.63e-3};
  std::vector<double> appears_at_m = {1.234e-3, 2.071e-3, 1.552e-3};
  std::vector<double> moves_at_m = {-1.117e-3, -0.383e-3, -0.941e-3};
  double dy_min_m = -5e-3, dy_max_m = 5e-3, coarse_step_m = 0.5e-3;
};
inline constexpr double kLocatedMove = 100.0;
//! Half the width of a located jump's cell.
inline constexpr double kLocatedHalfCell = 0.5e-6;
//! The value of quantity q of slot s, wheel w at (dy, second) on the side of slot s's jump that `after` names (0
//! where the slot is absent there); `present` says whether it is.
double located_value(std::size_t q, std::size_t s, std::size_t w, double dy, double second, bool after,
                     bool& present);
//! Where row j's jump of slot s lies (its cell's midpoint).
double located_jump(const LocatedOptions& options, std::size_t slot, std::size_t row);
TableData make_located(const LocatedOptions& options = {});

//! True when two answer lists are byte-identical.
bool identical(const std::vector<ctab_result>& a, const std::vector<ctab_result>& b);
//! The bytes of a C header written by blob_c_header (`ctab export --format c-header`), parsed back.
std::vector<unsigned char> parse_c_header(const std::string& text);

}  // namespace ctab::lookup::test
