// SPDX-License-Identifier: Apache-2.0
#pragma once
// Internal pieces of bem2d (not installed): the element grid over the potential contact area, the constrained CG
// solver and the assembly of the NormalSolution. See ctab/contact/bem2d.hpp for the method.
#include <cstddef>
#include <string>
#include <vector>

#include "ctab/contact/bem2d.hpp"
#include "ctab/contact/bem2d_convolution.hpp"
#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/normal_solution.hpp"
#include "ctab/contact/solve_status.hpp"

namespace ctab::gen::bem2d {

//! Elements covering { h(y) + A(y) x^2 < covered_approach } plus one element on every side (within the gap data).
struct ElementGrid {
  std::size_t nx = 0, ny = 0;
  double dx = 0.0, dy = 0.0;             // element size [m]
  double x0 = 0.0, y0 = 0.0;             // centre of element (0, 0) [m]
  double covered_approach = 0.0;         // approach [m] up to which the grid holds every element that can touch
  bool first_row_at_data_end = false;    // no further row below the first one fits inside the gap data
  bool last_row_at_data_end = false;     // ... above the last one
  std::vector<double> h;                 // undeformed separation at the element centres [m], ny x nx
  std::vector<unsigned char> potential;  // 1 where h < covered_approach (the elements the solver may load)
};

//! Deepest separation of the gap at the element-row centres inside its data [m] (the approach of first contact).
[[nodiscard]] double deepest_separation(const GapProfile& gap, double dy, GridAlignment alignment);

//! Builds the grid for a validated gap. Returns InvalidInput (with `why`) when it would exceed
//! kBem2dMaxElementsPerSide or fewer than one row fits; NoContact when no element has h < covered_approach.
[[nodiscard]] SolveStatus make_element_grid(const GapProfile& gap, double dx, double dy, GridAlignment alignment,
                                            double covered_approach, ElementGrid& grid, std::string& why);

enum class Prescribed { Approach, Load };

struct CgResult {
  SolveStatus status = SolveStatus::NumericalFailure;
  int iterations = 0;
  double residual = 0.0;  // relative pressure change of the last iteration [-]
  double approach = 0.0;  // the prescribed one, or the mean of h + u over the contact set [m]
};

//! Polonsky-Keer constrained CG. `pressure` holds a non-negative start on the potential elements and receives
//! the solution [Pa]; `target` is the approach [m] or the normal force [N].
[[nodiscard]] CgResult solve_constrained_cg(InfluenceConvolution& influence, const ElementGrid& grid,
                                            Prescribed prescribed, double target, const Bem2dGrid& options,
                                            std::vector<double>& pressure);

//! Start for the CG: `start`'s pressures at the element centres (nearest element) where it is given and loads a
//! potential element, else p ∝ sqrt(estimate - h) where positive; scaled to the load or, for an approach, by an
//! exact line search on the quadratic program (one product with A).
void initial_pressure(InfluenceConvolution& influence, const ElementGrid& grid, Prescribed prescribed, double target,
                      double estimated_approach, std::vector<double>& pressure,
                      const Bem2dPressureField* start = nullptr);

//! Patches (contiguous loaded rows), strips (one per row) and totals of a solved pressure field.
void assemble_solution(const ElementGrid& grid, const std::vector<double>& pressure, NormalSolution& solution);
//! True when a loaded element lies in a first or last row that is the end of the gap data, or on the x-border.
[[nodiscard]] bool loaded_at_border(const ElementGrid& grid, const std::vector<double>& pressure);
//! Copies the field out.
void export_field(const ElementGrid& grid, const std::vector<double>& pressure, Bem2dPressureField& field);

}  // namespace ctab::gen::bem2d
