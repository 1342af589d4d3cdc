// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/hertz_strip.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <numbers>

#include "ctab/contact/hertz.hpp"

namespace ctab::gen {

namespace {

struct DeepestPoint {
  std::size_t k = 0;
  double y = 0.0, h = 0.0, A = 0.0, B = 0.0;
  double y_first = 0.0, y_last = 0.0;  // extent of the gap data [m]
};

// Lateral curvature rule (docs/method.md "The method ladder", hertz): the local B at the contact point when B >= A/20;
// otherwise (negative, i.e. concave, or nearly flat) the patch-mean lateral curvature, floored at A/20 unless the
// gap is convex across the patch (local B > 0 and the mean at least half of it: then the mean, unfloored).
constexpr double kCurvatureRatioLimit = 20.0;       // B >= A/20: CONTACT's R_y <= 20 R_x rule
constexpr double kMeanCurvatureHalfSpan_m = 10e-3;  // CONTACT clips the patch to +-10 mm around the point
constexpr int kMeanCurvatureIterations = 20;        // fixed point on (delta, B) for a prescribed load
constexpr double kMeanCurvatureTolerance = 1e-9;    // relative change of B that ends it
constexpr double kConvexMeanShare = 0.5;            // patch-mean B >= this x local B > 0: convex across the patch

// dh/dy at node i: central difference (one-sided at the ends).
double gap_slope(const GapProfile& gap, std::size_t i) {
  const std::size_t lo = i == 0 ? 0 : i - 1, hi = std::min(i + 1, gap.size() - 1);
  return (gap.h_m[hi] - gap.h_m[lo]) / (gap.y_m[hi] - gap.y_m[lo]);
}

// Patch-mean lateral curvature over the interpenetration run {h < h_k + depth} around the deepest node k,
// clipped to +-10 mm: B_mean = [h'(y_e) - h'(y_s)] / (2 (y_e - y_s)), i.e. half the mean of h'' over the run.
// This is CONTACT's estimate kappa ~ Delta(alpha)/Delta(s) between the two ends of the interpenetration region
// (eve70a/CONTACT m_wr_locatecp.f90 estimate_curvatures_v2; ../shared/facts/methods_and_tables.md 1.1.1), with
// alpha ~ dh/dy in the contact plane and B = kappa/2. NaN when the run holds a single node.
double mean_lateral_curvature(const GapProfile& gap, std::size_t k, double depth_m) {
  const double level = gap.h_m[k] + depth_m, y_k = gap.y_m[k];
  std::size_t s = k, e = k;
  while (s > 0 && gap.h_m[s - 1] < level && y_k - gap.y_m[s - 1] <= kMeanCurvatureHalfSpan_m) --s;
  while (e + 1 < gap.size() && gap.h_m[e + 1] < level && gap.y_m[e + 1] - y_k <= kMeanCurvatureHalfSpan_m) ++e;
  if (e == s) return std::numeric_limits<double>::quiet_NaN();
  return (gap_slope(gap, e) - gap_slope(gap, s)) / (2.0 * (gap.y_m[e] - gap.y_m[s]));
}

double lateral_curvature(const GapProfile& gap, const DeepestPoint& point, double depth_m) {
  const double floor = point.A / kCurvatureRatioLimit, local = gap.B_per_m[point.k];
  if (local >= floor) return local;
  const double mean = mean_lateral_curvature(gap, point.k, depth_m);
  if (!std::isfinite(mean)) return floor;
  // Convex across the patch (the local curvature positive, the patch mean at least half of it): the curvature is
  // the gap's own and needs no floor. Flooring it gave a wrong ellipse with status converged on a laterally
  // elongated Hertzian gap (B < A/20, a/b < 1/7; stability_matrix_test). The floor is for concave gaps.
  if (local > 0.0 && mean >= kConvexMeanShare * local) return mean;
  return std::max(mean, floor);
}

DeepestPoint deepest_point(const GapProfile& gap) {
  const auto k = static_cast<std::size_t>(std::min_element(gap.h_m.begin(), gap.h_m.end()) - gap.h_m.begin());
  return {k,
          gap.y_m[k],
          gap.h_m[k],
          gap.A_per_m[k],
          std::max(gap.B_per_m[k], gap.A_per_m[k] / kCurvatureRatioLimit),
          gap.y_m.front(),
          gap.y_m.back()};
}

// Strip centres (k + centre_offset) strip_width_m, as strip_grid.hpp places them.
NormalSolution make_patch(const HertzContact& contact, const DeepestPoint& point, double strip_width_m,
                          double centre_offset, std::chrono::steady_clock::time_point start) {
  NormalSolution solution;
  solution.method = "hertz";
  solution.status = contact.status;
  solution.approach_m = point.h + contact.approach_m;
  if (contact.status == SolveStatus::Converged) {
    if (point.y - contact.semi_axis_y_m < point.y_first || point.y + contact.semi_axis_y_m > point.y_last)
      solution.status = SolveStatus::ZoneTruncated;  // the ellipse runs past the gap data, as MIM-1D reports it
    solution.normal_load_N = contact.normal_force_N;
    PatchSolution patch;
    patch.normal_force_N = contact.normal_force_N;
    patch.area_m2 = contact.area_m2;
    patch.max_pressure_Pa = contact.max_pressure_Pa;
    patch.centre_of_pressure_y_m = point.y;
    patch.y_min_m = point.y - contact.semi_axis_y_m;
    patch.y_max_m = point.y + contact.semi_axis_y_m;
    const double b = contact.semi_axis_y_m;
    for (long k = static_cast<long>(std::ceil((point.y - b) / strip_width_m - centre_offset));; ++k) {
      const double y = (static_cast<double>(k) + centre_offset) * strip_width_m;
      if (y > point.y + b) break;
      const double s = (y - point.y) / b;
      if (std::abs(s) >= 1.0) continue;
      const double profile = std::sqrt(1.0 - s * s);
      const double a = contact.semi_axis_x_m * profile, p0 = contact.max_pressure_Pa * profile;
      patch.strips.push_back({y, a, p0, std::numbers::pi * a * 0.5 * strip_width_m * p0});
    }
    solution.patches.push_back(std::move(patch));
  }
  solution.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return solution;
}

}  // namespace

NormalSolution solve_hertz_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                        double approach_m) {
  const auto start = std::chrono::steady_clock::now();
  DeepestPoint point = deepest_point(gap);
  HertzContact contact;
  if (std::isfinite(approach_m) && approach_m <= point.h) {
    contact.status = SolveStatus::NoContact;
  } else {
    point.B = lateral_curvature(gap, point, approach_m - point.h);
    contact = hertz_from_approach(point.A, point.B, E_star_Pa, approach_m - point.h);
  }
  return make_patch(contact, point, strip_width_m, grid_centre_offset(gap.strip_alignment), start);
}

NormalSolution solve_hertz_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m,
                                    double normal_force_N) {
  const auto start = std::chrono::steady_clock::now();
  DeepestPoint point = deepest_point(gap);
  HertzContact contact = hertz_from_load(point.A, point.B, E_star_Pa, normal_force_N);
  // A patch-mean curvature depends on the patch, the patch on the curvature: fixed point on (delta, B).
  for (int i = 0; i < kMeanCurvatureIterations && contact.status == SolveStatus::Converged; ++i) {
    const double B = lateral_curvature(gap, point, contact.approach_m);
    const bool settled = std::abs(B - point.B) <= kMeanCurvatureTolerance * point.B;
    point.B = B;
    contact = hertz_from_load(point.A, point.B, E_star_Pa, normal_force_N);
    if (settled) break;
  }
  return make_patch(contact, point, strip_width_m, grid_centre_offset(gap.strip_alignment), start);
}

}  // namespace ctab::gen
