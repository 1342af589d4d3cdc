// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Influence coefficients of bem2d: normal displacement (difference of the two bodies) due to a uniform unit
//! pressure on a rectangle, Love (1929, Phil. Trans. R. Soc. A228:377-420), as in CONTACT's elascf_pcwcns:
//!   A(x, y) = [[ F(X, Y) ]] / (pi E*),  F(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|)  (a term is 0 when its factor is),
//!   [[F]] = F(X2, Y2) - F(X1, Y2) - F(X2, Y1) + F(X1, Y1),  X1,2 = x -+ dx/2,  Y1,2 = y -+ dy/2,
//! with (x, y) the observation point relative to the element centre. The asinh form differs from Love's log form
//! by -X ln|X| - Y ln|Y|, which cancels in the double difference. Self-coefficient of a square h x h element:
//! 4 h ln(1 + sqrt 2) / (pi E*).

namespace ctab::gen {

//! Love's primitive F(X, Y) [m].
[[nodiscard]] double love_primitive(double X_m, double Y_m) noexcept;

//! Displacement [m] per unit pressure [Pa] at (x, y) from the centre of a dx x dy element; E* [Pa].
[[nodiscard]] double love_influence_m_per_Pa(double x_m, double y_m, double dx_m, double dy_m,
                                             double E_star_Pa) noexcept;

}  // namespace ctab::gen
