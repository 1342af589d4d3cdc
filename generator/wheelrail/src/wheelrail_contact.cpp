// SPDX-License-Identifier: Apache-2.0
// The driver of one wheel-rail case: rigid contact search, the main patch in a window that grows while the contact
// reaches its end, CONTACT's reference point where asked, further patches, results. The steps live in their own
// files (wheel_case.hpp lists them).
#include "ctab/wheelrail/wheelrail_contact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "centre_following.hpp"
#include "further_patches.hpp"
#include "gap_passes.hpp"
#include "main_patch_strips.hpp"
#include "patch_forces.hpp"
#include "patch_results.hpp"
#include "wheel_case.hpp"
#include "wheelrail_tuning.hpp"
#include "ctab/contact/resolution.hpp"

namespace ctab::gen {

using namespace tuning;

WheelContactWorkspace::WheelContactWorkspace() : impl_(std::make_unique<Impl>()) {}
WheelContactWorkspace::~WheelContactWorkspace() = default;
WheelContactWorkspace::WheelContactWorkspace(WheelContactWorkspace&&) noexcept = default;
WheelContactWorkspace& WheelContactWorkspace::operator=(WheelContactWorkspace&&) noexcept = default;

namespace {

// Sums of one patch problem's loaded runs.
struct PatchTotals {
  double force_N = 0.0, area_m2 = 0.0, max_pressure_Pa = 0.0;
};

PatchTotals patch_totals(const NormalSolution& solution) {
  PatchTotals t;
  for (const PatchSolution& run : solution.patches) {
    t.force_N += run.normal_force_N;
    t.area_m2 += run.area_m2;
    t.max_pressure_Pa = std::max(t.max_pressure_Pa, run.max_pressure_Pa);
  }
  return t;
}

// |value - reference| / reference; +inf without a positive reference.
double relative_change(double value, double reference) {
  return reference > 0.0 ? std::abs(value - reference) / reference : std::numeric_limits<double>::infinity();
}

std::string invalid_input(const WheelCase& c) {
  const WheelRailOptions& options = c.options;
  if (!std::isfinite(c.dy_m)) return "lateral shift dy is not finite";
  if (!std::isfinite(c.roll_rad)) return "roll angle is not finite";
  if (!std::isfinite(c.load_value)) return "load is not finite";
  if (c.load_value < 0.0) return c.load == LoadKind::Approach ? "negative approach" : "negative load";
  if (options.reference == ReferenceRule::Prescribed) {
    const PrescribedReference& reference = options.prescribed_reference;
    if (options.surface != ContactSurface::Planar) return "a prescribed reference point needs the planar surface";
    if (!std::isfinite(reference.contact_angle_rad) || !c.side.rail().contains(reference.rail_y_m))
      return "the prescribed reference point (rail y " + number_text(reference.rail_y_m) + " m, angle " +
             number_text(reference.contact_angle_rad) + " rad) is not on the rail profile";
  }
  return {};
}

// Gap minima and the height of first contact; false when the wheel is not over the rail.
bool find_rigid_contact(WheelCase& c) {
  double z_first = 0.0;
  c.side.gap_minima(c.dy_m, c.roll_rad, c.ws.minima, z_first);
  if (c.ws.minima.empty() || !std::isfinite(z_first)) return false;
  c.result.first_contact_z_m = z_first + c.side.track().nominal_radius_m;
  c.result.rigid_contact = c.ws.minima[0];
  c.builder.set_first_contact_height(z_first);
  // At most one patch per gap minimum: size the pool now so that references into it stay valid.
  if (c.ws.pool.size() < c.ws.minima.size()) c.ws.pool.resize(c.ws.minima.size());
  return true;
}

// The main patch's reference point: the deepest gap minimum, or the prescribed point (WheelRailOptions).
GapMinimum main_reference(WheelCase& c) {
  GapMinimum point = c.ws.minima[0];
  if (c.options.reference != ReferenceRule::Prescribed) return point;
  point.rail_y_m = c.options.prescribed_reference.rail_y_m;
  point.contact_angle_rad = c.options.prescribed_reference.contact_angle_rad;
  const WheelSurfacePoint w = c.builder.wheel_at(point.rail_y_m, point.wheel_s_m);
  point.rolling_radius_m = w.radius_m;
  return point;
}

// The main patch on its own, at this reference point: a prescribed approach samples the gap at it, a prescribed load
// runs the gap passes (gap_passes.hpp). Converged, or the failure with c.detail.
SolveStatus solve_main_patch(WheelCase& c, double depth, const GapMinimum& reference) {
  c.ws.used = 0;
  PatchProblem& main = c.ws.acquire();
  main.reference = reference;
  if (c.load == LoadKind::Approach) {
    main.gap_dz = c.load_value;
    follow_interpenetration_centre(c, main);
    if (!build_main(c, main, depth)) return SolveStatus::InvalidInput;
    c.result.vertical_approach_m = c.load_value;
    solve_patch_at(c, main, c.load_value);
  } else if (const SolveStatus status = solve_main_for_load(c, main, depth); status != SolveStatus::Converged) {
    return status;
  }
  const SolveStatus status = main.solution.status;
  if (!is_success(status) && status != SolveStatus::ZoneTruncated)
    c.detail = patch_failure(c.options.method, main.solution, 0);
  return is_success(status) ? SolveStatus::Converged : status;
}

// CONTACT's reference rule: the main patch re-solved in the plane at the interpenetration centre of its solved
// approach until the reference point moves by less than kRecentreTolerance_m (at most kRecentrePasses). The re-solves
// are secant steps on the fixed point c = C(c) (C: the centre at the approach solved in the plane at c): where one
// region spans tread and flange root C has a slope near -1, where plain re-solves alternate between two centres.
SolveStatus recentre_main_patch(WheelCase& c, double depth) {
  if (!c.options.at_interpenetration_centre()) return SolveStatus::Converged;
  GapMinimum previous_at{}, previous_centre{};
  for (int pass = 0; pass < kRecentrePasses; ++pass) {
    const GapMinimum at = c.ws.pool[0].reference;
    GapMinimum centre = c.ws.minima[0];
    if (!interpenetration_centre(shifted_side(c), centre, c.result.vertical_approach_m)) return SolveStatus::Converged;
    if (std::abs(centre.rail_y_m - at.rail_y_m) < kRecentreTolerance_m) return SolveStatus::Converged;
    GapMinimum next = centre;
    const double moved = at.rail_y_m - previous_at.rail_y_m;
    if (pass > 0 && moved != 0.0) {
      const double slope = std::min((centre.rail_y_m - previous_centre.rail_y_m) / moved, kMaxCentreSlope);
      if (!secant_centre(shifted_side(c), at, centre, 1.0 / (1.0 - slope), next)) next = centre;
    }
    previous_at = at;
    previous_centre = centre;
    c.recentring = true;  // the plane stays at this centre through the re-solve's passes
    const SolveStatus status = solve_main_patch(c, depth, next);
    c.recentring = false;
    if (status != SolveStatus::Converged) return status;
  }
  return SolveStatus::Converged;
}

// Solves in a window that doubles while the main contact reaches its end. Converged, or the failure (with c.detail);
// a contact still truncated after kWindowAttempts is left for collect_patches to report.
SolveStatus solve_in_growing_window(WheelCase& c) {
  double depth = std::max(kWindowFactor * expected_approach(c.side, c.ws.minima[0], c.dy_m, c.roll_rad, c.E_star_Pa,
                                                            c.load, c.load_value),
                          kMinimumWindowDepth_m);
  for (int attempt = 0; attempt < kWindowAttempts; ++attempt) {
    const SolveStatus status = solve_main_patch(c, depth, main_reference(c));
    if (status == SolveStatus::ZoneTruncated) {
      depth *= kWindowGrowth;
      continue;
    }
    if (status != SolveStatus::Converged) return status;
    if (const SolveStatus recentred = recentre_main_patch(c, depth); recentred != SolveStatus::Converged) {
      if (recentred == SolveStatus::ZoneTruncated) {
        depth *= kWindowGrowth;
        continue;
      }
      return recentred;
    }
    open_further_patches(c, depth);
    return solve_further_patches(c);
  }
  c.detail = "the contact reaches the end of the window after " + std::to_string(kWindowAttempts) +
             " widenings (depth " + number_text(depth / kWindowGrowth) + " m): the profiles end inside the contact";
  return SolveStatus::Converged;
}

// The main patch's last solve as the next shift's warm start (cleared when this case failed).
void save_warm_start(WheelCase& c, SolveStatus status) {
  if (c.warm == nullptr) return;
  const PatchProblem* main = c.ws.used > 0 ? &c.ws.pool[0] : nullptr;
  if (is_success(status) && main != nullptr && main->solver && c.mim1d()) {
    c.warm->push_back_to_earlier();  // the next shift extrapolates from this case and the one before
    main->solver->save_warm_start(main->solution, *c.warm);
    c.warm->origin_y_m = main->grid_origin_y();
    c.warm->origin_angle_rad = main->angle;
    c.warm->sampling_approach_m = main->gap_dz;
    c.warm->same_contact = false;  // the next shift's contact
  } else {
    c.warm->clear();
  }
}

WheelContact finish(WheelCase& c, SolveStatus status, std::string detail = {}) {
  save_warm_start(c, status);
  c.result.status = resolution_status(status, c.options.method, patch_extents(c.result), c.options.mim1d.strip_width_m);
  if (!is_success(status)) {
    c.result.patches.clear();
    c.result.detail = detail.empty() ? status_name(status) : std::move(detail);
  }
  c.result.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - c.start).count();
  return std::move(c.result);
}

WheelContact solve_case(WheelCase& c) {
  c.ws.used = 0;
  if (c.warm != nullptr) extrapolate_warm_start(*c.warm, c.ws.chain_start);
  c.result.dy_m = c.dy_m;
  c.result.roll_rad = c.roll_rad;
  if (std::string why = invalid_input(c); !why.empty()) return finish(c, SolveStatus::InvalidInput, std::move(why));
  if (!find_rigid_contact(c))
    return finish(c, SolveStatus::InvalidInput,
                  "the wheel does not reach the rail at dy = " + number_text(c.dy_m) +
                      " m, roll = " + number_text(c.roll_rad) + " rad (lateral shift beyond the profiles)");
  if (c.load_value == 0.0) {
    c.result.near_misses = c.ws.minima;
    return finish(c, SolveStatus::NoContact);
  }
  if (const SolveStatus status = solve_in_growing_window(c); status != SolveStatus::Converged)
    return finish(c, status, std::move(c.detail));
  const SolveStatus status = collect_patches(c);
  collect_near_misses(c);
  return finish(c, status, std::move(c.detail));
}

}  // namespace

WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                 LoadKind load, double load_value, const WheelRailOptions& options) {
  WheelContactWorkspace workspace;
  return solve_wheel_contact(side, dy_m, roll_rad, E_star_Pa, load, load_value, options, workspace);
}

WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                 LoadKind load, double load_value, const WheelRailOptions& options,
                                 WheelContactWorkspace& workspace) {
  WheelCase c(side, dy_m, roll_rad, E_star_Pa, load, load_value, options, workspace.impl(), nullptr);
  return solve_case(c);
}

WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                 LoadKind load, double load_value, const WheelRailOptions& options,
                                 WheelContactWorkspace& workspace, Mim1dWarmStart& warm_start) {
  WheelCase c(side, dy_m, roll_rad, E_star_Pa, load, load_value, options, workspace.impl(), &warm_start);
  return solve_case(c);
}

StripWidthTotals resolve_at_strip_width(WheelContactWorkspace& workspace, double E_star_Pa,
                                        const Mim1dOptions& options) noexcept {
  WheelContactWorkspace::Impl& ws = workspace.impl();
  StripWidthTotals totals;
  double case_force_N = 0.0;
  for (std::size_t k = 0; k < ws.used; ++k)
    if (is_success(ws.pool[k].solution.status)) case_force_N += ws.pool[k].solution.normal_load_N;
  for (std::size_t k = 0; k < ws.used; ++k) {
    const PatchProblem& p = ws.pool[k];
    const PatchTotals own = patch_totals(p.solution);
    if (!is_success(p.solution.status) || !(own.force_N > 0.0)) continue;
    if (!prepare_mim1d_solver(ws.other_width, p.gap, E_star_Pa, options).empty()) return {};
    const NormalSolution solution = ws.other_width->solve_for_load(own.force_N, Mim1dWarmStart{}, options.tolerance);
    if (!is_success(solution.status)) return {};
    totals.matrix_entries += solution.matrix_entries;
    const PatchTotals other = patch_totals(solution);
    totals.area_m2 += other.area_m2;
    totals.max_pressure_Pa = std::max(totals.max_pressure_Pa, other.max_pressure_Pa);
    if (own.force_N >= kResolvedForceShare * case_force_N)
      totals.worst_patch_change = std::max({totals.worst_patch_change, relative_change(other.area_m2, own.area_m2),
                                            relative_change(other.max_pressure_Pa, own.max_pressure_Pa)});
    totals.solved = true;
  }
  return totals;
}

}  // namespace ctab::gen
