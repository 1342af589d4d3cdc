// SPDX-License-Identifier: Apache-2.0
#include "gap_scan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ctab::gen::gap_scan {

Pose::Pose(double dy, double roll) : dy_m(dy), roll_rad(roll), cos_roll(std::cos(roll)), sin_roll(std::sin(roll)) {}

Grid make_grid(const SideGeometry& side, const Pose& pose) {
  Grid grid;
  side.overlap(pose.dy_m, pose.roll_rad, grid.s_begin, grid.s_end);
  // No overlap (the wheel lies beside the rail: the clipped range collapses onto one end): no grid at all.
  if (side.wheel_point(grid.s_begin, pose.dy_m, pose.roll_rad).rail_y_m > side.rail().y_max() ||
      side.wheel_point(grid.s_end, pose.dy_m, pose.roll_rad).rail_y_m < side.rail().y_min())
    return grid;
  grid.count = static_cast<std::size_t>((grid.s_end - grid.s_begin) / SideGeometry::kScanStep_m) + 1;
  grid.step = (grid.s_end - grid.s_begin) / static_cast<double>(std::max<std::size_t>(grid.count - 1, 1));
  return grid;
}

double rail_y(const SideGeometry& side, const Pose& pose, double s) {
  return pose.dy_m + (side.wheel_origin_y_m() + s) * pose.cos_roll -
         (side.track().nominal_radius_m + side.wheel().z_at(s)) * pose.sin_roll - side.rail_origin_y_m();
}

void scan(const SideGeometry& side, const Pose& pose, const Grid& grid, std::size_t first, std::size_t last,
          std::vector<CoarseMinimum>& out, std::vector<double>* values) {
  double previous2 = 0, previous = 0;
  for (std::size_t k = first; k <= last && k < grid.count; ++k) {
    const double g = side.gap_rotated(grid.s(k), pose.dy_m, pose.cos_roll, pose.sin_roll);
    if (values != nullptr) values->push_back(g);
    const bool one_before = k >= first + 1 || first == 0;  // as the whole scan, whose "previous" starts at 0
    const bool interior_minimum = k >= first + 2 && previous < previous2 && previous <= g;
    const bool end_minimum =
        (k == 1 && first == 0 && previous <= g) || (k + 1 == grid.count && one_before && g < previous);
    if (interior_minimum || end_minimum) {
      const std::size_t at = interior_minimum || k == 1 ? k - 1 : k;
      out.push_back({grid.s(at), interior_minimum || k == 1 ? previous : g});
    }
    previous2 = previous;
    previous = g;
  }
}

double refine(const SideGeometry& side, const Pose& pose, const Grid& grid, double centre) {
  double lo = std::max(grid.s_begin, centre - grid.step), hi = std::min(grid.s_end, centre + grid.step);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0), c = pose.cos_roll, sn = pose.sin_roll, dy = pose.dy_m;
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = side.gap_rotated(x1, dy, c, sn), f2 = side.gap_rotated(x2, dy, c, sn);
  for (int i = 0; i < 48 && hi - lo > 1e-10; ++i) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = side.gap_rotated(x1, dy, c, sn);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = side.gap_rotated(x2, dy, c, sn);
    }
  }
  return 0.5 * (lo + hi);
}

double RefinedPair::lowest() const noexcept {
  if (count == 0) return std::numeric_limits<double>::quiet_NaN();
  return std::min(std::min(std::numeric_limits<double>::infinity(), first), second);
}

RefinedPair refine_two_lowest(const SideGeometry& side, const Pose& pose, const Grid& grid,
                              std::vector<CoarseMinimum>& coarse) {
  RefinedPair pair;
  pair.count = std::min<std::size_t>(2, coarse.size());
  pair.second = std::numeric_limits<double>::infinity();
  std::partial_sort(coarse.begin(), coarse.begin() + static_cast<std::ptrdiff_t>(pair.count), coarse.end(),
                    [](const CoarseMinimum& a, const CoarseMinimum& b) { return a.gap < b.gap; });
  for (std::size_t k = 0; k < pair.count; ++k)
    (k == 0 ? pair.first : pair.second) =
        side.gap_rotated(refine(side, pose, grid, coarse[k].s), pose.dy_m, pose.cos_roll, pose.sin_roll);
  return pair;
}

}  // namespace ctab::gen::gap_scan
