// SPDX-License-Identifier: Apache-2.0
#include "centre_following.hpp"

namespace ctab::gen {

ShiftedSide shifted_side(const WheelCase& c) { return {c.side, c.dy_m, c.roll_rad, c.result.first_contact_z_m}; }

bool follows_centre(const WheelCase& c) {
  return c.options.reference != ReferenceRule::Prescribed && !c.recentring &&
         (c.options.takes_contacts_angle() || centres_conformal_grid(c.options));
}

bool centres_conformal_grid(const WheelRailOptions& options) {
  return options.surface == ContactSurface::Conformal && !options.at_interpenetration_centre();
}

bool centre_at(WheelCase& c, double x, GapMinimum& centre) {
  CentreCache& cache = c.centre_cache;
  if (x != cache.approach_m) {
    cache.approach_m = x;
    cache.centre = c.ws.minima[0];
    cache.found = interpenetration_centre(shifted_side(c), cache.centre, x);
  }
  centre = cache.centre;
  return cache.found;
}

void follow_interpenetration_centre(WheelCase& c, PatchProblem& main) {
  if (!follows_centre(c)) return;
  GapMinimum centre;
  if (!centre_at(c, main.gap_dz, centre)) return;
  if (c.options.at_interpenetration_centre()) {
    main.reference = centre;
    return;
  }
  if (c.options.takes_contacts_angle()) main.reference.contact_angle_rad = centre.contact_angle_rad;
  if (centres_conformal_grid(c.options)) main.origin_y = centre.rail_y_m;
}

double next_grid_origin(WheelCase& c, const PatchProblem& p, double x) {
  GapMinimum centre;
  if (!centres_conformal_grid(c.options) || !centre_at(c, x, centre)) return p.origin_y;
  return centre.rail_y_m;
}

}  // namespace ctab::gen
