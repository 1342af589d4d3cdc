// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Result of a normal-contact solve on a strip problem: per patch, the integral quantities and the strips.
#include <string>
#include <vector>

#include "ctab/contact/solve_status.hpp"

namespace ctab::gen {

//! One strip of a patch (MIM-1D: paper Eq. 7, semi-elliptic pressure along x).
struct StripSolution {
  double y_m = 0.0;            //!< strip centre, lateral coordinate [m]
  double half_length_m = 0.0;  //!< a_i, half-length along the rolling direction [m]
  double p0_Pa = 0.0;          //!< p0_i, peak pressure of the strip [Pa]
  double load_N = 0.0;         //!< N_i = pi a_i b p0_i, load carried by the strip [N] (paper Eq. A1)
};

//! A contact patch: a maximal run of loaded strips.
struct PatchSolution {
  double normal_force_N = 0.0;          //!< sum of the strip loads [N]
  double area_m2 = 0.0;                 //!< sum of 2 a_i * 2 b [m^2]
  double max_pressure_Pa = 0.0;         //!< max p0_i [Pa]
  double centre_of_pressure_y_m = 0.0;  //!< load-weighted mean strip centre [m]
  double y_min_m = 0.0;                 //!< lower edge of the first strip [m]
  double y_max_m = 0.0;                 //!< upper edge of the last strip [m]
  std::vector<StripSolution> strips;
};

struct NormalSolution {
  SolveStatus status = SolveStatus::InvalidInput;
  std::string method;          //!< "mim1d", "hertz", ...
  double approach_m = 0.0;     //!< rigid approach delta [m]
  double normal_load_N = 0.0;  //!< total normal force [N]
  int iterations = 0;          //!< inner iterations (linear solves), all outer iterations together
  int outer_iterations = 0;    //!< iterations on delta for a prescribed load (0 for a prescribed approach)
  double residual = 0.0;       //!< final relative residual (displacement for delta, force for load) [-]
  double solve_time_s = 0.0;   //!< wall-clock time of the solve [s]
  //! MIM-1D: entries of the influence matrices built, n^2 per iteration on n loaded strips [-] (a deterministic
  //! measure of the solve's cost, for the least model's test; 0 for the other methods).
  double matrix_entries = 0.0;
  std::vector<PatchSolution> patches;
  //! Empty, or why the solve failed where the status alone does not say (e.g. bem2d: "grid of 1638 x 164 elements
  //! (max 1024 per side): element size too small").
  std::string detail;
};

}  // namespace ctab::gen
