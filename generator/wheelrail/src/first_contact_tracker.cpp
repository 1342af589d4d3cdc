// SPDX-License-Identifier: Apache-2.0
#include "ctab/wheelrail/first_contact_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gap_scan.hpp"

namespace ctab::gen {

namespace {

using gap_scan::CoarseMinimum;

constexpr double kWindow_m = FirstContactTracker::kWindowSteps * SideGeometry::kScanStep_m;
constexpr double kMaxRoll_rad = FirstContactTracker::kMaxWindowRoll_rad;
constexpr std::size_t kChunkIntervals = 8;  // grid intervals per bound (chosen: 0.8 mm)
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct IndexRange {
  std::size_t first, last;
};

// Grid indices of [s_lo, s_hi], widened to whole grid points and clipped to the grid.
IndexRange indices_covering(const gap_scan::Grid& grid, double s_lo, double s_hi) {
  const double lo = std::floor((s_lo - grid.s_begin) / grid.step), hi = std::ceil((s_hi - grid.s_begin) / grid.step);
  const double last = static_cast<double>(grid.count - 1);
  return {static_cast<std::size_t>(std::clamp(lo, 0.0, last)), static_cast<std::size_t>(std::clamp(hi, 0.0, last))};
}

// Grid points farther than `reach` from every minimum of `centres` (increasing S) and from both ends.
void mark_outside(const gap_scan::Grid& grid, const std::vector<double>& centres, double reach,
                  std::vector<char>& outside) {
  outside.assign(grid.count, 0);
  std::size_t centre = 0;
  for (std::size_t k = 0; k < grid.count; ++k) {
    const double s = grid.s(k);
    if (s - grid.s_begin <= reach || grid.s_end - s <= reach) continue;
    while (centre + 1 < centres.size() && centres[centre + 1] <= s) ++centre;
    const bool near = !centres.empty() && (std::abs(s - centres[centre]) <= reach ||
                                           (centre + 1 < centres.size() && centres[centre + 1] - s <= reach));
    outside[k] = near ? 0 : 1;
  }
}

}  // namespace

double FirstContactTracker::height(double roll_rad) {
  double value = 0.0;
  if (has_reference_ && window_scan(roll_rad, value)) {
    ++window_scans_;
    return value;
  }
  return full_scan(roll_rad);
}

double FirstContactTracker::full_scan(double roll_rad) {
  ++full_scans_;
  thread_local std::vector<CoarseMinimum> coarse;
  thread_local std::vector<double> values;
  thread_local std::vector<char> outside;
  coarse.clear();
  values.clear();
  const gap_scan::Pose pose(dy_m_, roll_rad);
  const gap_scan::Grid grid = gap_scan::make_grid(*side_, pose);
  has_reference_ = false;
  if (grid.count == 0) return gap_scan::RefinedPair{}.lowest();
  gap_scan::scan(*side_, pose, grid, 0, grid.count - 1, coarse, &values);
  if (coarse.empty()) return gap_scan::RefinedPair{}.lowest();
  // The new reference: its minima, and bounds of the gap on the intervals whose both ends lie farther than
  // W - 2 h0 from them and from the ends (any point farther than W from them at a nearby roll lies in one).
  centres_.clear();
  for (const CoarseMinimum& m : coarse) centres_.push_back(m.s);
  const CoarseMinimum lowest_minimum =
      *std::min_element(coarse.begin(), coarse.end(),
                        [](const CoarseMinimum& a, const CoarseMinimum& b) { return a.gap < b.gap; });
  mark_outside(grid, centres_, kWindow_m - 2.0 * grid.step, outside);
  const DerivativeBlocks &rail = side_->rail_bounds(), &wheel = side_->wheel_bounds();
  const double lever = side_->largest_lever_m(), wheel_slope = wheel.all().slope;
  const double shift = lever * kMaxRoll_rad;  // rail y moves at most this much [m]
  const double sn = std::abs(pose.sin_roll) + kMaxRoll_rad;
  const double reference_y = gap_scan::rail_y(*side_, pose, lowest_minimum.s);
  const ProfileTable::DerivativeBounds at_reference = rail.between(reference_y - shift, reference_y + shift);
  const double grid_dip = grid.step * grid.step / 8.0;
  constexpr double kScanDip = SideGeometry::kScanStep_m * SideGeometry::kScanStep_m / 8.0;  // any roll's grid
  coarse_at_reference_ = coarse_at_max_roll_ = refined_at_reference_ = refined_at_max_roll_ = kInfinity;
  for (std::size_t chunk = 0; chunk + 1 < grid.count; chunk += kChunkIntervals) {
    const std::size_t end = std::min(chunk + kChunkIntervals, grid.count - 1);  // intervals chunk..end-1
    double lowest = kInfinity;
    for (std::size_t k = chunk; k < end; ++k)
      if (outside[k] && outside[k + 1]) lowest = std::min({lowest, values[k], values[k + 1]});
    if (lowest == kInfinity) continue;
    const double s0 = grid.s(chunk), s1 = grid.s(end);
    const ProfileTable::DerivativeBounds r =
        rail.between(gap_scan::rail_y(*side_, pose, s0) - shift, gap_scan::rail_y(*side_, pose, s1) + shift);
    const ProfileTable::DerivativeBounds w = wheel.between(s0, s1);
    const double stretch = 1.0 + w.slope * sn;
    const double curvature = r.second_derivative * stretch * stretch + w.second_derivative * (1.0 + r.slope * sn);
    const double d = std::max(std::abs(s0 - lowest_minimum.s), std::abs(s1 - lowest_minimum.s));
    const double slope_change = std::max(r.slope_high - at_reference.slope_low, at_reference.slope_high - r.slope_low);
    const double rate =
        slope_change * lever + at_reference.slope * d * (sn + wheel_slope) + d * (1.0 + wheel_slope * sn);
    const double slack = lowest - grid_dip * curvature - lowest_minimum.gap;
    coarse_at_reference_ = std::min(coarse_at_reference_, slack);
    coarse_at_max_roll_ = std::min(coarse_at_max_roll_, slack - rate * kMaxRoll_rad);
    refined_at_reference_ = std::min(refined_at_reference_, slack - kScanDip * curvature);
    refined_at_max_roll_ = std::min(refined_at_max_roll_, slack - kScanDip * curvature - rate * kMaxRoll_rad);
  }
  reference_roll_ = roll_rad;
  reference_s_ = lowest_minimum.s;
  reference_s_begin_ = grid.s_begin;
  reference_s_end_ = grid.s_end;
  reference_step_ = grid.step;
  has_reference_ = grid.count > 1 && !std::isnan(refined_at_max_roll_) && !std::isnan(coarse_at_max_roll_);
  return gap_scan::refine_two_lowest(*side_, pose, grid, coarse).lowest();
}

bool FirstContactTracker::window_scan(double roll_rad, double& height) {
  const double distance = std::abs(roll_rad - reference_roll_);
  if (!(distance <= kMaxRoll_rad)) return false;
  const gap_scan::Pose pose(dy_m_, roll_rad);
  const gap_scan::Grid grid = gap_scan::make_grid(*side_, pose);
  if (grid.count < 2 || std::abs(grid.s_begin - reference_s_begin_) > reference_step_ ||
      std::abs(grid.s_end - reference_s_end_) > reference_step_)
    return false;
  // The chords of the concave bounds, from the reference point's gap at this roll.
  const double at_reference = side_->gap_rotated(reference_s_, dy_m_, pose.cos_roll, pose.sin_roll);
  const double t = distance / kMaxRoll_rad;
  auto chord = [&](double at_0, double at_max) {
    return at_0 == kInfinity ? kInfinity : at_reference + at_0 + t * (at_max - at_0);
  };
  const double bound = chord(coarse_at_reference_, coarse_at_max_roll_);
  const double refined_bound = chord(refined_at_reference_, refined_at_max_roll_);
  // Index ranges: W + 2 h around each reference minimum and from each end, merged.
  thread_local std::vector<IndexRange> ranges;
  ranges.clear();
  const double margin = kWindow_m + 2.0 * grid.step;
  ranges.push_back(indices_covering(grid, grid.s_begin, grid.s_begin + margin));
  for (const double c : centres_) ranges.push_back(indices_covering(grid, c - margin, c + margin));
  ranges.push_back(indices_covering(grid, grid.s_end - margin, grid.s_end));
  std::sort(ranges.begin(), ranges.end(), [](const IndexRange& a, const IndexRange& b) { return a.first < b.first; });
  std::size_t merged = 0;
  for (std::size_t i = 1; i < ranges.size(); ++i) {
    if (ranges[i].first <= ranges[merged].last + 1) ranges[merged].last = std::max(ranges[merged].last, ranges[i].last);
    else ranges[++merged] = ranges[i];
  }
  ranges.resize(merged + 1);
  thread_local std::vector<CoarseMinimum> coarse;
  coarse.clear();
  for (const IndexRange& r : ranges) gap_scan::scan(*side_, pose, grid, r.first, r.last, coarse);
  if (coarse.empty()) return false;
  const gap_scan::RefinedPair pair = gap_scan::refine_two_lowest(*side_, pose, grid, coarse);
  // Every grid minimum within W of a reference minimum or an end is in `coarse`; any other lies above `bound`,
  // and refined above `refined_bound`. Both picks below `bound`: the full scan picks the same two. Otherwise the
  // lowest's refined gap must beat any other pick.
  const bool same_picks = pair.count == 2 && coarse[1].gap < bound;
  const bool first_wins = pair.first <= pair.second && pair.first < refined_bound;
  if (!(coarse[0].gap < bound) || !(same_picks || first_wins)) return false;
  height = pair.lowest();
  return true;
}

}  // namespace ctab::gen
