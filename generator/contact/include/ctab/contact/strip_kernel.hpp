// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The strip influence kernel of MIM-1D in closed form (the integration along y of paper Eq. 10 done
//! analytically).
//!
//! Displacement at the centre (0, y_i) of strip i due to strip j (half-width b, half-length a_j, pressure
//! p0_j sqrt(1 - (x/a_j)^2)), paper Eq. 10 with the eta-integral done analytically:
//!   C_ij = (2 a_j / (pi E*)) [ h((d + b)/a_j) - h((d - b)/a_j) ],   d = y_i - y_j,
//!   h(t) = integral_0^1 sqrt(1 - u^2) asinh(t/u) du            (odd in t),
//!   h'(t) = D(m) / sqrt(1 + t^2),  m = 1/(1 + t^2),  D(m) = (K - E)/m  (Carlson R_D, elliptic.hpp).
//! Asymptotes: h(t) = t ln(4/t) + O(t^3 ln t) for t -> 0; h(t) = (pi/4) asinh(t) + pi/8 + (pi/4) ln 2 + O(1/t^2)
//! for t -> infinity.
//! h is tabulated on 2^-40 <= t < 2^40 (128 cubic-Hermite intervals per octave, values from exact h' by 4-point
//! Gauss-Legendre); absolute error below 1e-10. The table is computed at build time (contact_tables_gen writes
//! it as source, bit for bit what build_intervals() computes) so no process pays for it at start. A lookup is a few integer operations on
//! the IEEE exponent and mantissa plus one cubic, no logarithm.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ctab::gen {

class StripKernel {
 public:
  static constexpr int kMinExponent = -40;
  static constexpr int kMaxExponent = 40;
  static constexpr int kMantissaBits = 7;
  static constexpr double kTableMin = 0x1p-40;  //!< 2^kMinExponent
  static constexpr double kTableMax = 0x1p+40;  //!< 2^kMaxExponent

  //! The process-wide table (built on first use; thread-safe).
  [[nodiscard]] static const StripKernel& instance();

  //! h(t) for any finite t.
  [[nodiscard]] double value(double t) const noexcept;
  //! h(t) and t h'(t) at once (the latter enters the Newton Jacobian).
  void value_and_scaled_slope(double t, double& h, double& t_dh) const noexcept;
  //! The same for 2^-40 <= t < 2^40 only (the matrix build's hot loop; no range or sign handling).
  void value_and_scaled_slope_in_table(double t, double& h, double& t_dh) const noexcept {
    const auto bits = std::bit_cast<std::uint64_t>(t);
    const auto exponent = static_cast<int>(bits >> 52) - 1023;
    const auto step = static_cast<std::size_t>((bits >> (52 - kMantissaBits)) & ((1u << kMantissaBits) - 1));
    const Interval& in = intervals_[static_cast<std::size_t>(exponent - kMinExponent) * (1u << kMantissaBits) + step];
    const double s = (t - in.t0) * in.inverse_width;
    h = in.c0 + s * (in.c1 + s * (in.c2 + s * in.c3));
    t_dh = t * (in.c1 + s * (2.0 * in.c2 + s * 3.0 * in.c3)) * in.inverse_width;
  }
  //! h and t h'(t) at t_k = (2k + 1) beta, k = 0 .. count - 1 (beta > 0): the lags of one column of MIM-1D's
  //! influence matrix (Mim1dSolver::build_matrices).
  void at_odd_multiples(double beta, std::size_t count, double* h, double* t_dh) const noexcept {
    if (count == 0) return;
    if (in_table(beta) && in_table(static_cast<double>(2 * count - 1) * beta)) {
      for (std::size_t k = 0; k < count; ++k)
        value_and_scaled_slope_in_table(static_cast<double>(2 * k + 1) * beta, h[k], t_dh[k]);
      return;
    }
    for (std::size_t k = 0; k < count; ++k)
      value_and_scaled_slope(static_cast<double>(2 * k + 1) * beta, h[k], t_dh[k]);
  }
  //! True when value_and_scaled_slope_in_table may be used for t.
  [[nodiscard]] static bool in_table(double t) noexcept { return t >= kTableMin && t < kTableMax; }

  //! h'(t) evaluated exactly (Carlson), for tests and table construction.
  [[nodiscard]] static double exact_slope(double t) noexcept;

  struct Interval {
    double t0;
    double inverse_width;
    double c0, c1, c2, c3;  // h(t0 + s w) = c0 + s (c1 + s (c2 + s c3)), s in [0, 1)
  };
  //! Intervals of the table.
  static constexpr std::size_t kIntervalCount = static_cast<std::size_t>(kMaxExponent - kMinExponent)
                                                << static_cast<unsigned>(kMantissaBits);
  //! The table computed now (tests; the build-time generator contact_tables_gen).
  [[nodiscard]] static std::vector<Interval> build_intervals();
  //! The table in use (kIntervalCount intervals).
  [[nodiscard]] const Interval* intervals() const noexcept { return intervals_; }

 private:
  StripKernel();
  std::vector<Interval> storage_;  // the table when computed at start (a build without the generated one)
  const Interval* intervals_;
};

}  // namespace ctab::gen
