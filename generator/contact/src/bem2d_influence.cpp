// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/bem2d_influence.hpp"

#include <cmath>
#include <numbers>

namespace ctab::gen {

double love_primitive(double X_m, double Y_m) noexcept {
  // X asinh(Y/|X|) + Y asinh(X/|Y|); each term vanishes with its prefactor (the limit X ln|X| -> 0).
  const double first = X_m == 0.0 ? 0.0 : X_m * std::asinh(Y_m / std::abs(X_m));
  const double second = Y_m == 0.0 ? 0.0 : Y_m * std::asinh(X_m / std::abs(Y_m));
  return first + second;
}

double love_influence_m_per_Pa(double x_m, double y_m, double dx_m, double dy_m, double E_star_Pa) noexcept {
  const double x1 = x_m - 0.5 * dx_m, x2 = x_m + 0.5 * dx_m;
  const double y1 = y_m - 0.5 * dy_m, y2 = y_m + 0.5 * dy_m;
  const double box = love_primitive(x2, y2) - love_primitive(x1, y2) - love_primitive(x2, y1) + love_primitive(x1, y1);
  return box / (std::numbers::pi * E_star_Pa);
}

}  // namespace ctab::gen
