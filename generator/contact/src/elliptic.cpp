// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/elliptic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ctab::gen {

namespace {
// Duplication stops when the arguments agree to this relative tolerance; with the fifth-order
// series of DLMF 19.36 the truncation error is then O(tol^6) < 1e-17.
constexpr double kDuplicationTolerance = 1.0e-3;
}  // namespace

double carlson_rf(double x, double y, double z) noexcept {
  double mean = (x + y + z) / 3.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double dx = (mean - x) / mean, dy = (mean - y) / mean, dz = (mean - z) / mean;
    if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < kDuplicationTolerance) {
      // DLMF 19.36.1 with X + Y + Z = 0.
      const double e2 = dx * dy - dz * dz;
      const double e3 = dx * dy * dz;
      return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / std::sqrt(mean);
    }
    const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
    const double lambda = sx * sy + sy * sz + sz * sx;
    x = 0.25 * (x + lambda);
    y = 0.25 * (y + lambda);
    z = 0.25 * (z + lambda);
    mean = (x + y + z) / 3.0;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double carlson_rd(double x, double y, double z) noexcept {
  double sum = 0.0;
  double scale = 1.0;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double mean = (x + y + 3.0 * z) / 5.0;
    const double dx = (mean - x) / mean, dy = (mean - y) / mean, dz = (mean - z) / mean;
    if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) < kDuplicationTolerance) {
      // DLMF 19.36.2 with X + Y + 3Z = 0.
      const double xy = dx * dy, zz = dz * dz;
      const double e2 = xy - 6.0 * zz;
      const double e3 = (3.0 * xy - 8.0 * zz) * dz;
      const double e4 = 3.0 * (xy - zz) * zz;
      const double e5 = xy * zz * dz;
      const double series = 1.0 - 3.0 * e2 / 14.0 + e3 / 6.0 + 9.0 * e2 * e2 / 88.0 - 3.0 * e4 / 22.0 -
                            9.0 * e2 * e3 / 52.0 + 3.0 * e5 / 26.0;
      return 3.0 * sum + scale * series / (mean * std::sqrt(mean));
    }
    const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
    const double lambda = sx * sy + sy * sz + sz * sx;
    sum += scale / (sz * (z + lambda));
    scale *= 0.25;
    x = 0.25 * (x + lambda);
    y = 0.25 * (y + lambda);
    z = 0.25 * (z + lambda);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

CompleteElliptic complete_elliptic_from_complement(double mc) noexcept {
  const double m = 1.0 - mc;
  const double k = carlson_rf(0.0, mc, 1.0);
  const double d = carlson_rd(0.0, mc, 1.0) / 3.0;
  return {k, k - m * d, d};
}

double elliptic_k(double m) noexcept { return carlson_rf(0.0, 1.0 - m, 1.0); }
double elliptic_e(double m) noexcept {
  if (m >= 1.0) return 1.0;
  return complete_elliptic_from_complement(1.0 - m).E;
}
double elliptic_d(double m) noexcept { return carlson_rd(0.0, 1.0 - m, 1.0) / 3.0; }

}  // namespace ctab::gen
