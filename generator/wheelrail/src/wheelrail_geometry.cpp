#include "ctab/wheelrail/wheelrail_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "ctab/contact/error.hpp"
#include "ctab/contact/root_finding.hpp"

namespace ctab::gen {

SideGeometry::SideGeometry(const ProfileTable& wheel, const ProfileTable& rail, const TrackSetup& track)
    : wheel_(&wheel), rail_(&rail), track_(track) {
  double gauge_point = 0.0;
  if (!rail.first_y_at_depth(track.gauge_height_m, gauge_point))
    throw InputError(rail.name(), 0,
                     "rail profile does not reach the gauge height " + std::to_string(track.gauge_height_m * 1e3) +
                         " mm below its top");
  rail_origin_y_ = 0.5 * track.gauge_m - gauge_point;
  wheel_origin_y_ = 0.5 * track.flange_back_distance_m - track.flange_back_position_m;
}

WheelSurfacePoint SideGeometry::wheel_point(double s_m, double dy_m, double roll_rad) const noexcept {
  const ProfilePoint f = wheel_->at(s_m);
  const double c = std::cos(roll_rad), sn = std::sin(roll_rad);
  const double yl = wheel_origin_y_ + s_m, zl = track_.nominal_radius_m + f.z;
  WheelSurfacePoint p;
  p.rail_y_m = dy_m + yl * c - zl * sn - rail_origin_y_;
  p.z_m = yl * sn + zl * c;
  const double dy_ds = c - f.dz * sn, dz_ds = sn + f.dz * c;
  p.slope = dz_ds / dy_ds;
  p.curvature = f.curvature();  // invariant under the rigid motion
  p.radius_m = zl;
  return p;
}

void SideGeometry::overlap(double dy_m, double roll_rad, double& s_begin, double& s_end) const noexcept {
  // y_rail(S) is increasing in S; clip the wheel range to the rail table by bisection.
  auto inside_from = [&](double lo, double hi, bool lower_end) {
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      const double y = wheel_point(mid, dy_m, roll_rad).rail_y_m;
      const bool inside = lower_end ? y >= rail_->y_min() : y <= rail_->y_max();
      (inside == lower_end ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
  };
  s_begin = wheel_->y_min();
  s_end = wheel_->y_max();
  if (wheel_point(s_begin, dy_m, roll_rad).rail_y_m < rail_->y_min()) s_begin = inside_from(s_begin, s_end, true);
  if (wheel_point(s_end, dy_m, roll_rad).rail_y_m > rail_->y_max()) s_end = inside_from(s_begin, s_end, false);
}

namespace {

struct CoarseMinimum {
  double s, gap;
};

}  // namespace

// Coarse scan of the gap on a uniform S grid: local minima (interior and at the ends), unrefined.
static void coarse_minima(const SideGeometry& side, double dy_m, double roll_rad, std::vector<CoarseMinimum>& out,
                          double& step, double& s_begin, double& s_end) {
  out.clear();
  side.overlap(dy_m, roll_rad, s_begin, s_end);
  // No overlap (the wheel lies beside the rail: the clipped range collapses onto one end): no minimum at all.
  if (side.wheel_point(s_begin, dy_m, roll_rad).rail_y_m > side.rail().y_max() ||
      side.wheel_point(s_end, dy_m, roll_rad).rail_y_m < side.rail().y_min())
    return;
  const auto count = static_cast<std::size_t>((s_end - s_begin) / SideGeometry::kScanStep_m) + 1;
  step = (s_end - s_begin) / static_cast<double>(std::max<std::size_t>(count - 1, 1));
  double previous2 = 0, previous = 0;
  const double c = std::cos(roll_rad), sn = std::sin(roll_rad);
  for (std::size_t k = 0; k < count; ++k) {
    const double g = side.gap_rotated(s_begin + step * static_cast<double>(k), dy_m, c, sn);
    const bool interior_minimum = k >= 2 && previous < previous2 && previous <= g;
    const bool end_minimum = (k == 1 && previous <= g) || (k + 1 == count && g < previous);
    if (interior_minimum || end_minimum) {
      const std::size_t at = interior_minimum || k == 1 ? k - 1 : k;
      out.push_back({s_begin + step * static_cast<double>(at), interior_minimum || k == 1 ? previous : g});
    }
    previous2 = previous;
    previous = g;
  }
}

// Golden-section refinement of a coarse minimum on [s - step, s + step] within the overlap; returns S.
static double refine_minimum(const SideGeometry& side, double dy_m, double roll_rad, double centre, double step,
                             double s_begin, double s_end) {
  double lo = std::max(s_begin, centre - step), hi = std::min(s_end, centre + step);
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0), c = std::cos(roll_rad), sn = std::sin(roll_rad);
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = side.gap_rotated(x1, dy_m, c, sn), f2 = side.gap_rotated(x2, dy_m, c, sn);
  for (int i = 0; i < 48 && hi - lo > 1e-10; ++i) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = side.gap_rotated(x1, dy_m, c, sn);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = side.gap_rotated(x2, dy_m, c, sn);
    }
  }
  return 0.5 * (lo + hi);
}

void SideGeometry::gap_minima(double dy_m, double roll_rad, std::vector<GapMinimum>& minima,
                              double& first_contact_z_m) const {
  minima.clear();
  thread_local std::vector<CoarseMinimum> coarse;
  double step = 0, s_begin = 0, s_end = 0;
  coarse_minima(*this, dy_m, roll_rad, coarse, step, s_begin, s_end);
  for (const CoarseMinimum& c : coarse) {
    const double s = refine_minimum(*this, dy_m, roll_rad, c.s, step, s_begin, s_end);
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
  thread_local std::vector<CoarseMinimum> coarse;
  double step = 0, s_begin = 0, s_end = 0;
  coarse_minima(*this, dy_m, roll_rad, coarse, step, s_begin, s_end);
  if (coarse.empty()) return std::numeric_limits<double>::quiet_NaN();
  // The two lowest coarse minima can swap order on refinement (near-conformal tread); refine both.
  std::partial_sort(coarse.begin(),
                    coarse.begin() + std::min<std::ptrdiff_t>(2, static_cast<std::ptrdiff_t>(coarse.size())),
                    coarse.end(), [](const CoarseMinimum& a, const CoarseMinimum& b) { return a.gap < b.gap; });
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < std::min<std::size_t>(2, coarse.size()); ++k)
    lowest =
        std::min(lowest, gap(refine_minimum(*this, dy_m, roll_rad, coarse[k].s, step, s_begin, s_end), dy_m, roll_rad));
  return lowest;
}

namespace {

// Roll iteration (rigid_wheelset_pose): the bracket starts at +-20 mrad (chosen: covers |dy| <= 12 mm on S1002/UIC60,
// measured up to 3 mrad) and doubles up to kRollBracketWidenings times (+-320 mrad, far beyond a wheelset on its
// rails).
constexpr double kInitialRollBracket_rad = 0.02;
constexpr int kRollBracketWidenings = 4;
constexpr double kRollTolerance_rad = 1e-13;
constexpr double kHeightTolerance_m = 1e-12;  // z_ws of the two wheels agree to this
constexpr int kRollIterations = 100;

std::string shift_text(double dy_m) {
  char text[48];
  std::snprintf(text, sizeof text, "dy = %.6g m", dy_m);
  return text;
}

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

}  // namespace

WheelsetPose rigid_wheelset_pose(const SideGeometry& right, const SideGeometry& left, double dy_m) {
  WheelsetPose pose;
  pose.dy_m = dy_m;
  auto heights = [&](double roll, double& z_right, double& z_left) {
    z_right = right.first_contact_height(dy_m, roll);
    z_left = left.first_contact_height(-dy_m, -roll);
  };
  // Both wheels touch when z_ws(right) = z_ws(left); the difference falls monotonically with the roll angle.
  auto mismatch = [&](double roll) {
    double zr = 0, zl = 0;
    heights(roll, zr, zl);
    return zr - zl;
  };
  double lo = -kInitialRollBracket_rad, hi = kInitialRollBracket_rad;
  double f_lo = mismatch(lo), f_hi = mismatch(hi);
  for (int widen = 0; widen < kRollBracketWidenings && (f_lo > 0.0) == (f_hi > 0.0); ++widen) {
    lo *= 2.0;
    hi *= 2.0;
    f_lo = mismatch(lo);
    f_hi = mismatch(hi);
  }
  const RootResult root =
      find_root_bracketed(mismatch, lo, f_lo, hi, f_hi, kRollTolerance_rad, kHeightTolerance_m, kRollIterations);
  pose.converged = root.converged;
  pose.roll_rad = root.x;
  heights(pose.roll_rad, pose.z_right_m, pose.z_left_m);
  if (!pose.converged) pose.detail = roll_failure(dy_m, f_lo, f_hi, hi);
  return pose;
}

}  // namespace ctab::gen
