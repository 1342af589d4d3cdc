// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Rigid wheel-rail geometry of one side of a wheelset on tangent track (Manchester benchmark conventions).
//!
//! Frames (SI, z down): track y towards the right rail; each side is handled in its own canonical frame with y
//! towards that side's field side (the left side mirrored), where the wheelset's lateral shift is +dy for the
//! right side and -dy for the left, and its roll +phi / -phi. Wheelset-local: a wheel profile point at S sits at
//! y_l = FBDIST/2 - FBPOS + S (750 mm + S for the benchmark), z_l = r_nom + F(S) below the axle; in the track frame
//! y = dy + y_l cos(phi) - z_l sin(phi), z = z_ws + y_l sin(phi) + z_l cos(phi) (negative phi lifts the right wheel).
//! The rail's profile origin sits at y = gauge/2 - y_g, where y_g is the gauge point: the first point of the rail
//! profile (from the track centre) that is `gauge_height` below the top; z = 0 is the plane on the rail tops.
//! Vertical gap at S: g(S) = z_rail(y_rail(S)) - z_wheel(S); the wheel touches when min g = 0.
#include <cmath>
#include <string>
#include <vector>

#include "ctab/profiles/profile.hpp"

namespace ctab::gen {

//! Track and wheelset parameters (Manchester benchmark defaults).
struct TrackSetup {
  double gauge_m = 1.435;                  //!< track gauge [m]
  double gauge_height_m = 0.014;           //!< gauge measured this far below the top of the rails [m]
  double flange_back_distance_m = 1.360;   //!< inner faces of the wheels [m]
  double flange_back_position_m = -0.070;  //!< S of the flange back in the wheel profile [m]
  double nominal_radius_m = 0.460;         //!< rolling radius at S = 0 [m]
};

//! One local minimum of the vertical gap: a contact point or a near miss.
struct GapMinimum {
  double wheel_s_m = 0.0;          //!< S on the wheel profile [m]
  double rail_y_m = 0.0;           //!< y on the rail profile [m]
  double gap_m = 0.0;              //!< vertical gap at the rigid position (0 for the first contact) [m]
  double contact_angle_rad = 0.0;  //!< rail surface inclination there (negative on the gauge side) [rad]
  double rolling_radius_m = 0.0;   //!< distance from the axle, r_nom + F(S) [m]
};

//! The wheel surface point at S in the side frame with z_ws = 0, and its rail coordinate.
struct WheelSurfacePoint {
  double rail_y_m = 0.0;  //!< lateral position in rail coordinates [m]
  double z_m = 0.0;       //!< height (down) in the track frame, z_ws = 0 [m]
  double slope = 0.0;     //!< dz/dy of the wheel surface in the track frame [-]
  double radius_m = 0.0;  //!< r_nom + F(S) [m]
  ProfilePoint profile;   //!< the wheel profile at S (its own frame)
  //! Signed curvature of the wheel surface (as ProfilePoint::curvature, invariant under the rigid motion) [1/m]; on
  //! demand: the contact searches' Newton steps evaluate many wheel points and need it at few.
  [[nodiscard]] double curvature() const { return profile.curvature(); }
};

//! Derivative bounds of a profile's cubic per block of kBlock intervals, for range queries (the gap scans' error
//! bounds, FirstContactTracker).
class DerivativeBlocks {
 public:
  static constexpr std::size_t kBlock = 16;
  DerivativeBlocks() = default;
  explicit DerivativeBlocks(const ProfileTable& profile);
  //! Bounds over [y_lo, y_hi] (rounded out to whole blocks); the whole profile's when the range leaves it.
  [[nodiscard]] ProfileTable::DerivativeBounds between(double y_lo, double y_hi) const noexcept;
  [[nodiscard]] const ProfileTable::DerivativeBounds& all() const noexcept { return all_; }

 private:
  double y_min_ = 0.0, y_max_ = 0.0, block_m_ = 1.0;
  ProfileTable::DerivativeBounds all_;
  std::vector<ProfileTable::DerivativeBounds> blocks_;
};

class SideGeometry {
 public:
  //! Places the profiles (validated tables) on the track; throws InputError if the rail has no gauge point.
  SideGeometry(const ProfileTable& wheel, const ProfileTable& rail, const TrackSetup& track);

  [[nodiscard]] WheelSurfacePoint wheel_point(double s_m, double dy_m, double roll_rad) const noexcept;
  //! The same with the roll's cosine and sine given (a caller that evaluates many points at one roll).
  [[nodiscard]] WheelSurfacePoint wheel_point(double s_m, double dy_m, double cos_roll, double sin_roll) const noexcept;
  //! Vertical gap at S for z_ws = 0 (so that min over S is the z_ws of first contact).
  [[nodiscard]] double gap(double s_m, double dy_m, double roll_rad) const noexcept {
    return gap_rotated(s_m, dy_m, std::cos(roll_rad), std::sin(roll_rad));
  }
  //! The same with the roll given by its cosine and sine (scan loops compute them once).
  [[nodiscard]] double gap_rotated(double s_m, double dy_m, double cos_roll, double sin_roll) const noexcept {
    const double yl = wheel_origin_y_ + s_m, zl = track_.nominal_radius_m + wheel_->z_at(s_m);
    return rail_->z_at(dy_m + yl * cos_roll - zl * sin_roll - rail_origin_y_) - (yl * sin_roll + zl * cos_roll);
  }
  //! All local minima of the gap over the overlapping range, the deepest first; gaps relative to the deepest.
  //! `first_contact_z_m` receives the z_ws at which the wheel touches. Scratch-free apart from the output.
  void gap_minima(double dy_m, double roll_rad, std::vector<GapMinimum>& minima, double& first_contact_z_m) const;
  //! Only the z_ws of first contact (the two lowest coarse minima refined): the roll iteration's function.
  [[nodiscard]] double first_contact_height(double dy_m, double roll_rad) const;
  //! Wheel profile range that lies over the rail for this shift and roll [m].
  void overlap(double dy_m, double roll_rad, double& s_begin, double& s_end) const noexcept;

  [[nodiscard]] const ProfileTable& wheel() const noexcept { return *wheel_; }
  [[nodiscard]] const ProfileTable& rail() const noexcept { return *rail_; }
  [[nodiscard]] const TrackSetup& track() const noexcept { return track_; }
  [[nodiscard]] double rail_origin_y_m() const noexcept { return rail_origin_y_; }
  [[nodiscard]] double wheel_origin_y_m() const noexcept { return wheel_origin_y_; }
  //! Derivative bounds of the rail's and the wheel's interpolating cubics (the gap scans' error estimates).
  [[nodiscard]] const DerivativeBlocks& rail_bounds() const noexcept { return rail_bounds_; }
  [[nodiscard]] const DerivativeBlocks& wheel_bounds() const noexcept { return wheel_bounds_; }
  //! Largest distance of a wheel profile point from the axle centre, sqrt(y_l^2 + z_l^2) [m].
  [[nodiscard]] double largest_lever_m() const noexcept { return largest_lever_m_; }

  static constexpr double kScanStep_m = 0.1e-3;  //!< coarse scan step before refining minima

 private:
  const ProfileTable* wheel_;
  const ProfileTable* rail_;
  TrackSetup track_;
  double rail_origin_y_ = 0.0;   // lateral track position of the rail profile origin [m]
  double wheel_origin_y_ = 0.0;  // wheelset-local lateral position of S = 0 [m]
  DerivativeBlocks rail_bounds_, wheel_bounds_;
  double largest_lever_m_ = 0.0;
};

//! Rigid wheelset state for one lateral shift.
struct WheelsetPose {
  double dy_m = 0.0;       //!< lateral shift [m]
  double roll_rad = 0.0;   //!< roll angle [rad] (0 in single-wheel mode)
  double z_right_m = 0.0;  //!< z_ws at first contact of the right wheel [m]
  double z_left_m = 0.0;   //!< the same for the left wheel [m]
  bool converged = true;
  std::string detail;  //!< empty when converged; otherwise why not, in words (names dy)
};

//! A neighbouring shift's roll, to start the roll search from.
struct RollGuess {
  double roll_rad = 0.0;    //!< expected roll [rad]
  double spread_rad = 0.0;  //!< expected error of roll_rad [rad] (the first bracket's half width, at least 1e-7)
};

//! Roll angle at which both wheels touch at the same z_ws (rigid wheelset), by a safeguarded root finder. The
//! result is the point of a fixed lattice (kRollLattice_rad) nearest the root, so it does not depend on where the
//! search starts: `guess` (a neighbouring shift's roll) only makes it faster, and the roll is bit for bit the same
//! with or without one.
[[nodiscard]] WheelsetPose rigid_wheelset_pose(const SideGeometry& right, const SideGeometry& left, double dy_m,
                                               const RollGuess* guess = nullptr);

//! Spacing of the roll lattice [rad]: 2^-44 (5.7e-14 rad), below the roll tolerance (1e-13 rad).
inline constexpr double kRollLattice_rad = 0x1p-44;

}  // namespace ctab::gen
