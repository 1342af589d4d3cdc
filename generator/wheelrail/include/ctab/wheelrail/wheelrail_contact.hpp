// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Normal contact of one wheel on its rail at a given lateral shift and roll: rigid contact search, strip problems
//! in the inclined contact planes, MIM-1D (or Hertz) per patch, and the loading condition.
//!
//! Patches: the deepest gap minimum opens a patch; its strip problem lives in the plane tangent to the rail at that
//! point (angle delta0): s along the plane, h(s) the separation of rail and wheel along the plane normal,
//! A(s) = cos(delta)/(2 r) with r the wheel's rolling radius there (the radius seen in the contact plane is
//! r/cos(delta)), B(s) = h''/2 from the two profile curvatures. The window grows from s = 0 while h stays below
//! twice the expected approach (at least 50 um; doubled if the contact reaches its end), so close minima (the near-conformal tread, tread and flange
//! root at a shift of 5 mm) fall into the same patch, as CONTACT combines them. A minimum outside every window
//! whose gap the approach closes opens a patch of its own; the rest are near misses, reported with their gaps.
//! Loading: total normal force (sum over patches; the paper's and CONTACT's convention), vertical force
//! (sum of N_i cos alpha_i over the strips), or vertical approach dz of the wheel beyond first contact. h(s) is
//! sampled with the wheel lowered by dz (a prescribed load re-samples it at the solved dz until dz settles), so
//! that each strip sees the vertical shift along its own normal, dz cos(delta_w)/cos(delta_w - alpha) at a wheel
//! surface of inclination delta_w, not a uniform dz cos(delta_ref): the strip solver's scalar approach is
//! dz cos(delta_ref) and the rest is part of h. With several patches the vertical approach is found by a
//! safeguarded root finder. A patch's contact angle is the direction of its resultant normal force (planar: the
//! plane's inclination).
//!
//! Conformal surface (WheelRailOptions::surface, CONTACT's conformal approach D = 4): instead of the plane, a
//! curved surface midway between rail and wheel, marched from the reference point: each surface point lies midway
//! between the two profiles on its own normal, inclined at alpha = the mean of the two profile inclinations there;
//! s is the arc length (0 at the reference point), h the separation along the local normal, A = cos(alpha)/(2 r),
//! B the difference of the two profile curvatures (the surface's own curvature cancels); the strip solver is
//! unchanged (half-space on the unrolled surface). Each strip pushes along its own normal, the contact angle is the
//! direction of the resultant, and the centre of pressure is sum N_i y_i / sum N_i over the strips' surface points.
#include <cstdint>
#include <memory>
#include <limits>
#include <string>
#include <vector>

#include "ctab/contact/normal_solution.hpp"
#include "ctab/contact/solve_status.hpp"
#include "ctab/wheelrail/wheelrail_options.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"

namespace ctab::gen {

struct PatchStrip {
  double s_m = 0.0;            //!< lateral coordinate in the contact plane (conformal: arc length) [m]
  double y_rail_m = 0.0;       //!< rail y of the point: the rail below it (planar), the surface point (conformal) [m]
  double half_length_m = 0.0;  //!< a_i [m]
  double p0_Pa = 0.0;          //!< p0_i [Pa]
};

struct ContactPatch {
  std::string zone;  //!< "tread" (S > -26 mm, S1002 section B and beyond) or "flange"
  double normal_force_N = 0.0;
  //! Force of the wheel on the rail in the side frame, summed over the strips along each strip's normal (planar:
  //! every strip of a patch has the contact-plane normal): lateral + towards the field side, vertical + down [N].
  //! The load balance uses the same components, so sum force_vertical_N = prescribed vertical load.
  double force_lateral_N = 0.0;
  double force_vertical_N = 0.0;
  double area_m2 = 0.0;
  double max_pressure_Pa = 0.0;
  double approach_m = 0.0;       //!< normal approach of the patch [m]
  double plane_angle_rad = 0.0;  //!< reference angle: the rail slope at the reference point (planar: the plane) [rad]
  //! Direction of the resultant normal force, atan2(-force_lateral_N, force_vertical_N), on both surfaces (planar:
  //! equal to plane_angle_rad, every strip having the plane's normal) [rad].
  double contact_angle_rad = 0.0;
  double y_rail_m = 0.0;                //!< contact reference point (deepest rigid point) on the rail [m]
  double y_wheel_m = 0.0;               //!< the same on the wheel, origin at the tape circle [m]
  double rolling_radius_m = 0.0;        //!< rolling radius at the reference point [m]
  double y_cop_rail_m = 0.0;            //!< centre of pressure on the rail (conformal: CONTACT's y_cop_rail) [m]
  double s_min_m = 0.0, s_max_m = 0.0;  //!< lateral extent of the loaded strips in the plane [m]
  //! Rail y of s = 0 [m]: conformal, the surface point's (the strip grid's centre, CONTACT's reference point at the
  //! settled approach); NaN on a plane (s = 0 is where the plane touches the rail).
  double s_origin_y_rail_m = std::numeric_limits<double>::quiet_NaN();
  std::vector<PatchStrip> strips;
};

struct WheelContact {
  SolveStatus status = SolveStatus::InvalidInput;
  double dy_m = 0.0;                 //!< lateral shift of the wheelset [m]
  double roll_rad = 0.0;             //!< roll angle [rad]
  double vertical_approach_m = 0.0;  //!< wheel lowered beyond first contact [m]
  double first_contact_z_m = 0.0;    //!< z_ws of first contact, relative to the nominal r_nom [m]
  GapMinimum rigid_contact;          //!< the rigid first-contact point (rolling radius for dr)
  double normal_force_N = 0.0;       //!< sum over patches
  double vertical_force_N = 0.0;     //!< sum of the patches' force_vertical_N
  int iterations = 0;                //!< MIM-1D iterations, all patches and root-finding steps
  double matrix_entries = 0.0;       //!< MIM-1D influence-matrix entries built, the same (NormalSolution) [-]
  double solve_time_s = 0.0;
  std::vector<ContactPatch> patches;
  std::vector<GapMinimum> near_misses;  //!< minima not in contact, with their vertical gap
  //! Empty on success; otherwise what went wrong, in words (e.g. "negative approach", "patch needs 5000 strips
  //! (max 4000): strip width too small", "MIM-1D did not converge in 300 iterations at patch 1").
  std::string detail;
};

//! Reusable storage of solve_wheel_contact: the patches' strip problems and their MIM-1D solvers. One per thread
//! in a sweep; a case then allocates only when it needs more room than any case before it on that thread.
//! Results do not depend on what the workspace solved before.
class WheelContactWorkspace {
 public:
  WheelContactWorkspace();
  ~WheelContactWorkspace();
  WheelContactWorkspace(WheelContactWorkspace&&) noexcept;
  WheelContactWorkspace& operator=(WheelContactWorkspace&&) noexcept;
  struct Impl;
  [[nodiscard]] Impl& impl() noexcept { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

//! Solves the contact of one side (side frame: dy, roll as in wheelrail_geometry.hpp). Never throws.
[[nodiscard]] WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                               LoadKind load, double load_value, const WheelRailOptions& options,
                                               WheelContactWorkspace& workspace);
//! The same, warm-started (MIM-1D with a prescribed load): the main patch starts from `warm_start` (a neighbouring
//! lateral shift's solution of the same wheel and load; empty: cold), extrapolated with its earlier solve (the shift
//! before it, at the same step: warm_start.earlier, extrapolate_warm_start), which is then replaced by this case's
//! main patch (cleared when the case failed), ready for the next shift. The result agrees with the cold solve within
//! the solver tolerance (Mim1dOptions::tolerance), except where a two-point window holds two self-consistent strip
//! sets and the chain stays on its neighbour's (docs/method.md, warm start); it is a function of the inputs and
//! `warm_start` alone.
[[nodiscard]] WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                               LoadKind load, double load_value, const WheelRailOptions& options,
                                               WheelContactWorkspace& workspace, Mim1dWarmStart& warm_start);
//! The same with a temporary workspace.
[[nodiscard]] WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                               LoadKind load, double load_value, const WheelRailOptions& options);

//! Totals of resolve_at_strip_width.
struct StripWidthTotals {
  double area_m2 = 0.0;          //!< total area of the loaded runs [m^2]
  double max_pressure_Pa = 0.0;  //!< largest peak pressure [Pa]
  double matrix_entries = 0.0;   //!< influence-matrix entries the solves built [-] (NormalSolution)
  //! Largest relative change of area or max pressure of one patch problem carrying at least kResolvedForceShare of
  //! the case's normal force, from the case's own solve to this one [-] (0 when none was compared).
  double worst_patch_change = 0.0;
  bool solved = false;           //!< false: no loaded patch, or a strip solve failed (the totals are then zero)
};

//! The last case solved in `workspace` solved again with MIM-1D (options, at its strip width) on the very gap samples
//! that case ended with, each patch problem at the normal force its loaded runs carried: the change that the strip
//! width alone makes, geometry and load held fixed (the least model's error estimate, least_model.hpp). Only the
//! workspace's spare solver changes; the case's own patch problems stay as they were. Never throws.
[[nodiscard]] StripWidthTotals resolve_at_strip_width(WheelContactWorkspace& workspace, double E_star_Pa,
                                                      const Mim1dOptions& options) noexcept;

}  // namespace ctab::gen
