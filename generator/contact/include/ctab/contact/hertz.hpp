// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Hertz theory of elliptic contact between two elastic bodies.
//!
//! Geometry: undeformed separation h(x, y) = A x^2 + B y^2 near the first point of contact, x the rolling
//! direction, y lateral; A, B > 0 are HALF the summed principal curvatures [1/m] (CONTACT's A1, B1).
//! Semi-axes a (along x) and b (along y) are kept unsorted: a > b when A < B.
//! Coefficients (Timoshenko & Goodier; paper Eqs. 18-19): with alpha = 3N/(4 E* (A + B)),
//!   a = m alpha^(1/3),  b = n alpha^(1/3),  p0 = 3N/(2 pi a b),  delta = r (3N/(4E*))^(2/3) (A + B)^(1/3).
//! The eccentricity solves A_small/B_large = g^2 (K - E)/(E - g^2 K) = (1 - m_e) D / (K - D) with g the
//! semi-axis ratio (<= 1) and m_e = 1 - g^2 the elliptic parameter (CONTACT m_hertz.f90 form: no
//! cancellation at small eccentricity); solved by a safeguarded root finder in log(1 - m_e).
//! Checks: circle m = n = r = 1; B/A = 3: m = 1.4858, n = 0.7171 (tests/hertz_test.cpp).
#include <array>
#include <cstddef>
#include <vector>

#include "ctab/contact/solve_status.hpp"

namespace ctab::gen {

//! Non-dimensional Hertz coefficients for one curvature pair.
struct HertzCoefficients {
  double m = 1.0;  //!< semi-axis coefficient along x (the direction of curvature A) [-]
  double n = 1.0;  //!< semi-axis coefficient along y (the direction of curvature B) [-]
  double r = 1.0;  //!< approach coefficient [-]
};

//! Coefficients m, n, r for relative curvatures A, B > 0 [1/m]. Returns false (and circle values) if A or B
//! is not positive and finite.
[[nodiscard]] bool hertz_coefficients(double A_per_m, double B_per_m, HertzCoefficients& out) noexcept;

//! The same from a table in x = ln(B/A) (cubic Hermite, 64 nodes per unit of x on |x| <= 12, relative error
//! < 1e-10), exact outside that range. For loops over many strips. The table is computed at build time
//! (contact_tables_gen writes it as source, bit for bit what build_hertz_table() computes).
[[nodiscard]] bool hertz_coefficients_tabulated(double A_per_m, double B_per_m, HertzCoefficients& out) noexcept;

//! One node of that table: m, n, r at x = -12 + k/64 and their slopes d/dx (5-point stencil).
struct HertzTableNode {
  std::array<double, 3> value, slope;
};
inline constexpr std::size_t kHertzTableNodes = 24 * 64 + 1;
//! The table computed now (tests; the build-time generator contact_tables_gen).
[[nodiscard]] std::vector<HertzTableNode> build_hertz_table();
//! The table in use (kHertzTableNodes nodes).
[[nodiscard]] const HertzTableNode* hertz_table();

//! A full Hertz solution.
struct HertzContact {
  SolveStatus status = SolveStatus::InvalidInput;
  double semi_axis_x_m = 0.0;    //!< a, along the rolling direction [m]
  double semi_axis_y_m = 0.0;    //!< b, lateral [m]
  double max_pressure_Pa = 0.0;  //!< p0 [Pa]
  double approach_m = 0.0;       //!< rigid approach delta [m]
  double normal_force_N = 0.0;   //!< N [N]
  double area_m2 = 0.0;          //!< pi a b [m^2]
};

//! Hertz contact for a prescribed normal force N >= 0 [N]; E* [Pa].
[[nodiscard]] HertzContact hertz_from_load(double A_per_m, double B_per_m, double E_star_Pa,
                                           double normal_force_N) noexcept;
//! Hertz contact for a prescribed approach delta >= 0 [m]; E* [Pa].
[[nodiscard]] HertzContact hertz_from_approach(double A_per_m, double B_per_m, double E_star_Pa,
                                               double approach_m) noexcept;

//! Strip half-length per unit peak pressure, a_i / p0_i = pi m^2 n / (2 E* (A + B)) [m/Pa] (paper Eqs. 25-26).
//! Returns 0 for invalid curvatures.
[[nodiscard]] double strip_length_compliance(double A_per_m, double B_per_m, double E_star_Pa) noexcept;

}  // namespace ctab::gen
