#include "ctab/contact/strip_compliance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "ctab/contact/hertz.hpp"

namespace ctab::gen {

namespace {

// Minimum lateral curvature relative to the rolling one (CONTACT estimate_curvatures: R_y <= 20 R_x).
constexpr double kMinimumCurvatureRatio = 1.0 / 20.0;

// Memoised local Hertz data: consecutive strips often share (A, B).
class ComplianceCache {
 public:
  explicit ComplianceCache(double E_star) : E_star_(E_star) {}
  StripHertz operator()(double A, double B) {
    B = std::max(B, kMinimumCurvatureRatio * A);
    if (A != last_A_ || B != last_B_) {
      last_A_ = A;
      last_B_ = B;
      HertzCoefficients c;
      last_value_ = {};
      if (hertz_coefficients_tabulated(A, B, c)) {
        last_value_.compliance_m_per_Pa = std::numbers::pi * c.m * c.m * c.n / (2.0 * E_star_ * (A + B));
        last_value_.length_factor = c.r * (1.0 + B / A) / (c.m * c.m);
        last_value_.depth_factor = c.r * (1.0 + A / B) / (c.n * c.n);
      }
    }
    return last_value_;
  }

 private:
  double E_star_;
  double last_A_ = -1.0, last_B_ = -1.0;
  StripHertz last_value_;
};

}  // namespace

void strip_compliances(const StripGrid& grid, double E_star_Pa, double approach_m, const CurvatureOptions& options,
                       std::vector<StripHertz>& compliance, std::vector<double>& scratch) {
  const std::size_t n = grid.size();
  compliance.assign(n, StripHertz{});
  ComplianceCache cache(E_star_Pa);
  double b_low = std::numeric_limits<double>::infinity(), b_high = -b_low;
  for (std::size_t j = 0; j < n; ++j)
    if (grid.h_m[j] < approach_m) {
      b_low = std::min(b_low, grid.B_per_m[j]);
      b_high = std::max(b_high, grid.B_per_m[j]);
    }
  // Pointwise, or uniform lateral curvature over the contact (nothing to smooth; Hertz stays bit-exact).
  if (options.treatment == CurvatureTreatment::Pointwise || b_low == b_high) {
    for (std::size_t k = 0; k < n; ++k)
      if (grid.h_m[k] < approach_m) compliance[k] = cache(grid.A_per_m[k], grid.B_per_m[k]);
    return;
  }
  // scratch: [0, n) weights, [n, 2n) half-width of the run holding each strip, [2n, 3n + 1) kernel by lag.
  scratch.assign(3 * n + 1, 0.0);
  double* weight = scratch.data();
  double* run_half_width = weight + n;
  double* kernel = weight + 2 * n;
  // Virtual interpenetration at half the approach, measured from the deepest point.
  const double h_min = *std::min_element(grid.h_m.begin(), grid.h_m.end());
  const double virtual_level = h_min + 0.5 * (approach_m - h_min);
  for (std::size_t i = 0; i < n; ++i) weight[i] = std::max(0.0, virtual_level - grid.h_m[i]);
  for (std::size_t i = 0; i < n;) {  // half-width of each run of positive weight
    std::size_t j = i;
    while (j < n && weight[j] > 0.0) ++j;
    for (std::size_t k = i; k < j; ++k) run_half_width[k] = 0.5 * static_cast<double>(j - i) * grid.strip_width_m;
    i = std::max(j, i + 1);
  }
  // Strips between runs take the nearest run's half-width (left-to-right, then right-to-left pass).
  std::vector<double> distance(n, std::numeric_limits<double>::infinity());
  for (int pass = 0; pass < 2; ++pass) {
    double carried = 0.0, carried_distance = std::numeric_limits<double>::infinity();
    for (std::size_t step = 0; step < n; ++step) {
      const std::size_t k = pass == 0 ? step : n - 1 - step;
      if (weight[k] > 0.0) {
        carried = run_half_width[k];
        carried_distance = 0.0;
        distance[k] = 0.0;
        continue;
      }
      carried_distance += 1.0;
      if (carried_distance < distance[k]) {
        distance[k] = carried_distance;
        run_half_width[k] = carried;
      }
    }
  }
  double kernel_length = -1.0;
  std::size_t reach = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (grid.h_m[k] >= approach_m) continue;  // never in contact at this approach
    const double length = options.smoothing_fraction * run_half_width[k];
    if (!(length > 0.0)) {  // no virtual contact anywhere: local curvature
      compliance[k] = cache(grid.A_per_m[k], grid.B_per_m[k]);
      continue;
    }
    if (length != kernel_length) {  // Gaussian weight per lag, recomputed only when the length changes
      kernel_length = length;
      reach = std::min(n, static_cast<std::size_t>(4.0 * length / grid.strip_width_m) + 1);
      for (std::size_t lag = 0; lag <= reach; ++lag) {
        const double d = static_cast<double>(lag) * grid.strip_width_m / length;
        kernel[lag] = std::exp(-0.5 * d * d);
      }
    }
    double sum_w = 0.0, sum_wb = 0.0;
    const std::size_t j_begin = k > reach ? k - reach : 0, j_end = std::min(n, k + reach + 1);
    for (std::size_t j = j_begin; j < j_end; ++j) {
      const double w = weight[j] * kernel[j > k ? j - k : k - j];
      sum_w += w;
      sum_wb += w * grid.B_per_m[j];
    }
    compliance[k] = cache(grid.A_per_m[k], sum_w > 0.0 ? sum_wb / sum_w : grid.B_per_m[k]);
  }
}

}  // namespace ctab::gen
