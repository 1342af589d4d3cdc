// SPDX-License-Identifier: Apache-2.0
#include "ctab/wheelrail/least_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ctab/contact/resolution.hpp"
#include "ctab/wheelrail/patch_shape.hpp"

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
  return std::max({std::abs(f.area_m2 - c.area_m2) / f.area_m2,
                   std::abs(f.max_pressure_Pa - c.max_pressure_Pa) / f.max_pressure_Pa, coarse.worst_patch_change});
}

bool strip_model_at_risk(const WheelContact& contact) noexcept {
  int loaded = 0;
  for (const ContactPatch& p : contact.patches) {
    if (!(p.normal_force_N >= kResolvedForceShare * contact.normal_force_N)) continue;
    ++loaded;
    if (p.zone == "flange" && patch_shape(p).angle_spread_rad >= kEscalationAngleSpread_rad) return true;
  }
  return loaded >= 2;
}

namespace {

// The coarsest of `sizes` (coarsest first) with at least kEscalationElementsAcross elements across `extent_m`.
double escalation_size(double extent_m, std::initializer_list<double> sizes) {
  double size = *sizes.begin();
  for (const double s : sizes) {
    size = s;
    if (extent_m / s >= kEscalationElementsAcross) break;
  }
  return size;
}

// Row width and element length of an escalated case from its MIM-1D patches carrying >= kResolvedForceShare.
void escalation_grid(const WheelContact& mim1d, double& row_width_m, double& element_length_m) {
  double width = kInfinity, length = kInfinity;
  for (const ContactPatch& p : mim1d.patches) {
    if (!(p.normal_force_N >= kResolvedForceShare * mim1d.normal_force_N)) continue;
    double longest = 0.0;
    for (const PatchStrip& s : p.strips) longest = std::max(longest, 2.0 * s.half_length_m);
    width = std::min(width, p.s_max_m - p.s_min_m);
    length = std::min(length, longest);
  }
  row_width_m = escalation_size(width, {kEscalationRowWidth_m, 0.5 * kEscalationRowWidth_m});
  element_length_m = escalation_size(length, {kEscalationElementLength_m, 0.5 * kEscalationElementLength_m,
                                              0.25 * kEscalationElementLength_m});
}

// The escalation of a case whose MIM-1D solution `mim1d` has a patch at risk: bem2d on the same case; when bem2d
// fails, the MIM-1D solution with status UnderResolved (usable, its bound not held) and bem2d's reason.
WheelContact escalate(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa, LoadKind load,
                      double load_value, const WheelRailOptions& options, WheelContactWorkspace& workspace,
                      WheelContact&& mim1d, AutoChoice& chosen) {
  WheelRailOptions at = options;
  at.method = ContactMethod::Bem2d;
  escalation_grid(mim1d, at.mim1d.strip_width_m, at.bem2d_element_length_m);
  WheelContact solved = solve_wheel_contact(side, dy_m, roll_rad, E_star_Pa, load, load_value, at, workspace);
  ++chosen.solves;
  if (solved.status == SolveStatus::Converged) {
    chosen.method = ContactMethod::Bem2d;
    chosen.strip_width_m = at.mim1d.strip_width_m;
    return solved;
  }
  mim1d.status = SolveStatus::UnderResolved;
  mim1d.detail = "the strip model may miss the tolerance on a patch whose surface turns (bem2d: " +
                 std::string(status_name(solved.status)) + (solved.detail.empty() ? "" : ", " + solved.detail) + ")";
  return std::move(mim1d);
}

}  // namespace

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
    const bool within = kAutoSafetyFactor * chosen.estimated_error <= tolerance;
    if (last || !is_success(fine.status) || (resolved && within)) {
      // The finest width without the estimate within the tolerance: usable, but its bound does not hold.
      if (last && !within && fine.status == SolveStatus::Converged) {
        fine.status = SolveStatus::UnderResolved;
        fine.detail = "the finest strip width's estimated error exceeds the tolerance on a patch";
      }
      if (is_success(fine.status) && fine.status != SolveStatus::NoContact && strip_model_at_risk(fine))
        return done(escalate(side, dy_m, roll_rad, E_star_Pa, load, load_value, options, workspace, std::move(fine),
                             chosen));
      return done(std::move(fine));
    }
    fine = solve_at(kAutoStripWidths_m[rung + 1]);
  }
}

}  // namespace ctab::gen
