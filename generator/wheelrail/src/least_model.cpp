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

std::size_t auto_start_rung(double patch_width_m) noexcept {
  for (std::size_t k = 1; k < kAutoStripWidths_m.size(); ++k)
    if (patch_width_m / kAutoStripWidths_m[k] >= kMinResolvedStrips * (1.0 - 1e-9)) return k;
  return kAutoStripWidths_m.size() - 1;
}

double richardson_error(const WheelContact& fine, const StripWidthTotals& coarse) noexcept {
  const Totals f = totals(fine);
  const Totals c{coarse.area_m2, coarse.max_pressure_Pa};
  if (!coarse.solved || !(f.area_m2 > 0.0 && f.max_pressure_Pa > 0.0 && c.area_m2 > 0.0)) return kInfinity;
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
    chosen.matrix_entries += solved.matrix_entries;
    chosen.strip_width_m = width_m;
    return solved;
  };
  const auto done = [&](WheelContact&& contact) {
    if (choice != nullptr) *choice = chosen;
    return std::move(contact);
  };
  std::size_t rung = kAutoFirstRung;
  WheelContact fine = solve_at(kAutoStripWidths_m[rung]);
  const bool usable = is_success(fine.status) && fine.status != SolveStatus::NoContact && !fine.patches.empty();
  if (fine.status != SolveStatus::NoContact && !usable) fine = solve_at(kAutoFallbackWidth_m);
  if (!usable) return done(std::move(fine));
  chosen.patch_width_m = smallest_patch_width(fine);
  if (const std::size_t start = auto_start_rung(chosen.patch_width_m); start > rung) {
    rung = start;
    fine = solve_at(kAutoStripWidths_m[rung]);
  }
  for (;; ++rung) {
    Mim1dOptions coarse = at.mim1d;
    coarse.strip_width_m = 2.0 * kAutoStripWidths_m[rung];
    const StripWidthTotals check = resolve_at_strip_width(workspace, E_star_Pa, coarse);
    chosen.matrix_entries += check.matrix_entries;
    chosen.estimated_error = richardson_error(fine, check);
    const bool last = rung + 1 == kAutoStripWidths_m.size();
    const bool resolved = fine.status != SolveStatus::UnderResolved;
    if (last || !is_success(fine.status) || (resolved && kAutoSafetyFactor * chosen.estimated_error <= tolerance))
      return done(std::move(fine));
    fine = solve_at(kAutoStripWidths_m[rung + 1]);
  }
}

}  // namespace ctab::gen
