// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Options of the 2-D boundary-element reference solver (bem2d.hpp), free of Eigen so that configurations and
//! the method interface can hold them.
#include <cstddef>
#include <cstdint>

#include "ctab/contact/grid_alignment.hpp"

namespace ctab::gen {

//! Most elements along either side of the bem2d grid. Memory: the FFT work arrays hold about
//! 2 x (2n)^2 complex numbers, 64 MB at n = 1024; a 512 x 512 grid solves in seconds.
inline constexpr std::size_t kBem2dMaxElementsPerSide = 1024;
//! Cap on constrained-CG iterations per solve. Chosen: the measured cases (Hertz sphere, the non-Hertzian body)
//! need 20-200 iterations up to 512 x 512 elements; 5000 leaves a wide margin and bounds a hopeless case.
inline constexpr int kBem2dMaxIterations = 5000;

//! Element grid and solver settings of bem2d: dx x dy rectangles placed as `alignment` says.
struct Bem2dGrid {
  double dx_m = 0.2e-3;  //!< element length along the rolling direction x [m]
  double dy_m = 0.2e-3;  //!< element width along the lateral direction y [m] (one "strip" per element row)
  //! Relative convergence tolerance of the constrained CG [-] (Polonsky-Keer's criterion): the pressure change of
  //! one iteration, sum |dp| over sum p, with no element entering or leaving the contact set: tight enough that
  //! area and peak pressure are settled to the sixth digit on the Hertz sphere (88 iterations at 0.1 mm).
  double tolerance = 1.0e-8;
  int max_iterations = kBem2dMaxIterations;  //!< constrained-CG iteration cap [-], at most kBem2dMaxIterations
  //! Where the elements sit (grid_alignment.hpp), along x as along y: centred, an element sits at x = 0 (odd
  //! counts along x, as CONTACT's wheel-rail strip files). On an 8-11 row flank patch the two placements count
  //! areas 3 % apart.
  GridAlignment alignment = GridAlignment::EdgesAtOrigin;
};

}  // namespace ctab::gen
