#include "ctab/contact/hertz_strip.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "ctab/contact/hertz.hpp"

namespace ctab::gen {

namespace {

struct DeepestPoint {
  double y = 0.0, h = 0.0, A = 0.0, B = 0.0;
  double y_first = 0.0, y_last = 0.0;  // extent of the gap data [m]
};

DeepestPoint deepest_point(const GapProfile& gap) {
  const auto k = static_cast<std::size_t>(std::min_element(gap.h_m.begin(), gap.h_m.end()) - gap.h_m.begin());
  return {gap.y_m[k], gap.h_m[k], gap.A_per_m[k], std::max(gap.B_per_m[k], gap.A_per_m[k] / 20.0), gap.y_m.front(),
          gap.y_m.back()};
}

NormalSolution make_patch(const HertzContact& contact, const DeepestPoint& point, double strip_width_m,
                          std::chrono::steady_clock::time_point start) {
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
    for (long k = static_cast<long>(std::ceil((point.y - b) / strip_width_m - 0.5));; ++k) {
      const double y = (static_cast<double>(k) + 0.5) * strip_width_m;
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

NormalSolution solve_hertz_for_approach(const GapProfile& gap, double E_star_Pa, double strip_width_m, double approach_m) {
  const auto start = std::chrono::steady_clock::now();
  const DeepestPoint point = deepest_point(gap);
  HertzContact contact;
  if (std::isfinite(approach_m) && approach_m <= point.h) {
    contact.status = SolveStatus::NoContact;
  } else {
    contact = hertz_from_approach(point.A, point.B, E_star_Pa, approach_m - point.h);
  }
  return make_patch(contact, point, strip_width_m, start);
}

NormalSolution solve_hertz_for_load(const GapProfile& gap, double E_star_Pa, double strip_width_m, double normal_force_N) {
  const auto start = std::chrono::steady_clock::now();
  const DeepestPoint point = deepest_point(gap);
  return make_patch(hertz_from_load(point.A, point.B, E_star_Pa, normal_force_N), point, strip_width_m, start);
}

}  // namespace ctab::gen
