// SPDX-License-Identifier: Apache-2.0
#include "ctab/wheelrail/patch_shape.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ctab::gen {

PatchShape patch_shape(const ContactPatch& patch) noexcept {
  PatchShape shape;
  const std::vector<PatchStrip>& strips = patch.strips;
  shape.strips = static_cast<int>(strips.size());
  double longest_m = 0.0;
  for (const PatchStrip& s : strips) longest_m = std::max(longest_m, 2.0 * s.half_length_m);
  if (longest_m > 0.0) shape.aspect_ratio = (patch.s_max_m - patch.s_min_m) / longest_m;
  // The surface inclination between neighbouring strips: cos(alpha) = |d y_rail / d s| (conformal: the strips'
  // surface points; planar: the plane's cosine everywhere, so no spread).
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest, previous = 0.0;
  for (std::size_t i = 1; i < strips.size(); ++i) {
    const double ds = strips[i].s_m - strips[i - 1].s_m;
    if (!(std::abs(ds) > 0.0)) continue;
    const double alpha = std::acos(std::min(std::abs((strips[i].y_rail_m - strips[i - 1].y_rail_m) / ds), 1.0));
    if (i > 1) shape.max_turn_per_strip_rad = std::max(shape.max_turn_per_strip_rad, std::abs(alpha - previous));
    previous = alpha;
    lowest = std::min(lowest, alpha);
    highest = std::max(highest, alpha);
  }
  if (highest >= lowest) shape.angle_spread_rad = highest - lowest;
  return shape;
}

}  // namespace ctab::gen
