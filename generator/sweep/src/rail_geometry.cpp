// SPDX-License-Identifier: Apache-2.0
// Where a stored patch's s coordinate starts on the rail profile (rail_geometry.hpp).
#include "rail_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace ctab::gen::detail {

namespace {

// Second start point of the secant steps, beside the extrapolated one [m]: 0.1 mm, well inside the millimetre
// scale over which the rail's slope changes, so the first secant is close to the slope's derivative.
constexpr double kSecantStartStep_m = 1e-4;
// Secant steps at most: the search converges superlinearly within a few steps near a tangent point; the cap ends
// it where the slope never reaches the target (a patch beyond the profile's slopes).
constexpr int kMaxSecantSteps = 40;
// Slope mismatch [-] at which the steps stop: the round-off level of the rail's tabulated slope.
constexpr double kSlopeConverged = 1e-13;
// Slope mismatch [-] up to which the point counts as the tangent point; a larger one keeps the extrapolation.
constexpr double kSlopeAccepted = 1e-9;

}  // namespace

double s_origin_y_rail(const ContactPatch& patch, const ProfileTable& rail) {
  if (std::isfinite(patch.s_origin_y_rail_m)) return patch.s_origin_y_rail_m;  // conformal: the surface's origin
  if (patch.s_min_m <= 0.0 && patch.s_max_m >= 0.0) return patch.y_rail_m;
  const auto& strips = patch.strips;
  double y = patch.y_rail_m;
  if (strips.size() >= 2 && strips.back().s_m > strips.front().s_m)
    y = strips.front().y_rail_m - strips.front().s_m * (strips.back().y_rail_m - strips.front().y_rail_m) /
                                      (strips.back().s_m - strips.front().s_m);
  const double target = std::tan(patch.plane_angle_rad);
  auto f = [&](double at) { return rail.at(at).dz - target; };
  double y0 = y, y1 = y + kSecantStartStep_m, f0 = f(y0), f1 = f(y1);
  for (int i = 0; i < kMaxSecantSteps && std::abs(f1) > kSlopeConverged && f1 != f0; ++i) {
    const double next = y1 - f1 * (y1 - y0) / (f1 - f0);
    y0 = y1;
    f0 = f1;
    y1 = std::clamp(next, rail.y_min(), rail.y_max());
    f1 = f(y1);
  }
  return std::abs(f1) <= kSlopeAccepted ? y1 : y;
}

}  // namespace ctab::gen::detail
