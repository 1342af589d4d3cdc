// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Wheel and rail profiles as functions z(y) in CONTACT's canonical form, SI units:
//! y lateral [m], positive towards the field side; z [m] positive downwards (rail: depth below the top of the
//! rail; wheel: radius increase F(S) relative to the tape circle, so "down" when standing on the rail).
//!
//! Every profile, analytic or measured, is first a parametric curve (ProfileCurve, monotone in y) and is then
//! tabulated on a uniform lateral grid (ProfileTable) with z, dz/dy and d2z/dy2 at each node: evaluation is a
//! cubic Hermite interpolation of z (exact slopes at the nodes) and a linear one of d2z/dy2.
#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ctab::gen {

//! A point of a parametric plane curve with first and second derivatives in the parameter t.
struct CurvePoint {
  double y = 0.0, z = 0.0;      //!< position [m]
  double dy = 0.0, dz = 0.0;    //!< d/dt
  double d2y = 0.0, d2z = 0.0;  //!< d2/dt2
};

//! A plane curve y(t), z(t) with y strictly increasing in t on [t_begin, t_end].
class ProfileCurve {
 public:
  virtual ~ProfileCurve() = default;
  [[nodiscard]] virtual double t_begin() const = 0;
  [[nodiscard]] virtual double t_end() const = 0;
  [[nodiscard]] virtual CurvePoint at(double t) const = 0;
};

//! The curve rotated about the origin by angle [rad] (positive turns +y towards +z) and then shifted.
class TransformedCurve final : public ProfileCurve {
 public:
  TransformedCurve(std::shared_ptr<const ProfileCurve> base, double angle_rad, double shift_y_m, double shift_z_m);
  [[nodiscard]] double t_begin() const override { return base_->t_begin(); }
  [[nodiscard]] double t_end() const override { return base_->t_end(); }
  [[nodiscard]] CurvePoint at(double t) const override;

 private:
  std::shared_ptr<const ProfileCurve> base_;
  double cos_, sin_, shift_y_, shift_z_;
};

//! Value, slope and second derivative of a profile at one lateral position.
struct ProfilePoint {
  double z = 0.0;                          //!< [m]
  double dz = 0.0;                         //!< dz/dy [-]
  double d2z = 0.0;                        //!< d2z/dy2 [1/m]
  [[nodiscard]] double curvature() const;  //!< signed curvature d2z/(1+dz^2)^(3/2) [1/m]; > 0 concave seen from -z
};

//! A profile tabulated on a uniform lateral grid.
class ProfileTable {
 public:
  ProfileTable() = default;
  //! Samples the curve every `step_m` over its y-range (inverting y(t) by safeguarded Newton).
  ProfileTable(const ProfileCurve& curve, double step_m, std::string name);

  [[nodiscard]] double y_min() const noexcept { return y0_; }
  [[nodiscard]] double y_max() const noexcept { return y0_ + step_ * static_cast<double>(z_.size() - 1); }
  [[nodiscard]] double step() const noexcept { return step_; }
  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  [[nodiscard]] bool contains(double y) const noexcept { return y >= y_min() && y <= y_max(); }
  //! Evaluates at y (clamped to the table range).
  [[nodiscard]] ProfilePoint at(double y) const noexcept;
  //! z alone (the contact search's inner loop), the same cubic as at().
  [[nodiscard]] double z_at(double y) const noexcept {
    const double u = std::clamp((y - y0_) * inverse_step_, 0.0, static_cast<double>(z_.size() - 1));
    const auto k = std::min(static_cast<std::size_t>(u), z_.size() - 2);
    const double s = u - static_cast<double>(k), s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * z_[k] + (s3 - 2 * s2 + s) * dz_[k] * step_ + (-2 * s3 + 3 * s2) * z_[k + 1] +
           (s3 - s2) * dz_[k + 1] * step_;
  }
  //! Lowest y at which z reaches `depth` (the gauge face for a rail measured from its top), if any.
  [[nodiscard]] bool first_y_at_depth(double depth_m, double& y_out) const noexcept;
  //! The tabulated z values (provenance hashing).
  [[nodiscard]] const std::vector<double>& z_samples() const noexcept { return z_; }
  //! Highest point (smallest z) of the profile: {y, z}.
  [[nodiscard]] std::pair<double, double> highest_point() const noexcept;
  //! Largest |dz/dy| and |d2z/dy2| of the interpolating cubic (what z_at evaluates) over the whole table:
  //! exact bounds for the gap scans' error estimates (wheelrail first_contact_tracker).
  struct DerivativeBounds {
    double slope = 0.0;                                    //!< max |dz/dy| [-]
    double second_derivative = 0.0;                        //!< max |d2z/dy2| [1/m]
    double slope_low = 0.0;                                //!< min dz/dy (signed) [-]
    double slope_high = 0.0;                               //!< max dz/dy (signed) [-]
    void include(const DerivativeBounds& other) noexcept;  //!< bounds of both
  };
  [[nodiscard]] DerivativeBounds derivative_bounds() const;
  //! The same for each interval between neighbouring nodes (interval k: [y_min + k step, y_min + (k + 1) step]).
  [[nodiscard]] std::vector<DerivativeBounds> interval_derivative_bounds() const;

 private:
  std::string name_;
  double y0_ = 0.0, step_ = 1.0;
  double inverse_step_ = 1.0;  // 1 / step_: at() and z_at() multiply (two divisions a call took ~30 % of at())
  std::vector<double> z_, dz_, d2z_;
};

}  // namespace ctab::gen
