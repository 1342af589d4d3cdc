// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Sampling one patch's strip problem (internal to ctab::wheelrail): the separation h(s) of rail and wheel, the
//! curvatures A(s), B(s), the rail points and normals, on the plane tangent to the rail at the reference point
//! (planar) or on CONTACT's conformal surface midway between rail and wheel (docs/method.md "Contact surface").
#include <cmath>
#include <limits>
#include <vector>

#include "ctab/contact/grid_alignment.hpp"
#include "ctab/profiles/profile.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"
#include "ctab/wheelrail/wheelrail_options.hpp"
#include "patch_problem.hpp"

namespace ctab::gen {

//! A line in the side frame through (y, z) (rail y, track z) along the normal of inclination angle: the points
//! (y - n sin, z + n cos), n > 0 into the rail.
struct NormalLine {
  double y = 0, z = 0, c = 1, sn = 0;
};

//! Samples patch problems of one side at one lateral shift and roll.
class PatchBuilder {
 public:
  PatchBuilder(const SideGeometry& side, double dy, double roll, double z_first, ContactSurface surface,
               GridAlignment strips)
      : side_(side), dy_(dy), cos_roll_(std::cos(roll)), sin_roll_(std::sin(roll)), z_first_(z_first),
        surface_(surface), strips_(strips) {}
  //! z_ws of first contact: the wheel is placed touching the rail.
  void set_first_contact_height(double z_first) { z_first_ = z_first; }

  //! Wheel surface (touching position) at rail coordinate y: Newton on S from s_guess (updated).
  WheelSurfacePoint wheel_at(double y, double& s_guess) const;

  //! Samples h(s) outward from the reference point while h < depth, with the wheel lowered by p.gap_dz; false if
  //! fewer than tuning::kMinPatchSamples.
  bool build(PatchProblem& p, double depth, double step) const;

 private:
  struct Sample {
    double s = 0, h = 0, y_rail = 0, A = 0, B = 0, angle = 0, weight = 1;
  };
  // State carried from sample to sample along one side: Newton guesses and, conformal, the last surface point.
  struct SampleState {
    double n_rail = 0, n_wheel = 0, s_guess = 0;
    NormalLine line;         // conformal: the last sample's normal through its surface point
    double s = 0;            // conformal: its arc length
    double s_at_y = 0;       // conformal: the wheel parameter at the surface point's own y (midway's Newton guess)
    double turn = 0;         // conformal: how far the normal turned from the sample before to the last one [rad]
    double turn_before = 0;  // conformal: the same one sample earlier [rad]
    int turns = 0;           // conformal: samples with a turn so far
    double rail_slope = 0;   // the rail's slope dz/dy where the last intersection met it [-]
    double angle = 0;        // conformal: the inclination of line's normal, atan2(line.sn, line.c) [rad]
    // conformal: the rail at the last surface point's own y (midway), for the sample's strip geometry
    ProfilePoint rail_at_point;
    double rail_at_point_y = std::numeric_limits<double>::quiet_NaN();
  };

  static std::vector<std::vector<double>*> columns(PatchProblem& p);
  static void clear(PatchProblem& p);
  void sample_side(PatchProblem& p, int direction, double depth, double step) const;
  bool planar_sample(const PatchProblem& p, double s, SampleState& state, Sample& out) const;
  static void start_arc_length_at_origin(PatchProblem& p);
  bool conformal_sample(const PatchProblem& p, double ds, SampleState& state, Sample& out) const;
  bool centre_on_surface(const PatchProblem& p, SampleState& state) const;
  bool settle_midway(NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w, double& last_turn) const;
  static double next_move(const NormalLine& line, const SampleState& state, const WheelSurfacePoint& w, double turn);
  static void turn_intersections(const NormalLine& line, SampleState& state, const WheelSurfacePoint& w, double theta);
  static double relative_slope(const NormalLine& line, double slope);
  bool midway(NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w, double& moved) const;
  void fill_strip_geometry(const WheelSurfacePoint& w, const SampleState& state, const NormalLine& line,
                           Sample& out) const;
  bool intersect(const NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w) const;
  bool intersect_rail(const NormalLine& line, double& n_rail, double& slope) const;
  bool intersect_wheel(const NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w) const;

  const SideGeometry& side_;
  double dy_, cos_roll_, sin_roll_, z_first_;
  ContactSurface surface_;
  GridAlignment strips_;
};

}  // namespace ctab::gen
