// SPDX-License-Identifier: Apache-2.0
#include "patch_results.hpp"

#include <cmath>

#include "further_patches.hpp"
#include "linear_interpolation.hpp"
#include "patch_forces.hpp"

namespace ctab::gen {

namespace {

// Contact point of a run of strips: its deepest rigid point (the reference minimum for the run that holds it).
GapMinimum contact_point(const WheelCase& c, const PatchProblem& p, const PatchSolution& ps) {
  std::size_t deepest = p.gap.size();
  for (std::size_t i = 0; i < p.gap.size(); ++i)
    if (p.gap.y_m[i] >= ps.y_min_m && p.gap.y_m[i] <= ps.y_max_m &&
        (deepest == p.gap.size() || p.gap.h_m[i] < p.gap.h_m[deepest]))
      deepest = i;
  const bool holds_reference = ps.y_min_m <= p.reference_s && ps.y_max_m >= p.reference_s;
  GapMinimum point = p.reference;
  if (!holds_reference && deepest < p.gap.size()) {
    double s_guess = p.reference.wheel_s_m;
    point.rail_y_m = p.rail_y[deepest];
    (void)c.builder.wheel_at(point.rail_y_m, s_guess);
    point.wheel_s_m = s_guess;
    point.rolling_radius_m = c.side.track().nominal_radius_m + c.side.wheel().at(s_guess).z;
  }
  return point;
}

void add_patch(WheelCase& c, const PatchProblem& p, const PatchSolution& ps) {
  const GapMinimum point = contact_point(c, p, ps);
  ContactPatch out;
  out.zone = point.wheel_s_m > kFlangeRootS_m ? "tread" : "flange";
  out.normal_force_N = ps.normal_force_N;
  out.area_m2 = ps.area_m2;
  out.max_pressure_Pa = ps.max_pressure_Pa;
  out.approach_m = p.solution.approach_m;
  out.plane_angle_rad = p.angle;
  out.y_rail_m = point.rail_y_m;
  out.y_wheel_m = point.wheel_s_m;
  out.rolling_radius_m = point.rolling_radius_m;
  out.y_cop_rail_m = interpolate(p.gap.y_m, p.rail_y, ps.centre_of_pressure_y_m);
  out.s_min_m = ps.y_min_m;
  out.s_max_m = ps.y_max_m;
  double weighted_y = 0.0;
  for (const StripSolution& st : ps.strips) {
    const double y = interpolate(p.gap.y_m, p.rail_y, st.y_m);
    out.strips.push_back({st.y_m, y, st.half_length_m, st.p0_Pa});
    weighted_y += st.load_N * y;
  }
  c.result.normal_force_N += out.normal_force_N;
  const ForceComponents force = run_force(p, ps);
  out.force_lateral_N = force.lateral_N;
  out.force_vertical_N = force.vertical_N;
  // Contact angle on both surfaces: the direction of the patch's resultant normal force, the sum of the strips'
  // loads along their normals (planar: every strip has the plane's normal, so it equals plane_angle_rad).
  out.contact_angle_rad = std::atan2(-force.lateral_N, force.vertical_N);
  if (c.options.surface == ContactSurface::Conformal) {
    // CONTACT's y_cop_rail (sum q_i y_i / sum q_i over the strips' points on the curved surface).
    out.y_cop_rail_m = weighted_y / ps.normal_force_N;
    out.s_origin_y_rail_m = interpolate(p.gap.y_m, p.rail_y, 0.0);
  }
  c.result.vertical_force_N += out.force_vertical_N;
  c.result.patches.push_back(std::move(out));
}

bool all_patches_out_of_contact(const WheelCase& c) {
  for (std::size_t slot = 0; slot < c.ws.used; ++slot)
    if (c.ws.pool[slot].solution.status != SolveStatus::NoContact) return false;
  return true;
}

}  // namespace

SolveStatus collect_patches(WheelCase& c) {
  SolveStatus status = SolveStatus::Converged;
  for (std::size_t slot = 0; slot < c.ws.used; ++slot) {
    const PatchProblem& p = c.ws.pool[slot];
    if (p.solution.status == SolveStatus::NoContact) continue;
    if (!is_success(p.solution.status)) {
      status = p.solution.status;
      if (c.detail.empty() || p.solution.status != SolveStatus::ZoneTruncated)
        c.detail = patch_failure(c.options.method, p.solution, slot);
    }
    for (const PatchSolution& ps : p.solution.patches) add_patch(c, p, ps);
  }
  if (c.result.patches.empty() && status == SolveStatus::Converged) {
    // An approach too small to reach any strip centre (e.g. 1 nm) is no contact, as on a gap file.
    if (all_patches_out_of_contact(c)) return SolveStatus::NoContact;
    c.detail = "no loaded strip in any patch";
    status = SolveStatus::NumericalFailure;
  }
  return status;
}

void collect_near_misses(WheelCase& c) {
  for (std::size_t k = 1; k < c.ws.minima.size(); ++k)
    if (c.ws.minima[k].gap_m >= c.result.vertical_approach_m && !inside_window(c, c.ws.minima[k]))
      c.result.near_misses.push_back(c.ws.minima[k]);
}

std::vector<PatchExtent> patch_extents(const WheelContact& result) {
  std::vector<PatchExtent> extents;
  for (const ContactPatch& p : result.patches)
    extents.push_back(patch_extent(p.s_max_m - p.s_min_m, p.normal_force_N, p.strips));
  return extents;
}

}  // namespace ctab::gen
