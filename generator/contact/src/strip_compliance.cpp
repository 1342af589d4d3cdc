// SPDX-License-Identifier: Apache-2.0
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
// Two runs of virtual interpenetration separated by a ridge shallower than this fraction of the virtual depth
// count partly as one (virtual_half_widths): 2 %, a narrow but continuous blend that stays below the ridge of a
// two-point contact (tread and flange root at dy = 5 mm: between 2 % and 5 % of the depth), which is not merged.
constexpr double kMergeBlendDepth = 0.02;
// Smoothing kernel: a Gaussian cut at kKernelCutoff standard deviations and lowered by its value there, so that it
// reaches zero continuously (a strip leaving its reach changes nothing). The local curvature carries a weight of
// kLocalCurvatureWeight x the virtual depth (chosen: ~1e-4 of the kernel sum inside a contact, so results there
// are unchanged to that order). Both keep B_eff, and the force-approach curve, continuous in the approach.
constexpr double kKernelCutoff = 4.0;
const double kKernelFloor = std::exp(-0.5 * kKernelCutoff * kKernelCutoff);
constexpr double kLocalCurvatureWeight = 1.0e-3;

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

// One run of positive virtual interpenetration: strips [begin, end), edges where it crosses zero [m].
struct VirtualRun {
  std::size_t begin = 0, end = 0;
  double left_m = 0.0, right_m = 0.0;
  [[nodiscard]] double half_width_m() const { return 0.5 * (right_m - left_m); }
};

// Half-width W_i of the virtual contact seen by every strip, continuous in the approach (a jump in W_i makes the
// strip compliances, and with them the force-approach curve, jump: Newton and the load root finder then cycle).
// Run edges are the zero crossings of the linearly interpolated virtual interpenetration (not whole strips), so a
// run widens smoothly as strips enter. Two neighbouring runs count partly as one, with the factor
// theta = 1 - ridge/(kMergeBlendDepth depth) in [0, 1] (ridge: how far the highest point between them stays
// above the virtual level), so that W_i grows smoothly into the merged run's half-width as the ridge goes under.
// Strips between runs interpolate linearly between the two neighbouring runs' W.
void virtual_half_widths(const StripGrid& grid, double level_m, double virtual_depth_m, const double* weight,
                         double* half_width) {
  const std::size_t n = grid.size();
  const double pitch = grid.strip_width_m;
  std::vector<VirtualRun> runs;
  std::vector<double> ridge;  // between runs r and r + 1: how far the gap stays above the virtual level [m]
  for (std::size_t i = 0; i < n;) {
    if (!(weight[i] > 0.0)) {
      ++i;
      continue;
    }
    VirtualRun run{i, i, 0.0, 0.0};
    while (run.end < n && weight[run.end] > 0.0) ++run.end;
    // Zero crossing between the last strip outside (level - h <= 0) and the first inside (w > 0).
    auto crossing = [&](std::size_t inside, std::size_t outside) {
      const double above = grid.h_m[outside] - level_m;  // >= 0
      return grid.y_m[inside] + (grid.y_m[outside] - grid.y_m[inside]) * weight[inside] / (weight[inside] + above);
    };
    run.left_m = run.begin == 0 ? grid.y_m[0] - 0.5 * pitch : crossing(run.begin, run.begin - 1);
    run.right_m = run.end == n ? grid.y_m[n - 1] + 0.5 * pitch : crossing(run.end - 1, run.end);
    if (!runs.empty()) {
      double highest = 0.0;
      for (std::size_t k = runs.back().end; k < run.begin; ++k) highest = std::max(highest, grid.h_m[k] - level_m);
      ridge.push_back(highest);
    }
    runs.push_back(run);
    i = run.end;
  }
  std::fill(half_width, half_width + n, 0.0);
  if (runs.empty()) return;
  // Effective half-width of each run: its own plus its neighbours' through the chain of merge factors.
  std::vector<double> theta(ridge.size()), effective(runs.size());
  for (std::size_t r = 0; r < ridge.size(); ++r)
    theta[r] = std::clamp(1.0 - ridge[r] / (kMergeBlendDepth * virtual_depth_m), 0.0, 1.0);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    effective[r] = runs[r].half_width_m();
    double chain = 1.0;
    for (std::size_t s = r; s-- > 0 && chain > 0.0;) effective[r] += (chain *= theta[s]) * runs[s].half_width_m();
    chain = 1.0;
    for (std::size_t s = r + 1; s < runs.size() && chain > 0.0; ++s)
      effective[r] += (chain *= theta[s - 1]) * runs[s].half_width_m();
  }
  std::size_t r = 0;  // the first run that does not end before strip k
  for (std::size_t k = 0; k < n; ++k) {
    while (r < runs.size() && runs[r].end <= k) ++r;
    if (r < runs.size() && k >= runs[r].begin) {
      half_width[k] = effective[r];
    } else if (r == 0) {
      half_width[k] = effective.front();
    } else if (r == runs.size()) {
      half_width[k] = effective.back();
    } else {  // between runs r - 1 and r
      const double t =
          std::clamp((grid.y_m[k] - runs[r - 1].right_m) / (runs[r].left_m - runs[r - 1].right_m), 0.0, 1.0);
      half_width[k] = (1.0 - t) * effective[r - 1] + t * effective[r];
    }
  }
}

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
  // Strips [weighted_begin, weighted_end) hold every positive weight: the sums skip the zeros outside (exactly).
  std::size_t weighted_begin = n, weighted_end = 0;
  for (std::size_t i = 0; i < n; ++i) {
    weight[i] = std::max(0.0, virtual_level - grid.h_m[i]);
    if (weight[i] > 0.0) weighted_begin = std::min(weighted_begin, i), weighted_end = i + 1;
  }
  virtual_half_widths(grid, virtual_level, virtual_level - h_min, weight, run_half_width);
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
      reach = std::min(n, static_cast<std::size_t>(kKernelCutoff * length / grid.strip_width_m) + 1);
      for (std::size_t lag = 0; lag <= reach; ++lag) {
        const double d = static_cast<double>(lag) * grid.strip_width_m / length;
        kernel[lag] = std::max(0.0, std::exp(-0.5 * d * d) - kKernelFloor);
      }
    }
    // The local curvature with a small weight of its own: B_eff tends to it where the kernel sees no virtual
    // contact, instead of switching to it when the last weight drops out of reach.
    const double local_weight = kLocalCurvatureWeight * (virtual_level - h_min);
    double sum_w = local_weight, sum_wb = local_weight * grid.B_per_m[k];
    const std::size_t j_begin = std::max(k > reach ? k - reach : 0, weighted_begin),
                      j_end = std::min(std::min(n, k + reach + 1), weighted_end);
    for (std::size_t j = j_begin; j < j_end; ++j) {
      const double w = weight[j] * kernel[j > k ? j - k : k - j];
      sum_w += w;
      sum_wb += w * grid.B_per_m[j];
    }
    compliance[k] = cache(grid.A_per_m[k], sum_w > 0.0 ? sum_wb / sum_w : grid.B_per_m[k]);
  }
}

}  // namespace ctab::gen
