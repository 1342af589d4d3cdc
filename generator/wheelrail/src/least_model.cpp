#include "ctab/wheelrail/least_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ctab/contact/resolution.hpp"

namespace ctab::gen {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Smallest width of the patches the resolution rule counts [m]; 0 without such a patch.
double smallest_patch_width(const WheelContact& contact) {
  std::vector<PatchExtent> extents;
  for (const ContactPatch& p : contact.patches) extents.push_back({p.s_max_m - p.s_min_m, 0.0, p.normal_force_N});
  const double width_m = min_resolved_strips(extents, ContactMethod::Mim1d, 1.0);
  return std::isfinite(width_m) ? width_m : 0.0;
}

// Total area [m^2] and largest peak pressure [Pa] over the patches.
struct Totals {
  double area_m2 = 0.0, max_pressure_Pa = 0.0;
};

Totals totals(const WheelContact& contact) {
  Totals t;
  for (const ContactPatch& p : contact.patches) {
    t.area_m2 += p.area_m2;
    t.max_pressure_Pa = std::max(t.max_pressure_Pa, p.max_pressure_Pa);
  }
  return t;
}

}  // namespace

double strips_in(const WheelContact& contact, double strip_width_m, bool squared) noexcept {
  double strips = 0.0;
  for (const ContactPatch& p : contact.patches) {
    const double n = std::round((p.s_max_m - p.s_min_m) / strip_width_m);
    strips += squared ? n * n : n;
  }
  return strips;
}

std::size_t auto_start_rung(double patch_width_m) noexcept {
  for (std::size_t k = 1; k < kAutoStripWidths_m.size(); ++k)
    if (patch_width_m / kAutoStripWidths_m[k] >= kMinResolvedStrips * (1.0 - 1e-9)) return k;
  return kAutoStripWidths_m.size() - 1;
}

double richardson_error(const WheelContact& fine, const WheelContact& coarse) noexcept {
  const Totals f = totals(fine), c = totals(coarse);
  if (!(f.area_m2 > 0.0 && f.max_pressure_Pa > 0.0 && c.area_m2 > 0.0)) return kInfinity;
  return std::max(std::abs(f.area_m2 - c.area_m2) / f.area_m2,
                  std::abs(f.max_pressure_Pa - c.max_pressure_Pa) / f.max_pressure_Pa);
}

WheelContact solve_wheel_contact_auto(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                      LoadKind load, double load_value, const WheelRailOptions& options,
                                      double tolerance, WheelContactWorkspace& workspace, AutoChoice* choice) {
  WheelRailOptions at = options;
  at.method = ContactMethod::Mim1d;
  AutoChoice chosen;
  const auto solve_at = [&](double width_m) {
    at.mim1d.strip_width_m = width_m;
    WheelContact solved = solve_wheel_contact(side, dy_m, roll_rad, E_star_Pa, load, load_value, at, workspace);
    ++chosen.solves;
    chosen.strips_solved += strips_in(solved, width_m);
    chosen.influence_entries += strips_in(solved, width_m, true);
    chosen.strip_width_m = width_m;
    return solved;
  };
  WheelContact coarse = solve_at(kAutoStripWidths_m.front());
  const bool usable = is_success(coarse.status) && coarse.status != SolveStatus::NoContact && !coarse.patches.empty();
  if (coarse.status != SolveStatus::NoContact && !usable) coarse = solve_at(kAutoFallbackWidth_m);
  if (!usable) {
    if (choice != nullptr) *choice = chosen;
    return coarse;
  }
  chosen.patch_width_m = smallest_patch_width(coarse);
  std::size_t rung = auto_start_rung(chosen.patch_width_m);
  if (rung > 1) coarse = solve_at(kAutoStripWidths_m[rung - 1]);
  for (;; ++rung) {
    WheelContact fine = solve_at(kAutoStripWidths_m[rung]);
    chosen.estimated_error = richardson_error(fine, coarse);
    const bool last = rung + 1 == kAutoStripWidths_m.size();
    const bool resolved = fine.status != SolveStatus::UnderResolved;
    if (last || !is_success(fine.status) || (resolved && kAutoSafetyFactor * chosen.estimated_error <= tolerance)) {
      if (choice != nullptr) *choice = chosen;
      return fine;
    }
    coarse = std::move(fine);
  }
}

}  // namespace ctab::gen
