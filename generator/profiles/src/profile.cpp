// SPDX-License-Identifier: Apache-2.0
#include "ctab/profiles/profile.hpp"

#include <algorithm>
#include <cmath>

#include "ctab/core/error.hpp"

namespace ctab::gen {

TransformedCurve::TransformedCurve(std::shared_ptr<const ProfileCurve> base, double angle_rad, double shift_y_m,
                                   double shift_z_m)
    : base_(std::move(base)), cos_(std::cos(angle_rad)), sin_(std::sin(angle_rad)), shift_y_(shift_y_m),
      shift_z_(shift_z_m) {}

CurvePoint TransformedCurve::at(double t) const {
  const CurvePoint p = base_->at(t);
  CurvePoint q;
  q.y = cos_ * p.y - sin_ * p.z + shift_y_;
  q.z = sin_ * p.y + cos_ * p.z + shift_z_;
  q.dy = cos_ * p.dy - sin_ * p.dz;
  q.dz = sin_ * p.dy + cos_ * p.dz;
  q.d2y = cos_ * p.d2y - sin_ * p.d2z;
  q.d2z = sin_ * p.d2y + cos_ * p.d2z;
  return q;
}

double ProfilePoint::curvature() const {
  const double g = 1.0 + dz * dz;
  return d2z / (g * std::sqrt(g));
}

ProfileTable::ProfileTable(const ProfileCurve& curve, double step_m, std::string name)
    : name_(std::move(name)), step_(step_m), inverse_step_(1.0 / step_m) {
  const double t0 = curve.t_begin(), t1 = curve.t_end();
  const CurvePoint first = curve.at(t0), last = curve.at(t1);
  if (!(last.y > first.y)) throw InputError(name_, 0, "profile must extend in +y");
  y0_ = std::ceil(first.y / step_m) * step_m;
  const auto count = static_cast<std::size_t>(std::floor((last.y - y0_) / step_m)) + 1;
  z_.resize(count);
  dz_.resize(count);
  d2z_.resize(count);
  double t_lo = t0;
  CurvePoint at_lo = first;  // the curve at t_lo: the previous sample's solution
  for (std::size_t k = 0; k < count; ++k) {
    const double y = y0_ + step_m * static_cast<double>(k);
    // Bracket [t_lo, t_hi] with y(t_lo) <= y <= y(t_hi): grow t_hi from the previous solution.
    double lo = t_lo, hi = t1;
    double t = lo;
    CurvePoint p = at_lo;
    bool at_t = true;  // p is the curve at t (not so after a last step too small to evaluate again)
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double f = p.y - y;
      if (std::abs(f) <= 1e-15) break;
      if (f < 0.0) lo = t;
      else hi = t;
      double next = (p.dy > 0.0) ? t - f / p.dy : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      const bool step_too_small = std::abs(next - t) <= 1e-16 * (1.0 + std::abs(t));
      t = next;
      if (step_too_small) {
        at_t = false;
        break;
      }
      p = curve.at(t);
    }
    t_lo = t;
    if (!at_t) p = curve.at(t);
    at_lo = p;
    if (!(p.dy > 0.0))
      throw InputError(name_, 0, "profile is vertical or turns back near y = " + std::to_string(y * 1e3) + " mm");
    const double slope = p.dz / p.dy;
    z_[k] = p.z;
    dz_[k] = slope;
    // d2z/dy2 = (y' z'' - z' y'') / y'^3
    d2z_[k] = (p.dy * p.d2z - p.dz * p.d2y) / (p.dy * p.dy * p.dy);
  }
}

ProfilePoint ProfileTable::at(double y) const noexcept {
  const double u = std::clamp((y - y0_) * inverse_step_, 0.0, static_cast<double>(z_.size() - 1));
  const auto k = std::min(static_cast<std::size_t>(u), z_.size() - 2);
  const double s = u - static_cast<double>(k);
  const double h = step_;
  const double z0 = z_[k], z1 = z_[k + 1], m0 = dz_[k] * h, m1 = dz_[k + 1] * h;
  const double s2 = s * s, s3 = s2 * s;
  ProfilePoint p;
  p.z = (2 * s3 - 3 * s2 + 1) * z0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * z1 + (s3 - s2) * m1;
  p.dz = ((6 * s2 - 6 * s) * z0 + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * z1 + (3 * s2 - 2 * s) * m1) *
         inverse_step_;
  p.d2z = (1 - s) * d2z_[k] + s * d2z_[k + 1];
  return p;
}

bool ProfileTable::first_y_at_depth(double depth_m, double& y_out) const noexcept {
  for (std::size_t k = 0; k + 1 < z_.size(); ++k) {
    if ((z_[k] - depth_m) * (z_[k + 1] - depth_m) > 0.0 || z_[k] == z_[k + 1]) continue;
    if (z_[k] < depth_m && z_[k + 1] < depth_m) continue;
    // Refine on the Hermite cubic by bisection.
    double lo = y0_ + step_ * static_cast<double>(k), hi = lo + step_;
    const bool decreasing = z_[k] > z_[k + 1];
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((at(mid).z > depth_m) == decreasing ? lo : hi) = mid;
    }
    y_out = 0.5 * (lo + hi);
    return true;
  }
  return false;
}

std::pair<double, double> ProfileTable::highest_point() const noexcept {
  const auto k = static_cast<std::size_t>(std::min_element(z_.begin(), z_.end()) - z_.begin());
  return {y0_ + step_ * static_cast<double>(k), z_[k]};
}

std::vector<ProfileTable::DerivativeBounds> ProfileTable::interval_derivative_bounds() const {
  // On each interval the cubic's d2z/dy2 is linear (largest at an end) and its dz/dy quadratic (largest at an end
  // or where d2z/dy2 = 0).
  std::vector<DerivativeBounds> bounds(z_.size() > 1 ? z_.size() - 1 : 0);
  const double h = step_;
  for (std::size_t k = 0; k + 1 < z_.size(); ++k) {
    const double dz = z_[k + 1] - z_[k], m0 = dz_[k] * h, m1 = dz_[k + 1] * h;
    const double second_0 = (6 * dz - 4 * m0 - 2 * m1) / (h * h), second_1 = (-6 * dz + 2 * m0 + 4 * m1) / (h * h);
    DerivativeBounds& b = bounds[k];
    b.second_derivative = std::max(std::abs(second_0), std::abs(second_1));
    b.slope_low = std::min(dz_[k], dz_[k + 1]);
    b.slope_high = std::max(dz_[k], dz_[k + 1]);
    if ((second_0 > 0.0) != (second_1 > 0.0)) {
      const double s = second_0 / (second_0 - second_1);  // where the linear d2z/dy2 vanishes
      const double slope = ((6 * s * s - 6 * s) * -dz + (3 * s * s - 4 * s + 1) * m0 + (3 * s * s - 2 * s) * m1) / h;
      b.slope_low = std::min(b.slope_low, slope);
      b.slope_high = std::max(b.slope_high, slope);
    }
    b.slope = std::max(std::abs(b.slope_low), std::abs(b.slope_high));
  }
  return bounds;
}

void ProfileTable::DerivativeBounds::include(const DerivativeBounds& other) noexcept {
  slope = std::max(slope, other.slope);
  second_derivative = std::max(second_derivative, other.second_derivative);
  slope_low = std::min(slope_low, other.slope_low);
  slope_high = std::max(slope_high, other.slope_high);
}

ProfileTable::DerivativeBounds ProfileTable::derivative_bounds() const {
  const std::vector<DerivativeBounds> intervals = interval_derivative_bounds();
  DerivativeBounds all = intervals.empty() ? DerivativeBounds{} : intervals.front();
  for (const DerivativeBounds& b : intervals) all.include(b);
  return all;
}

}  // namespace ctab::gen
