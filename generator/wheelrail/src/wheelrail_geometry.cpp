// SPDX-License-Identifier: Apache-2.0
#include "ctab/wheelrail/wheelrail_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "ctab/core/error.hpp"
#include "ctab/core/number_text.hpp"
#include "ctab/contact/root_finding.hpp"
#include "ctab/wheelrail/first_contact_tracker.hpp"
#include "gap_scan.hpp"

namespace ctab::gen {

DerivativeBlocks::DerivativeBlocks(const ProfileTable& profile)
    : y_min_(profile.y_min()), y_max_(profile.y_max()), block_m_(profile.step() * kBlock) {
  const std::vector<ProfileTable::DerivativeBounds> intervals = profile.interval_derivative_bounds();
  for (std::size_t k = 0; k < intervals.size(); ++k) {
    if (k % kBlock == 0) blocks_.push_back(intervals[k]);
    blocks_.back().include(intervals[k]);
  }
  if (!blocks_.empty()) all_ = blocks_.front();
  for (const ProfileTable::DerivativeBounds& b : blocks_) all_.include(b);
}

ProfileTable::DerivativeBounds DerivativeBlocks::between(double y_lo, double y_hi) const noexcept {
  if (!(y_lo >= y_min_ && y_hi <= y_max_ && y_lo <= y_hi) || blocks_.empty()) return all_;
  const double last_block = static_cast<double>(blocks_.size() - 1);
  const auto first = static_cast<std::size_t>(std::min(std::floor((y_lo - y_min_) / block_m_), last_block));
  const auto last = static_cast<std::size_t>(std::min(std::floor((y_hi - y_min_) / block_m_), last_block));
  ProfileTable::DerivativeBounds bounds = blocks_[first];
  for (std::size_t b = first + 1; b <= last; ++b) bounds.include(blocks_[b]);
  return bounds;
}

SideGeometry::SideGeometry(const ProfileTable& wheel, const ProfileTable& rail, const TrackSetup& track)
    : wheel_(&wheel), rail_(&rail), track_(track) {
  double gauge_point = 0.0;
  if (!rail.first_y_at_depth(track.gauge_height_m, gauge_point))
    throw InputError(rail.name(), 0,
                     "rail profile does not reach the gauge height " + std::to_string(track.gauge_height_m * 1e3) +
                         " mm below its top");
  rail_origin_y_ = 0.5 * track.gauge_m - gauge_point;
  wheel_origin_y_ = 0.5 * track.flange_back_distance_m - track.flange_back_position_m;
  rail_bounds_ = DerivativeBlocks(rail);
  wheel_bounds_ = DerivativeBlocks(wheel);
  double largest_z = 0.0;
  for (const double z : wheel.z_samples()) largest_z = std::max(largest_z, std::abs(z));
  // Between nodes the cubic exceeds its nodes by at most 2 x (4/27) x slope x step (the Hermite slope basis).
  const double z_l = track.nominal_radius_m + largest_z + wheel_bounds_.all().slope * wheel.step();
  const double y_l = std::max(std::abs(wheel_origin_y_ + wheel.y_min()), std::abs(wheel_origin_y_ + wheel.y_max()));
  largest_lever_m_ = std::hypot(y_l, z_l);
}

WheelSurfacePoint SideGeometry::wheel_point(double s_m, double dy_m, double roll_rad) const noexcept {
  return wheel_point(s_m, dy_m, std::cos(roll_rad), std::sin(roll_rad));
}

WheelSurfacePoint SideGeometry::wheel_point(double s_m, double dy_m, double c, double sn) const noexcept {
  const ProfilePoint f = wheel_->at(s_m);
  const double yl = wheel_origin_y_ + s_m, zl = track_.nominal_radius_m + f.z;
  WheelSurfacePoint p;
  p.rail_y_m = dy_m + yl * c - zl * sn - rail_origin_y_;
  p.z_m = yl * sn + zl * c;
  const double dy_ds = c - f.dz * sn, dz_ds = sn + f.dz * c;
  p.slope = dz_ds / dy_ds;
  p.radius_m = zl;
  p.profile = f;
  return p;
}

void SideGeometry::overlap(double dy_m, double roll_rad, double& s_begin, double& s_end) const noexcept {
  // y_rail(S) is increasing in S; clip the wheel range to the rail table by bisection (until the midpoint equals
  // an end: later steps would change nothing).
  const double c = std::cos(roll_rad), sn = std::sin(roll_rad);
  auto rail_y = [&](double s) {  // wheel_point(s, dy_m, roll_rad).rail_y_m
    return dy_m + (wheel_origin_y_ + s) * c - (track_.nominal_radius_m + wheel_->at(s).z) * sn - rail_origin_y_;
  };
  auto inside_from = [&](double lo, double hi, bool lower_end) {
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      const double y = rail_y(mid);
      const bool inside = lower_end ? y >= rail_->y_min() : y <= rail_->y_max();
      (inside == lower_end ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  };
  s_begin = wheel_->y_min();
  s_end = wheel_->y_max();
  if (rail_y(s_begin) < rail_->y_min()) s_begin = inside_from(s_begin, s_end, true);
  if (rail_y(s_end) > rail_->y_max()) s_end = inside_from(s_begin, s_end, false);
}

void SideGeometry::gap_minima(double dy_m, double roll_rad, std::vector<GapMinimum>& minima,
                              double& first_contact_z_m) const {
  minima.clear();
  thread_local std::vector<gap_scan::CoarseMinimum> coarse;
  coarse.clear();
  const gap_scan::Pose pose(dy_m, roll_rad);
  const gap_scan::Grid grid = gap_scan::make_grid(*this, pose);
  if (grid.count > 0) gap_scan::scan(*this, pose, grid, 0, grid.count - 1, coarse);
  for (const gap_scan::CoarseMinimum& c : coarse) {
    const double s = gap_scan::refine(*this, pose, grid, c.s);
    const WheelSurfacePoint w = wheel_point(s, dy_m, roll_rad);
    const ProfilePoint r = rail_->at(w.rail_y_m);
    minima.push_back({s, w.rail_y_m, r.z - w.z_m, std::atan(r.dz), w.radius_m});
  }
  if (minima.empty()) {
    first_contact_z_m = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  std::sort(minima.begin(), minima.end(), [](const GapMinimum& a, const GapMinimum& b) { return a.gap_m < b.gap_m; });
  first_contact_z_m = minima.front().gap_m;
  for (GapMinimum& m : minima) m.gap_m -= first_contact_z_m;
}

double SideGeometry::first_contact_height(double dy_m, double roll_rad) const {
  thread_local std::vector<gap_scan::CoarseMinimum> coarse;
  coarse.clear();
  const gap_scan::Pose pose(dy_m, roll_rad);
  const gap_scan::Grid grid = gap_scan::make_grid(*this, pose);
  if (grid.count > 0) gap_scan::scan(*this, pose, grid, 0, grid.count - 1, coarse);
  return gap_scan::refine_two_lowest(*this, pose, grid, coarse).lowest();
}

namespace {

// Roll iteration (rigid_wheelset_pose): the bracket starts at +-20 mrad (chosen: covers |dy| <= 12 mm on S1002/UIC60,
// measured up to 3 mrad) and doubles up to kRollBracketWidenings times (+-320 mrad, far beyond a wheelset on its
// rails). From a guess it starts at guess +- spread (at least kMinimumGuessSpread_rad) and moves outward,
// quadrupling, at most kGuessWidenings times before it falls back to the cold bracket.
constexpr double kInitialRollBracket_rad = 0.02;
constexpr int kRollBracketWidenings = 4;
constexpr double kMinimumGuessSpread_rad = 1e-7;
constexpr int kGuessWidenings = 6;
constexpr int kRollIterations = 100;
constexpr int kLatticeSteps = 64;  // the root finder ends within one lattice step; more means it failed

std::string shift_text(double dy_m) { return "dy = " + number_text(dy_m) + " m"; }

// Why the roll iteration failed, in words.
std::string roll_failure(double dy_m, double f_lo, double f_hi, double bracket_rad) {
  if (!std::isfinite(f_lo) || !std::isfinite(f_hi))
    return "wheelset roll: a wheel does not reach its rail at " + shift_text(dy_m) +
           " (lateral shift beyond the profiles)";
  if ((f_lo > 0.0) == (f_hi > 0.0))
    return "wheelset roll: no roll angle within +-" + std::to_string(bracket_rad) + " rad lets both wheels touch at " +
           shift_text(dy_m);
  return "wheelset roll: did not converge in " + std::to_string(kRollIterations) + " steps at " + shift_text(dy_m);
}

bool brackets(double f_lo, double f_hi) {
  return std::isfinite(f_lo) && std::isfinite(f_hi) && (f_lo == 0.0 || f_hi == 0.0 || (f_lo > 0.0) != (f_hi > 0.0));
}

// A bracket from a guess: the mismatch falls with the roll, so both ends positive put the root above, both
// negative below. False when it does not bracket after kGuessWidenings moves (or a wheel leaves its rail).
template <class Mismatch>
bool bracket_from_guess(const RollGuess& guess, Mismatch& mismatch, double& lo, double& f_lo, double& hi,
                        double& f_hi) {
  double width = std::max(guess.spread_rad, kMinimumGuessSpread_rad);
  if (!std::isfinite(guess.roll_rad) || !std::isfinite(width) || !(std::abs(guess.roll_rad) < kInitialRollBracket_rad))
    return false;
  lo = guess.roll_rad - width;
  hi = guess.roll_rad + width;
  f_lo = mismatch(lo);
  f_hi = mismatch(hi);
  for (int move = 0; move < kGuessWidenings && std::isfinite(f_lo) && std::isfinite(f_hi) && !brackets(f_lo, f_hi);
       ++move) {
    width *= 4.0;
    if (f_hi > 0.0) {
      lo = hi;
      f_lo = f_hi;
      hi = lo + width;
      f_hi = mismatch(hi);
    } else {
      hi = lo;
      f_hi = f_lo;
      lo = hi - width;
      f_lo = mismatch(lo);
    }
  }
  return brackets(f_lo, f_hi);
}

// The lattice point nearest the root near `x`: the pair k L, (k + 1) L with mismatch >= 0 at the first and < 0 at
// the second (found by walking from round(x / L)), then the one with the smaller |mismatch| (a tie: the smaller
// |roll|). The choice is a function of the mismatch alone, not of x, and mirrors exactly: roll(-dy) = -roll(dy).
template <class Mismatch>
bool snap_to_lattice(Mismatch& mismatch, double x, double& roll) {
  auto at = [&](long long k) { return mismatch(static_cast<double>(k) * kRollLattice_rad); };
  long long k = std::llround(x / kRollLattice_rad), j = 0;
  double f_k = at(k), f_j = 0.0;
  int steps = 0;
  if (f_k >= 0.0) {
    for (j = k + 1, f_j = at(j); f_j >= 0.0 && ++steps < kLatticeSteps; f_j = at(++j)) {
      k = j;
      f_k = f_j;
    }
  } else {
    for (j = k, f_j = f_k, f_k = at(--k); f_k < 0.0 && ++steps < kLatticeSteps; f_k = at(--k)) {
      j = k;
      f_j = f_k;
    }
  }
  if (!(f_k >= 0.0 && f_j < 0.0)) return false;
  const bool take_k = std::abs(f_k) != std::abs(f_j) ? std::abs(f_k) < std::abs(f_j) : std::llabs(k) < std::llabs(j);
  roll = static_cast<double>(take_k ? k : j) * kRollLattice_rad;
  return true;
}

}  // namespace

WheelsetPose rigid_wheelset_pose(const SideGeometry& right, const SideGeometry& left, double dy_m,
                                 const RollGuess* guess) {
  WheelsetPose pose;
  pose.dy_m = dy_m;
  FirstContactTracker right_heights(right, dy_m), left_heights(left, -dy_m);
  auto heights = [&](double roll, double& z_right, double& z_left) {
    z_right = right_heights.height(roll);
    z_left = left_heights.height(-roll);
  };
  // Both wheels touch when z_ws(right) = z_ws(left); the difference falls monotonically with the roll angle.
  auto mismatch = [&](double roll) {
    double zr = 0, zl = 0;
    heights(roll, zr, zl);
    return zr - zl;
  };
  double lo = 0.0, hi = 0.0, f_lo = 0.0, f_hi = 0.0;
  if (guess == nullptr || !bracket_from_guess(*guess, mismatch, lo, f_lo, hi, f_hi)) {
    lo = -kInitialRollBracket_rad;
    hi = kInitialRollBracket_rad;
    f_lo = mismatch(lo);
    f_hi = mismatch(hi);
    for (int widen = 0; widen < kRollBracketWidenings && (f_lo > 0.0) == (f_hi > 0.0); ++widen) {
      lo *= 2.0;
      hi *= 2.0;
      f_lo = mismatch(lo);
      f_hi = mismatch(hi);
    }
  }
  const RootResult root = find_root_bracketed(mismatch, lo, f_lo, hi, f_hi, kRollLattice_rad, 0.0, kRollIterations);
  pose.converged = root.converged && snap_to_lattice(mismatch, root.x, pose.roll_rad);
  if (!pose.converged) pose.roll_rad = root.x;
  heights(pose.roll_rad, pose.z_right_m, pose.z_left_m);
  if (!pose.converged) pose.detail = roll_failure(dy_m, f_lo, f_hi, hi);
  return pose;
}

}  // namespace ctab::gen
