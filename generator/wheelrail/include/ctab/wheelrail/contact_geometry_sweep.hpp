// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Rigid contact geometry versus lateral shift for a wheelset (both sides), contact-point jumps, and the
//! equivalent conicity after EN 15302.
//!
//! Equivalent conicity: with dr(y) = r_right - r_left the kinematic oscillation of a free wheelset obeys
//! y'' = -dr(y)/(2 e0 r0) (x the distance along the track); its wavelength lambda at amplitude y_hat gives
//! tan(gamma_e) = (2 pi/lambda)^2 e0 r0, independent of e0 r0. The quarter wavelength is the integral
//! int_0^y_hat du / sqrt(2 (V(y_hat) - V(u))), V(u) = int_0^u dr/2 (e0 r0 = 1), computed with u = y_hat sin(theta)
//! by Gauss-Legendre. Linear dr = 2 gamma y gives gamma exactly. Assumes mirror-image sides (dr odd).
#include <string>
#include <vector>

#include "ctab/wheelrail/wheelrail_geometry.hpp"

namespace ctab::gen {

enum class ContactMode { SingleWheel, Wheelset };

struct RigidContactRow {
  double dy_m = 0.0;
  double roll_rad = 0.0;
  GapMinimum right, left;                    //!< first contact of each wheel (left in its own mirrored frame)
  double rolling_radius_difference_m = 0.0;  //!< r_right - r_left [m]
  bool converged = true;                     //!< false when the roll iteration failed or a wheel is off its rail
  std::string detail;                        //!< empty when converged; otherwise why not, in words
};

//! Rigid contact at one shift; in single-wheel mode roll = 0 and each wheel is lowered on its own.
[[nodiscard]] RigidContactRow rigid_contact(const SideGeometry& right, const SideGeometry& left, double dy_m,
                                            ContactMode mode);

//! A discontinuity of the contact position between two neighbouring shifts.
struct ContactJump {
  double dy_before_m = 0.0, dy_after_m = 0.0;  //!< the shifts on either side [m]
  double y_wheel_before_m = 0.0, y_wheel_after_m = 0.0;
  bool right_side = true;
};

//! Jumps: the wheel contact position moves by more than `threshold_m` between neighbouring rows.
[[nodiscard]] std::vector<ContactJump> find_contact_jumps(const std::vector<RigidContactRow>& rows, double threshold_m);

//! EN 15302 equivalent conicity at amplitude y_hat [m] from dr(y) sampled on a uniform grid y >= 0
//! (dy_m[0] = 0). Returns NaN if the grid does not reach y_hat or dr does not restore.
[[nodiscard]] double equivalent_conicity(const std::vector<double>& dy_m, const std::vector<double>& delta_r_m,
                                         double amplitude_m);

}  // namespace ctab::gen
