// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/resolution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ctab::gen {

bool discretises(ContactMethod method) noexcept { return method != ContactMethod::Hertz; }

namespace {

// Calls `use` with every patch that carries at least kResolvedForceShare of the summed force.
template <class Use>
void for_each_counted_patch(const std::vector<PatchExtent>& patches, Use&& use) {
  double total_N = 0.0;
  for (const PatchExtent& p : patches) total_N += p.force_N;
  for (const PatchExtent& p : patches)
    if (p.force_N >= kResolvedForceShare * total_N && p.force_N > 0.0) use(p);
}

}  // namespace

double min_resolved_strips(const std::vector<PatchExtent>& patches, ContactMethod method,
                           double strip_width_m) noexcept {
  double fewest = std::numeric_limits<double>::infinity();
  for_each_counted_patch(patches, [&](const PatchExtent& p) {
    double extent_m = p.width_m;
    if (method == ContactMethod::Bem2d) extent_m = std::min(extent_m, p.length_m);
    fewest = std::min(fewest, extent_m / strip_width_m);
  });
  return fewest;
}

double smallest_loaded_extent_m(const std::vector<PatchExtent>& patches) noexcept {
  double smallest = std::numeric_limits<double>::infinity();
  for_each_counted_patch(patches, [&](const PatchExtent& p) {
    smallest = std::min({smallest, p.width_m, p.length_m});
  });
  return std::isfinite(smallest) ? smallest : 0.0;
}

std::vector<PatchExtent> patch_extents(const NormalSolution& solution) {
  std::vector<PatchExtent> extents;
  for (const PatchSolution& p : solution.patches)
    extents.push_back(patch_extent(p.y_max_m - p.y_min_m, p.normal_force_N, p.strips));
  return extents;
}

SolveStatus resolution_status(SolveStatus status, ContactMethod method, const std::vector<PatchExtent>& patches,
                              double strip_width_m) noexcept {
  if (status != SolveStatus::Converged || !discretises(method)) return status;
  // a rounding margin: a patch of exactly 8 strips has width 8 * strip width up to the last bits
  const double strips = min_resolved_strips(patches, method, strip_width_m) * (1.0 + 1e-9);
  return strips < kMinResolvedStrips ? SolveStatus::UnderResolved : status;
}

}  // namespace ctab::gen
