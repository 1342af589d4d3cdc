// SPDX-License-Identifier: Apache-2.0
#include "interpenetration_centre.hpp"

#include <algorithm>
#include <cmath>

#include "wheelrail_tuning.hpp"

namespace ctab::gen {

namespace {

// The weights pen^(5/2) (integral of gap^2 along x) over the contiguous interpenetration region around the wheel
// parameter s0 at this step, with their moments in s and in the rail's inclination.
struct CentreSums {
  double weight = 0.0, moment = 0.0, angle_moment = 0.0;
  int samples = 0;
};

CentreSums centre_sums(const ShiftedSide& at, double s0, double approach_m, double step) {
  const SideGeometry& side = at.side;
  const double z_first = at.first_contact_z_m - side.track().nominal_radius_m;
  CentreSums sums;
  for (int direction : {-1, +1})
    for (int k = direction < 0 ? 1 : 0; k < tuning::kMaxSamplesPerSide * 10; ++k) {
      const double s = s0 + direction * step * k;
      if (!side.wheel().contains(s)) break;
      const double penetration = approach_m - (side.gap(s, at.dy_m, at.roll_rad) - z_first);
      if (!(penetration > 0.0)) break;
      const double rail_y = side.wheel_point(s, at.dy_m, at.roll_rad).rail_y_m;
      if (!side.rail().contains(rail_y)) break;
      const double weight = penetration * penetration * std::sqrt(penetration);
      sums.weight += weight;
      sums.moment += weight * s;
      sums.angle_moment += weight * std::atan(side.rail().at(rail_y).dz);
      ++sums.samples;
    }
  return sums;
}

}  // namespace

bool interpenetration_centre(const ShiftedSide& at, GapMinimum& point, double approach_m) {
  // Samples at the rigid scan's step, refined until the region holds kCentreSamples: the sums are smooth quadratures
  // of pen^(5/2), which vanishes at the region's edges, so a wide tread region needs no fine step.
  double step = SideGeometry::kScanStep_m;
  CentreSums sums = centre_sums(at, point.wheel_s_m, approach_m, step);
  while (sums.samples < tuning::kCentreSamples && step > tuning::kFinestCentreStep_m) {
    step = std::max(tuning::kFinestCentreStep_m, step * std::max(sums.samples, 1) / tuning::kCentreSamples);
    sums = centre_sums(at, point.wheel_s_m, approach_m, step);
  }
  if (sums.samples < 3 || !(sums.weight > 0.0)) return false;
  point.wheel_s_m = sums.moment / sums.weight;
  const WheelSurfacePoint w = at.side.wheel_point(point.wheel_s_m, at.dy_m, at.roll_rad);
  if (!at.side.rail().contains(w.rail_y_m)) return false;
  point.rail_y_m = w.rail_y_m;
  point.contact_angle_rad = sums.angle_moment / sums.weight;
  point.rolling_radius_m = w.radius_m;
  return true;
}

bool secant_centre(const ShiftedSide& at, const GapMinimum& from, const GapMinimum& centre, double step,
                   GapMinimum& out) {
  out = centre;
  out.wheel_s_m = from.wheel_s_m + step * (centre.wheel_s_m - from.wheel_s_m);
  out.contact_angle_rad = from.contact_angle_rad + step * (centre.contact_angle_rad - from.contact_angle_rad);
  if (!at.side.wheel().contains(out.wheel_s_m)) return false;
  const WheelSurfacePoint w = at.side.wheel_point(out.wheel_s_m, at.dy_m, at.roll_rad);
  if (!at.side.rail().contains(w.rail_y_m)) return false;
  out.rail_y_m = w.rail_y_m;
  out.rolling_radius_m = w.radius_m;
  return true;
}

}  // namespace ctab::gen
