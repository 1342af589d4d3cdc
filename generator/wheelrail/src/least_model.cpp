#include "ctab/wheelrail/least_model.hpp"

#include <cmath>
#include <limits>

#include "ctab/contact/resolution.hpp"

namespace ctab::gen {

namespace {

// Smallest width of the patches counted by the resolution rule [m]; 0 without such a patch.
double smallest_patch_width(const WheelContact& contact) {
  std::vector<PatchExtent> extents;
  for (const ContactPatch& p : contact.patches) extents.push_back({p.s_max_m - p.s_min_m, 0.0, p.normal_force_N});
  const double strips = min_resolved_strips(extents, ContactMethod::Mim1d, 1.0);
  return std::isfinite(strips) ? strips : 0.0;
}

double strips_in(const WheelContact& contact, double strip_width_m) {
  double strips = 0.0;
  for (const ContactPatch& p : contact.patches) strips += std::round((p.s_max_m - p.s_min_m) / strip_width_m);
  return strips;
}

}  // namespace

double auto_error_estimate(double strips) noexcept {
  return strips > 0.0 ? kAutoErrorCoefficient / strips : std::numeric_limits<double>::infinity();
}

double auto_strip_width(double patch_width_m, double tolerance) noexcept {
  for (const double width_m : kAutoStripWidths_m)
    if (kAutoSafetyFactor * auto_error_estimate(patch_width_m / width_m) <= tolerance) return width_m;
  return kAutoStripWidths_m.back();
}

WheelContact solve_wheel_contact_auto(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                      LoadKind load, double load_value, const WheelRailOptions& options,
                                      double tolerance, WheelContactWorkspace& workspace, AutoChoice* choice) {
  WheelRailOptions at = options;
  at.method = ContactMethod::Mim1d;
  const auto solve_at = [&](double width_m) {
    at.mim1d.strip_width_m = width_m;
    return solve_wheel_contact(side, dy_m, roll_rad, E_star_Pa, load, load_value, at, workspace);
  };
  AutoChoice chosen;
  const double first_width_m = kAutoStripWidths_m.front();
  WheelContact first = solve_at(first_width_m);
  chosen.solves = 1;
  chosen.strips_solved = strips_in(first, first_width_m);
  double width_m = first_width_m;
  if (first.status == SolveStatus::NoContact) {
    // nothing to resolve: the first look is the answer
  } else if (!is_success(first.status) || first.patches.empty()) {
    width_m = kAutoFallbackWidth_m;
  } else {
    chosen.patch_width_m = smallest_patch_width(first);
    width_m = auto_strip_width(chosen.patch_width_m, tolerance);
  }
  chosen.strip_width_m = width_m;
  chosen.estimated_error = chosen.patch_width_m > 0.0 ? auto_error_estimate(chosen.patch_width_m / width_m) : 0.0;
  if (width_m != first_width_m) {
    first = solve_at(width_m);
    ++chosen.solves;
    chosen.strips_solved += strips_in(first, width_m);
  }
  if (choice != nullptr) *choice = chosen;
  return first;
}

}  // namespace ctab::gen
