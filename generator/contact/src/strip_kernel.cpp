// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/strip_kernel.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "ctab/contact/elliptic.hpp"
#ifndef CTAB_RUNTIME_CONTACT_TABLES
#include "contact_tables.inc"  // generated at build time by contact_tables_gen (generator/CMakeLists.txt)
#endif

namespace ctab::gen {

namespace {

constexpr int kIntervalsPerOctave = 1 << StripKernel::kMantissaBits;
constexpr int kOctaves = StripKernel::kMaxExponent - StripKernel::kMinExponent;
constexpr std::size_t kIntervalCount = static_cast<std::size_t>(kOctaves) * kIntervalsPerOctave;
static_assert(kIntervalCount == StripKernel::kIntervalCount);
constexpr double kTableMin = StripKernel::kTableMin;
constexpr double kTableMax = StripKernel::kTableMax;
static_assert(kTableMin == 0x1p-40 && StripKernel::kMinExponent == -40 && StripKernel::kMaxExponent == 40);
// lim_{t->inf} h(t) - (pi/4) asinh(t)  (integration by parts of h; see header).
constexpr double kLargeArgumentConstant = std::numbers::pi / 8.0 + std::numbers::pi / 4.0 * std::numbers::ln2;

double small_argument_value(double t) { return t * std::log(4.0 / t); }
double large_argument_value(double t) { return std::numbers::pi / 4.0 * std::asinh(t) + kLargeArgumentConstant; }

double node(std::size_t index) {
  const int octave = static_cast<int>(index / kIntervalsPerOctave);
  const int step = static_cast<int>(index % kIntervalsPerOctave);
  return std::ldexp(1.0 + static_cast<double>(step) / kIntervalsPerOctave, StripKernel::kMinExponent + octave);
}

}  // namespace

double StripKernel::exact_slope(double t) noexcept {
  t = std::abs(t);
  if (t == 0.0) return std::numeric_limits<double>::infinity();
  const double mc = 1.0 / (1.0 + 1.0 / (t * t));  // t^2/(1 + t^2) without overflow
  const double d = carlson_rd(0.0, mc, 1.0) / 3.0;
  return d / std::sqrt(1.0 + t * t);
}

std::vector<StripKernel::Interval> StripKernel::build_intervals() {
  std::vector<Interval> intervals(kIntervalCount);
  // Cumulative integration of the exact slope, 4-point Gauss-Legendre per interval.
  static constexpr std::array<double, 4> kGaussNodes = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                                        0.8611363115940526};
  static constexpr std::array<double, 4> kGaussWeights = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                                          0.3478548451374538};
  double t0 = node(0);
  double h0 = small_argument_value(t0);
  double d0 = exact_slope(t0);
  for (std::size_t i = 0; i < kIntervalCount; ++i) {
    const double t1 = (i + 1 < kIntervalCount) ? node(i + 1) : kTableMax;
    const double width = t1 - t0;
    double integral = 0.0;
    for (std::size_t g = 0; g < kGaussNodes.size(); ++g)
      integral += kGaussWeights[g] * exact_slope(t0 + 0.5 * width * (1.0 + kGaussNodes[g]));
    const double h1 = h0 + 0.5 * width * integral;
    const double d1 = exact_slope(t1);
    Interval& interval = intervals[i];
    interval.t0 = t0;
    interval.inverse_width = 1.0 / width;
    interval.c0 = h0;
    interval.c1 = width * d0;
    interval.c2 = 3.0 * (h1 - h0) - 2.0 * width * d0 - width * d1;
    interval.c3 = 2.0 * (h0 - h1) + width * d0 + width * d1;
    t0 = t1;
    h0 = h1;
    d0 = d1;
  }
  return intervals;
}

#ifndef CTAB_RUNTIME_CONTACT_TABLES
StripKernel::StripKernel() : intervals_(generated::kStripKernelIntervals.data()) {}
#else
StripKernel::StripKernel() : storage_(build_intervals()), intervals_(storage_.data()) {}
#endif

const StripKernel& StripKernel::instance() {
  static const StripKernel kernel;
  return kernel;
}

void StripKernel::value_and_scaled_slope(double t, double& h, double& t_dh) const noexcept {
  const double sign = t < 0.0 ? -1.0 : 1.0;
  const double x = std::abs(t);
  if (x < kTableMin) {
    h = sign * (x == 0.0 ? 0.0 : small_argument_value(x));
    t_dh = x == 0.0 ? 0.0 : sign * x * (std::log(4.0 / x) - 1.0);
    return;
  }
  if (!(x < kTableMax)) {
    h = sign * large_argument_value(x);
    t_dh = sign * std::numbers::pi / 4.0;
    return;
  }
  // Index from the IEEE-754 bits: unbiased exponent and the leading kMantissaBits of the mantissa.
  value_and_scaled_slope_in_table(x, h, t_dh);
  h *= sign;
  t_dh *= sign;
}

double StripKernel::value(double t) const noexcept {
  double h = 0.0, t_dh = 0.0;
  value_and_scaled_slope(t, h, t_dh);
  return h;
}

}  // namespace ctab::gen
