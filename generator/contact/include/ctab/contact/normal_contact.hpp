// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The one entry point of the method ladder: a normal-contact problem on a gap profile, solved by the rung the
//! options name (contact_method.hpp). Eigen-free. Never throws: bad input gives SolveStatus::InvalidInput.
#include <cstdint>

#include "ctab/contact/bem2d_options.hpp"
#include "ctab/contact/contact_method.hpp"
#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/mim1d_options.hpp"
#include "ctab/contact/normal_solution.hpp"

namespace ctab::gen {

//! What is prescribed: the rigid approach delta [m] (same datum as the gap's h) or the total normal force [N].
struct Loading {
  enum class Kind : std::int8_t { Approach = 0, NormalForce = 1 };
  Kind kind = Kind::NormalForce;
  double value = 0.0;  //!< [m] for Approach, [N] for NormalForce

  [[nodiscard]] static Loading approach(double approach_m) noexcept { return {Kind::Approach, approach_m}; }
  [[nodiscard]] static Loading normal_force(double force_N) noexcept { return {Kind::NormalForce, force_N}; }
};

struct Bem2dPressureField;

struct MethodOptions {
  ContactMethod method = ContactMethod::Mim1d;
  double E_star_Pa = 0.0;         //!< combined modulus E* [Pa] (material.hpp)
  double strip_width_m = 0.2e-3;  //!< strip width 2b of every rung's output [m] (overrides mim1d.strip_width_m)
  Mim1dOptions mim1d;             //!< MIM-1D only: update rule, curvature treatment, tolerances
  //! bem2d only: element placement (wheel-rail patches: centred on the reference point, as CONTACT's grid).
  GridAlignment bem2d_alignment = GridAlignment::EdgesAtOrigin;
  //! bem2d only: element length along x [m]; 0 = square elements of the strip width. A long, narrow patch (the
  //! flange flank: 1.6 x 29 mm) can take rows finer than its elements are long (flank_grid_test).
  double bem2d_element_length_m = 0.0;
  //! bem2d, prescribed load only: the solved field of a nearby gap that starts the solve (bem2d.hpp), or null.
  const Bem2dPressureField* bem2d_start = nullptr;
  //! bem2d only: receives the solved field (not the object bem2d_start points to), or null.
  Bem2dPressureField* bem2d_field = nullptr;
};

//! Solves the gap with options.method. Output for every rung: patches of strips (y, half-length, p0, load).
[[nodiscard]] NormalSolution solve_normal_contact(const GapProfile& gap, const MethodOptions& options, Loading loading);

}  // namespace ctab::gen
