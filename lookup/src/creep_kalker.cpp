// SPDX-License-Identifier: Apache-2.0
// Kalker's linear-theory creepage coefficients: J.J. Kalker, "Three-dimensional elastic bodies in rolling contact",
// Kluwer 1990, Table E.3 (first published in Kalker's thesis, Delft 1967). The interpolation is the one CONTACT's
// linrol uses: linear in g = (shorter / longer axis) on each branch, quadratic in nu on the reciprocals.
#include <algorithm>
#include <cmath>

#include "ctab/lookup/creep.hpp"

namespace ctab::lookup {

namespace {

constexpr int kRows = 10;  // g = 0.1, 0.2, ..., 1.0
// [branch][row][coefficient][nu = 0, 0.25, 0.5]; branch 0: a < b (g = a/b), branch 1: a >= b (g = b/a).
constexpr double kTable[2][kRows][4][3] = {
    {{{2.51, 3.31, 4.85}, {2.51, 2.52, 2.53}, {0.334, 0.473, 0.731}, {6.42, 8.28, 11.7}},
     {{2.59, 3.37, 4.81}, {2.59, 2.63, 2.66}, {0.483, 0.603, 0.809}, {3.46, 4.27, 5.66}},
     {{2.68, 3.44, 4.80}, {2.68, 2.75, 2.81}, {0.607, 0.715, 0.889}, {2.49, 2.96, 3.72}},
     {{2.78, 3.53, 4.82}, {2.78, 2.88, 2.98}, {0.720, 0.823, 0.977}, {2.02, 2.32, 2.77}},
     {{2.88, 3.62, 4.83}, {2.88, 3.01, 3.14}, {0.827, 0.929, 1.07}, {1.74, 1.93, 2.22}},
     {{2.98, 3.72, 4.91}, {2.98, 3.14, 3.31}, {0.930, 1.03, 1.18}, {1.56, 1.68, 1.86}},
     {{3.09, 3.81, 4.97}, {3.09, 3.28, 3.48}, {1.03, 1.14, 1.29}, {1.43, 1.50, 1.60}},
     {{3.19, 3.91, 5.05}, {3.19, 3.41, 3.65}, {1.13, 1.25, 1.40}, {1.34, 1.37, 1.42}},
     {{3.29, 4.01, 5.12}, {3.29, 3.54, 3.82}, {1.23, 1.36, 1.51}, {1.27, 1.27, 1.27}},
     {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}}},
    {{{10.7, 11.7, 12.9}, {10.7, 12.8, 16.0}, {12.2, 14.6, 18.0}, {0.795, 0.526, 0.228}},
     {{6.96, 7.78, 8.82}, {6.96, 8.14, 9.79}, {5.72, 6.63, 7.89}, {0.828, 0.601, 0.341}},
     {{5.57, 6.34, 7.34}, {5.57, 6.40, 7.51}, {3.79, 4.32, 5.01}, {0.868, 0.674, 0.446}},
     {{4.84, 5.57, 6.57}, {4.84, 5.48, 6.31}, {2.88, 3.24, 3.70}, {0.912, 0.747, 0.549}},
     {{4.37, 5.10, 6.11}, {4.37, 4.90, 5.56}, {2.35, 2.62, 2.96}, {0.958, 0.819, 0.650}},
     {{4.06, 4.78, 5.80}, {4.06, 4.50, 5.04}, {2.01, 2.23, 2.50}, {1.01, 0.892, 0.751}},
     {{3.82, 4.54, 5.58}, {3.82, 4.21, 4.67}, {1.76, 1.95, 2.18}, {1.05, 0.965, 0.852}},
     {{3.65, 4.36, 5.42}, {3.65, 3.99, 4.39}, {1.58, 1.75, 1.94}, {1.10, 1.04, 0.954}},
     {{3.51, 4.22, 5.30}, {3.51, 3.81, 4.16}, {1.44, 1.59, 1.77}, {1.16, 1.11, 1.06}},
     {{3.40, 4.12, 5.20}, {3.40, 3.67, 3.98}, {1.33, 1.47, 1.63}, {1.21, 1.19, 1.16}}}};

// Quadratic through the reciprocals at nu = 0, 0.25, 0.5, inverted.
double in_nu(const double (&v)[3], double nu) noexcept {
  const double l0 = (nu - 0.25) * (nu - 0.5) / 0.125, l1 = nu * (nu - 0.5) / -0.0625, l2 = nu * (nu - 0.25) / 0.125;
  return 1.0 / (l0 / v[0] + l1 / v[1] + l2 / v[2]);
}

}  // namespace

KalkerCoefficients kalker_coefficients(double a_m, double b_m, double poisson_ratio) noexcept {
  if (!(a_m > 0.0 && b_m > 0.0 && std::isfinite(a_m) && std::isfinite(b_m))) return {};
  const int branch = a_m < b_m ? 0 : 1;
  const double g = std::clamp(branch == 0 ? a_m / b_m : b_m / a_m, 0.1, 1.0);
  const double position = g * 10.0 - 1.0;  // row index, 0 .. 9
  const int lo = std::min(static_cast<int>(position), kRows - 2);
  const double t = position - lo;
  const double nu = std::clamp(poisson_ratio, 0.0, 0.5);
  double c[4];
  for (int k = 0; k < 4; ++k) {
    double v[3];
    for (int j = 0; j < 3; ++j) v[j] = (1.0 - t) * kTable[branch][lo][k][j] + t * kTable[branch][lo + 1][k][j];
    c[k] = in_nu(v, nu);
  }
  return {c[0], c[1], c[2], c[3]};
}

}  // namespace ctab::lookup
