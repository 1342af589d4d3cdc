// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The z_ws of first contact of one side at one lateral shift for a sequence of nearby roll angles (the roll
//! search's function), cheaper than SideGeometry::first_contact_height and bit for bit equal to it.
//!
//! A full coarse scan (every 0.1 mm of the overlap) gives the gap minima; the next rolls re-scan only windows of
//! the same grid around them and around the overlap's ends. The windows find every grid minimum within the window
//! half width W of a known one; a minimum elsewhere (a contact jump) is excluded by a bound relative to the
//! reference point s_r (the reference scan's lowest grid minimum, re-evaluated at each roll). On each chunk of the
//! reference scan (roll phi0, step h0) outside the windows, at roll phi
//!   g(s) - g(s_r) >= min over the chunk of g(phi0) - (h0^2/8) max|g''| - g(s_r; phi0) - R |phi - phi0|,
//! the middle term bounding the gap between grid points, and R bounding |d(g(s) - g(s_r))/dphi| <=
//! |z_r'(y) - z_r'(y_r)| L + |z_r'(y_r)| d (|sin| + max|F'|) + d (1 + max|F'| |sin|), where L = max sqrt(y_l^2 + z_l^2)
//! and d = |s - s_r| (g = z_r(y(s)) - z_w(s); dy/dphi = -y_l sin - z_l cos, dz_w/dphi = y_l cos - z_l sin);
//! max|g''| <= max|z_r''| (1 + max|F'| |sin|)^2 + max|F''| (1 + max|z_r'| |sin|). The profiles' bounds are those of
//! their cubics over the chunk (DerivativeBlocks; the gauge face's slope of 40 must not count on the tread). When
//! the windows' two lowest minima lie below the least of these the full scan would refine the same two and return
//! the same value; otherwise (near a contact jump, or a roll farther than kMaxWindowRoll_rad from the reference)
//! the tracker scans in full and takes that scan as its new reference.
#include <cstddef>
#include <vector>

#include "ctab/wheelrail/wheelrail_geometry.hpp"

namespace ctab::gen {

class FirstContactTracker {
 public:
  FirstContactTracker(const SideGeometry& side, double dy_m) : side_(&side), dy_m_(dy_m) {}

  //! side.first_contact_height(dy_m, roll_rad), bit for bit (NaN when the wheel does not reach the rail).
  [[nodiscard]] double height(double roll_rad);

  [[nodiscard]] int full_scans() const noexcept { return full_scans_; }      //!< whole-grid scans so far
  [[nodiscard]] int window_scans() const noexcept { return window_scans_; }  //!< windowed scans accepted so far

  static constexpr std::size_t kWindowSteps = 20;     //!< window half width W in scan steps (2 mm; chosen)
  static constexpr double kMaxWindowRoll_rad = 2e-4;  //!< farthest roll from the reference scan's (chosen)

 private:
  [[nodiscard]] double full_scan(double roll_rad);
  [[nodiscard]] bool window_scan(double roll_rad, double& height);

  const SideGeometry* side_;
  double dy_m_;
  int full_scans_ = 0, window_scans_ = 0;
  bool has_reference_ = false;
  double reference_roll_ = 0.0, reference_s_begin_ = 0.0, reference_s_end_ = 0.0, reference_step_ = 0.0;
  // Lower bounds of g(s) - g(s_r) for grid minima outside the windows, as grid values (coarse) and refined, at the
  // reference roll and kMaxWindowRoll_rad from it (concave in |phi - phi0|: the chord bounds them in between) [m].
  double reference_s_ = 0.0;
  double coarse_at_reference_ = 0.0, coarse_at_max_roll_ = 0.0, refined_at_reference_ = 0.0, refined_at_max_roll_ = 0.0;
  std::vector<double> centres_;  // S of the reference scan's minima [m]
};

}  // namespace ctab::gen
