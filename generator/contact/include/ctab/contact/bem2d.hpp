// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Full 2-D boundary-element normal-contact solver: the reference rung of the method ladder.
//!
//! Geometry: the strip problem's gap h(x, y) = h(y) + A(y) x^2 (gap_profile.hpp), resampled at the element centres
//! (h by a cubic spline with the profile's own second derivative h'' = 2B, A linearly). Half-space, frictionless,
//! quasi-identical materials (combined modulus E*).
//! Method (../shared/facts/methods_and_tables.md 1.6): piecewise-constant pressure on dx x dy elements, Love's
//! (1929) influence coefficients for uniform pressure on a rectangle (bem2d_influence.hpp), the product
//! u = A p by zero-padded FFT (linear, not cyclic, convolution; bem2d_convolution.hpp), and the
//! Polonsky & Keer (1999, Wear 231:206-219) constrained conjugate-gradient iteration:
//!   prescribed load   - PK as published: the deformed distance is measured from its mean over the contact set
//!                       (the approach is that mean), the pressure is rescaled to the load every iteration;
//!   prescribed approach - the same iteration on the bound-constrained quadratic program
//!                       min 1/2 p'Ap + p'(h - delta), p >= 0 (its KKT conditions are the contact conditions):
//!                       no mean subtraction (delta is known), no rescaling.
//! Potential contact area: a body only closes the gap where h < delta (u > 0 wherever p > 0), so the grid covers
//! { h(y) + A(y) x^2 < delta } plus one element; for a prescribed load delta is first estimated (Hertz at the
//! deepest point, doubled), and the grid is rebuilt larger when the solved approach exceeds the covered one.
//! Start: a cold solve on a grid of 4096 elements or more first solves the same problem on elements twice as large
//! (recursively) and starts from that field, covering 1.25 times its approach (the grid, and the CG's iterations,
//! shrink; the result is the same to the CG tolerance).
//! NormalSolution fields: iterations = CG iterations at the requested element size (a coarse start's not counted), outer_iterations = grids built (prescribed load; 0 for an
//! approach), residual = the last relative pressure change.
//! Status: InvalidInput for a bad gap, E*, element size, load or approach, or a grid over
//! kBem2dMaxElementsPerSide; ZoneTruncated when loaded elements reach the ends of the gap data in y;
//! MaxIterations at the iteration cap; NumericalFailure on a non-finite iterate. Never throws, never NaN.
#include <cstddef>
#include <vector>

#include "ctab/contact/bem2d_options.hpp"
#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/normal_solution.hpp"

namespace ctab::gen {

//! The full pressure field of a bem2d solve (for accuracy charts): element (i, j) has its centre at
//! x = x0 + i dx, y = y0 + j dy and pressure pressure_Pa[j * nx + i].
struct Bem2dPressureField {
  std::size_t nx = 0;               //!< elements along x [-]
  std::size_t ny = 0;               //!< elements along y [-]
  double dx_m = 0.0;                //!< element length [m]
  double dy_m = 0.0;                //!< element width [m]
  double x0_m = 0.0;                //!< centre of the first element along x [m]
  double y0_m = 0.0;                //!< centre of the first element along y [m]
  std::vector<double> pressure_Pa;  //!< ny x nx, row j (one y) after row j - 1 [Pa]
  //! Solved approach less the deepest separation of the grid's rows [m]: how deep the next grid must reach when
  //! this field starts a solve of a nearby gap (0 when not solved).
  double depth_m = 0.0;

  [[nodiscard]] bool empty() const { return pressure_Pa.empty(); }

  [[nodiscard]] double at(std::size_t i, std::size_t j) const { return pressure_Pa[j * nx + i]; }
};

//! bem2d solution for a prescribed rigid approach [m] (same datum as the gap's h). Method "bem2d": one patch per
//! contiguous run of loaded element rows along y, one strip per row (p0 = row maximum, half-length = half the
//! loaded x-extent, load = row sum). `field`, when given, receives the pressure field. Never throws.
[[nodiscard]] NormalSolution solve_bem2d_for_approach(const GapProfile& gap, double E_star_Pa, const Bem2dGrid& grid,
                                                      double approach_m, Bem2dPressureField* field = nullptr);
//! The same for a prescribed total normal force [N]. `start` (optional, not empty): the solved field of a nearby
//! gap (the previous pass of a wheel-rail case) starts the CG, its pressures taken at the same (x, y), and the grid
//! first covers 1.25 times its depth instead of twice the Hertz approach: a start that already solves the gap ends
//! the CG within a few iterations. The result agrees with a cold start to the CG tolerance.
[[nodiscard]] NormalSolution solve_bem2d_for_load(const GapProfile& gap, double E_star_Pa, const Bem2dGrid& grid,
                                                  double normal_force_N, Bem2dPressureField* field = nullptr,
                                                  const Bem2dPressureField* start = nullptr);

}  // namespace ctab::gen
