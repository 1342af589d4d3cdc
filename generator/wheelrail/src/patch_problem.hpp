// SPDX-License-Identifier: Apache-2.0
#pragma once
//! One contact patch's strip problem (internal to ctab::wheelrail): the sampled separation h(s) with its curvatures,
//! the rail points and normals of the samples, and the patch's MIM-1D solver.
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/core/number_text.hpp"
#include "ctab/contact/normal_solution.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"
#include "ctab/wheelrail/wheelrail_options.hpp"

namespace ctab::gen {

//! Planar: the plane tangent to the rail at the reference point, s along it, every sample's normal the plane's.
//! Conformal: a curved reference surface midway between rail and wheel, s its arc length, every sample with its own
//! normal (normal_angle).
struct PatchProblem {
  GapMinimum reference;
  double angle = 0, c = 1, sn = 0;  // reference angle (rail inclination at the reference point), cos, sin
  double y0 = 0, z0 = 0;            // reference point on the rail (rail y, track z)
  // Conformal: the rail y of the surface point at s = 0, where the strip grid is centred (grid_origin_y); NaN: the
  // reference point's. reference_s: s of the reference point on the surface (0 unless the origin moved).
  double origin_y = std::numeric_limits<double>::quiet_NaN();
  double reference_s = 0;
  // Vertical approach of the wheel beyond first contact at which h was sampled [m] (the wheel lowered by it); h
  // holds the separation there plus gap_dz c, so that the strip solver's approach is gap_dz c at that position.
  double gap_dz = 0;
  double window_depth = 0;           // the window's depth [m] (PatchBuilder::build)
  GapProfile gap;                    // y_m holds s
  std::vector<double> rail_y;        // planar: rail y below each sample; conformal: rail y of the surface point
  std::vector<double> normal_angle;  // each sample's normal (inclination from the vertical, < 0 on the gauge side)
  // Each sample's d(separation)/d(dz), the vertical shift of the wheel seen along its normal: cos(delta_w) /
  // cos(delta_w - alpha) (PatchBuilder::intersect_wheel); for the gap slope (main_patch_strips.hpp).
  std::vector<double> approach_weight;
  std::vector<double> strip_gap_rate;  // scratch: d h_i / d gap_dz at each strip of the solver's grid
  std::vector<double> load_weight;     // scratch: cos of each strip's normal inclination (vertical load weights)
  std::unique_ptr<Mim1dSolver> solver;
  NormalSolution solution;

  [[nodiscard]] double grid_origin_y() const { return std::isnan(origin_y) ? y0 : origin_y; }
  //! Whether rail y lies strictly inside the sampled window (between the first and last samples' rail y).
  [[nodiscard]] bool window_holds(double y) const {
    return rail_y.size() >= 2 && y > rail_y.front() && y < rail_y.back();
  }
};

//! Where the strips lie relative to s = 0: centred on it where the grid is CONTACT's (its rows at s = 0, +-ds, ...:
//! CONTACT's reference rule, and the conformal surface, whose grid is centred on CONTACT's reference point), else
//! edges at it (the planar deepest point).
[[nodiscard]] GridAlignment strip_alignment(const WheelRailOptions& options);

//! Whether two reference points are the same point (every field equal: a patch built at either is the same).
[[nodiscard]] bool same_point(const GapMinimum& a, const GapMinimum& b);

//! Creates the patch's MIM-1D solver, or re-targets the one it already has. Returns an empty string, or why not.
[[nodiscard]] std::string prepare_mim1d_solver(std::unique_ptr<Mim1dSolver>& solver, const GapProfile& gap,
                                               double E_star, const Mim1dOptions& options);

//! Expected normal approach from Hertz with the curvatures at the gap minimum (window sizing only) [m].
[[nodiscard]] double expected_approach(const SideGeometry& side, const GapMinimum& m, double dy, double roll,
                                       double E_star, LoadKind load, double value);

}  // namespace ctab::gen
