// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Options of the MIM-1D solver (mim1d.hpp), free of Eigen so that configurations can hold them.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "ctab/contact/strip_compliance.hpp"

namespace ctab::gen {

enum class Mim1dUpdate : std::int8_t {
  FixedPoint = 0,  //!< the paper's successive substitution (Figure 3)
  Newton = 1,      //!< Newton on the strip loads (default)
};

struct Mim1dOptions {
  double strip_width_m = 0.2e-3;  //!< 2b [m]
  Mim1dUpdate update = Mim1dUpdate::Newton;
  CurvatureOptions curvature;  //!< lateral-curvature treatment in Eq. 26
  //! Relative convergence tolerance (loads, force) [-]: a few hundred times double round-off, which Newton reaches
  //! in 7-40 iterations on the wheel-rail and paper cases (ctab bench wheelrail, ctab paper-cases).
  double tolerance = 1.0e-11;
  //! Inner iterations per approach: those cases need 7-40; 300 leaves a wide margin (the fixed-point update is
  //! slower) and bounds a hopeless case.
  int max_iterations = 300;
  //! Iterations on delta for a prescribed load (the fallback outer loop, a safeguarded Newton/bisection).
  int max_outer_iterations = 60;
  //! Initial potential zone [y_min, y_max] [m] (Figure 7 experiments); default: the interpenetration zone.
  std::optional<std::pair<double, double>> starting_zone_m;
};

//! A converged MIM-1D solution carried to a neighbouring gap (the next lateral shift of a table sweep) as the
//! starting point of its solve: the strip loads by strip index k (strip centre (k + 1/2) 2b from the gap's y = 0,
//! strip_grid.hpp) and the approach beyond the gap's deepest point. Only the start changes: the solve converges to
//! the same tolerance, so the result agrees with a cold start within Mim1dOptions::tolerance.
struct Mim1dWarmStart {
  long first_strip = 0;         //!< strip index k of loads_N[0]
  std::vector<double> loads_N;  //!< strip loads N_k [N] (0 for strips out of contact); empty: no warm start
  double depth_m = 0.0;         //!< approach minus the deepest separation of the grid [m]
  //! Where the saved grid's y = 0 lay, in the caller's terms (wheel-rail: the patch's reference point, rail y [m],
  //! and its plane angle [rad]), so that the start can be moved onto a grid with another origin
  //! (move_warm_start_origin), and the caller's sampling approach of that grid (wheel-rail: the vertical approach
  //! at which the gap was sampled [m]). The solver does not read them.
  double origin_y_m = 0.0, origin_angle_rad = 0.0, sampling_approach_m = 0.0;
  //! True when the start is an earlier solve of the same contact (wheel-rail: the previous gap pass of the case),
  //! whose set the solve itself chose: it applies even where several basins of h interpenetrate. False (a
  //! neighbour's solution): such a gap starts cold (Mim1dSolver::solve_for_load).
  bool same_contact = false;
  //! The solve before this one in an equally spaced chain (wheel-rail: the lateral shift one step back; empty:
  //! none), so that the next solve starts from the two extrapolated (extrapolate_warm_start). The solver does not
  //! read it, and Mim1dSolver::save_warm_start leaves it alone.
  struct Earlier {
    long first_strip = 0;
    std::vector<double> loads_N;  //!< [N]; empty: no earlier solve
    double depth_m = 0.0, sampling_approach_m = 0.0;
  } earlier;
  [[nodiscard]] bool empty() const noexcept { return loads_N.empty(); }
  void clear() noexcept {
    loads_N.clear();
    earlier.loads_N.clear();
  }
  //! The current solve becomes the earlier one (its storage swapped, not copied); loads_N is left to be refilled.
  void push_back_to_earlier() noexcept {
    earlier.first_strip = first_strip;
    earlier.loads_N.swap(loads_N);
    earlier.depth_m = depth_m;
    earlier.sampling_approach_m = sampling_approach_m;
    loads_N.clear();
  }
};

}  // namespace ctab::gen
