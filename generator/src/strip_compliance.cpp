#include "ctab/gen/strip_compliance.hpp"

#include <algorithm>
#include <cmath>

#include "ctab/gen/hertz.hpp"

namespace ctab::gen {

namespace {

// Minimum lateral curvature relative to the rolling one (CONTACT estimate_curvatures: R_y <= 20 R_x).
constexpr double kMinimumCurvatureRatio = 1.0 / 20.0;

// Memoised Eq. 26 factor: consecutive strips often share (A, B).
class ComplianceCache {
 public:
  explicit ComplianceCache(double E_star) : E_star_(E_star) {}
  double operator()(double A, double B) {
    B = std::max(B, kMinimumCurvatureRatio * A);
    if (A != last_A_ || B != last_B_) {
      last_A_ = A;
      last_B_ = B;
      last_value_ = strip_length_compliance(A, B, E_star_);
    }
    return last_value_;
  }

 private:
  double E_star_;
  double last_A_ = -1.0, last_B_ = -1.0, last_value_ = 0.0;
};

}  // namespace

void strip_compliances(const StripGrid& grid, double E_star_Pa, double approach_m, const CurvatureOptions& options,
                       std::vector<double>& compliance, std::vector<double>& scratch) {
  const std::size_t n = grid.size();
  compliance.assign(n, 0.0);
  ComplianceCache cache(E_star_Pa);
  if (options.treatment == CurvatureTreatment::Pointwise) {
    for (std::size_t i = 0; i < n; ++i) compliance[i] = cache(grid.A_per_m[i], grid.B_per_m[i]);
    return;
  }
  // Virtual interpenetration at half the approach, measured from the deepest point.
  const double h_min = *std::min_element(grid.h_m.begin(), grid.h_m.end());
  const double virtual_level = h_min + 0.5 * (approach_m - h_min);
  scratch.assign(2 * n, 0.0);
  double* weight = scratch.data();
  double* run_half_width = scratch.data() + n;
  for (std::size_t i = 0; i < n; ++i) weight[i] = std::max(0.0, virtual_level - grid.h_m[i]);
  // Half-width of each run of positive weight; strips outside a run take the nearest run's value.
  std::size_t i = 0;
  double last_half_width = 0.0;
  while (i < n) {
    if (weight[i] <= 0.0) {
      run_half_width[i] = -1.0;
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < n && weight[j] > 0.0) ++j;
    last_half_width = 0.5 * static_cast<double>(j - i) * grid.strip_width_m;
    for (std::size_t k = i; k < j; ++k) run_half_width[k] = last_half_width;
    i = j;
  }
  if (last_half_width == 0.0) {  // no virtual contact at all: fall back to the local curvature
    for (std::size_t k = 0; k < n; ++k) compliance[k] = cache(grid.A_per_m[k], grid.B_per_m[k]);
    return;
  }
  for (std::size_t k = 0, nearest = 0; k < n; ++k) {  // fill gaps with the nearest run's half-width
    if (run_half_width[k] > 0.0) {
      nearest = k;
      continue;
    }
    double best = -1.0;
    for (std::size_t d = 1; d < n && best < 0.0; ++d) {
      if (k >= d && run_half_width[k - d] > 0.0) best = run_half_width[k - d];
      if (k + d < n && run_half_width[k + d] > 0.0) best = run_half_width[k + d];
    }
    run_half_width[k] = best;
    (void)nearest;
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (grid.h_m[k] >= approach_m) continue;  // never in contact at this approach
    const double length = options.smoothing_fraction * run_half_width[k];
    const double inverse_two_l2 = 1.0 / (2.0 * length * length);
    const double reach = 4.0 * length;
    double sum_w = 0.0, sum_wb = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      if (weight[j] <= 0.0) continue;
      const double d = grid.y_m[j] - grid.y_m[k];
      if (std::abs(d) > reach) continue;
      const double w = weight[j] * std::exp(-d * d * inverse_two_l2);
      sum_w += w;
      sum_wb += w * grid.B_per_m[j];
    }
    const double B_eff = sum_w > 0.0 ? sum_wb / sum_w : grid.B_per_m[k];
    compliance[k] = cache(grid.A_per_m[k], B_eff);
  }
}

}  // namespace ctab::gen
