// SPDX-License-Identifier: Apache-2.0
#include "ctab/validation/accuracy_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ctab::gen {

namespace {

//! Adds one patch (force, area, peak, load-weighted lateral position) to the totals.
void add_patch(ContactSummary& s, double force_N, double area_m2, double max_pressure_Pa, double y_cop_m,
               double& weighted_y) {
  s.area_m2 += area_m2;
  s.max_pressure_Pa = std::max(s.max_pressure_Pa, max_pressure_Pa);
  s.normal_force_N += force_N;
  weighted_y += force_N * y_cop_m;
}

void finish(ContactSummary& s, double weighted_y) {
  s.centre_of_pressure_m = s.normal_force_N > 0.0 ? weighted_y / s.normal_force_N : 0.0;
  for (auto& profile : s.profiles)
    std::sort(profile.begin(), profile.end(),
              [](const PressurePoint& a, const PressurePoint& b) { return a.y_m < b.y_m; });
}

double relative(double value, double reference) noexcept {
  if (!(reference > 0.0)) return std::numeric_limits<double>::infinity();
  return std::fabs(value - reference) / reference;
}

}  // namespace

namespace {

// Sums patches of either solution type: `centre_of` gives a patch's centre of pressure [m], `y_of` a strip's y [m].
template <class Patches, class CentreOf, class StripY>
ContactSummary summarise_patches(const Patches& patches, CentreOf centre_of, StripY y_of) {
  ContactSummary s;
  double weighted_y = 0.0;
  for (const auto& patch : patches) {
    add_patch(s, patch.normal_force_N, patch.area_m2, patch.max_pressure_Pa, centre_of(patch), weighted_y);
    auto& profile = s.profiles.emplace_back();
    for (const auto& strip : patch.strips) profile.push_back({y_of(strip), strip.p0_Pa});
  }
  finish(s, weighted_y);
  return s;
}

}  // namespace

ContactSummary summarise(const NormalSolution& solution) {
  return summarise_patches(
      solution.patches, [](const PatchSolution& p) { return p.centre_of_pressure_y_m; },
      [](const StripSolution& strip) { return strip.y_m; });
}

ContactSummary summarise(const WheelContact& contact) {
  return summarise_patches(
      contact.patches, [](const ContactPatch& p) { return p.y_cop_rail_m; },
      [](const PatchStrip& strip) { return strip.y_rail_m; });
}

double profile_pressure_at(const ContactSummary& summary, double y_m) noexcept {
  for (const auto& profile : summary.profiles) {
    if (profile.empty()) continue;
    // a strip covers half the spacing to its neighbour beyond the first and last centres (its own width)
    const double end_width = profile.size() > 1 ? 0.5 * (profile[1].y_m - profile[0].y_m) : 0.0;
    const double last_width = profile.size() > 1 ? 0.5 * (profile.back().y_m - profile[profile.size() - 2].y_m) : 0.0;
    if (y_m < profile.front().y_m - end_width || y_m > profile.back().y_m + last_width) continue;
    if (y_m <= profile.front().y_m) return profile.front().p0_Pa;
    if (y_m >= profile.back().y_m) return profile.back().p0_Pa;
    const auto upper = std::lower_bound(profile.begin(), profile.end(), y_m,
                                        [](const PressurePoint& p, double y) { return p.y_m < y; });
    if (upper == profile.begin()) return upper->p0_Pa;
    const auto lower = upper - 1;
    const double span = upper->y_m - lower->y_m;
    const double t = span > 0.0 ? (y_m - lower->y_m) / span : 0.0;
    return lower->p0_Pa + t * (upper->p0_Pa - lower->p0_Pa);
  }
  return 0.0;
}

AccuracyErrors accuracy_errors(const ContactSummary& candidate, const ContactSummary& reference) noexcept {
  AccuracyErrors e;
  e.area_rel = relative(candidate.area_m2, reference.area_m2);
  e.max_pressure_rel = relative(candidate.max_pressure_Pa, reference.max_pressure_Pa);
  double squared_error = 0.0, squared_reference = 0.0;
  for (const auto& profile : reference.profiles)
    for (const PressurePoint& point : profile) {
      const double d = profile_pressure_at(candidate, point.y_m) - point.p0_Pa;
      squared_error += d * d;
      squared_reference += point.p0_Pa * point.p0_Pa;
    }
  e.p0_profile_rms_rel =
      squared_reference > 0.0 ? std::sqrt(squared_error / squared_reference) : std::numeric_limits<double>::infinity();
  e.contact_point_m = std::fabs(candidate.centre_of_pressure_m - reference.centre_of_pressure_m);
  return e;
}

}  // namespace ctab::gen
