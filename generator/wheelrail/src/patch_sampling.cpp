// SPDX-License-Identifier: Apache-2.0
#include "patch_sampling.hpp"

#include <algorithm>
#include <cmath>

#include "linear_interpolation.hpp"
#include "wheelrail_tuning.hpp"

namespace ctab::gen {

using namespace tuning;

// Wheel surface (touching position) at rail coordinate y: Newton on S.
WheelSurfacePoint PatchBuilder::wheel_at(double y, double& s_guess) const {
  WheelSurfacePoint w = side_.wheel_point(s_guess, dy_, cos_roll_, sin_roll_);
  for (int i = 0; i < kWheelPointSteps && std::abs(w.rail_y_m - y) > kWheelPointTolerance_m; ++i) {
    // d rail_y / dS = 1 / (cos(roll) + slope sin(roll)), slope the track-frame slope (intersect_wheel)
    s_guess -= (w.rail_y_m - y) * (cos_roll_ + w.slope * sin_roll_);
    w = side_.wheel_point(s_guess, dy_, cos_roll_, sin_roll_);
  }
  w.z_m += z_first_;
  return w;
}

// Samples h(s) outward from the reference point while h < depth, with the wheel lowered by p.gap_dz; false if
// fewer than kMinPatchSamples.
bool PatchBuilder::build(PatchProblem& p, double depth, double step) const {
  p.angle = p.reference.contact_angle_rad;
  p.c = std::cos(p.angle);
  p.sn = std::sin(p.angle);
  p.y0 = p.reference.rail_y_m;
  p.z0 = side_.rail().at(p.y0).z;
  p.window_depth = depth;
  p.gap.source = "wheel-rail patch";
  p.gap.strip_alignment = strips_;
  clear(p);
  // Towards -s first (then reversed), then from s = 0 towards +s: the samples come out in increasing s.
  sample_side(p, -1, depth, step);
  for (std::vector<double>* v : columns(p)) std::reverse(v->begin(), v->end());
  sample_side(p, +1, depth, step);
  if (surface_ == ContactSurface::Conformal) start_arc_length_at_origin(p);
  return p.gap.size() >= kMinPatchSamples;
}

std::vector<std::vector<double>*> PatchBuilder::columns(PatchProblem& p) {
  return {&p.gap.y_m, &p.gap.h_m, &p.gap.A_per_m, &p.gap.B_per_m, &p.rail_y, &p.normal_angle, &p.approach_weight};
}
void PatchBuilder::clear(PatchProblem& p) {
  for (std::vector<double>* v : columns(p)) v->clear();
}

void PatchBuilder::sample_side(PatchProblem& p, int direction, double depth, double step) const {
  SampleState state;
  state.s_guess = p.reference.wheel_s_m;
  state.line = {p.y0, p.z0, p.c, p.sn};
  state.s_at_y = p.reference.wheel_s_m;
  if (surface_ == ContactSurface::Conformal && !centre_on_surface(p, state)) return;
  // Planar samples are equally spaced: each Newton starts from the last two samples' solutions extrapolated.
  double previous_n_rail = 0.0, previous_s = 0.0;
  int taken = 0;
  for (int k = (direction < 0 ? 1 : 0);; ++k) {
    if (surface_ == ContactSurface::Planar) {
      const double n_rail = state.n_rail, s = state.s_guess;
      if (taken >= 2) {
        state.n_rail += n_rail - previous_n_rail;
        state.s_guess += s - previous_s;
      }
      previous_n_rail = n_rail;
      previous_s = s;
      ++taken;
    }
    Sample sample;
    const bool inside = surface_ == ContactSurface::Planar
                            ? planar_sample(p, direction * step * k, state, sample)
                            : conformal_sample(p, k == 0 ? 0.0 : direction * step, state, sample);
    if (!inside) break;
    p.gap.y_m.push_back(sample.s);
    p.gap.h_m.push_back(sample.h + p.gap_dz * p.c);
    p.gap.A_per_m.push_back(sample.A);
    p.gap.B_per_m.push_back(sample.B);
    p.rail_y.push_back(sample.y_rail);
    p.normal_angle.push_back(sample.angle);
    p.approach_weight.push_back(sample.weight);
    if (sample.h + p.gap_dz * p.c > depth || k > kMaxSamplesPerSide) break;
  }
}

// Planar: separation along the plane normal at plane coordinate s; false outside the profiles.
bool PatchBuilder::planar_sample(const PatchProblem& p, double s, SampleState& state, Sample& out) const {
  const NormalLine line{p.y0 + s * p.c, p.z0 + s * p.sn, p.c, p.sn};
  WheelSurfacePoint w{};
  if (!intersect(line, p.gap_dz, state, w)) return false;
  out.s = s;
  out.y_rail = line.y - state.n_rail * line.sn;
  out.angle = p.angle;
  fill_strip_geometry(w, state, line, out);
  return true;
}

// Conformal: s = 0 at the surface point above the grid's origin rail point (same rail y), as CONTACT's rows lie
// (its row at s = 0 has the reference point's y_rail), not where the rail point's normal meets the surface (on the
// 69 deg flank that point lies 0.13 mm further along the surface, 2/3 of a strip).
void PatchBuilder::start_arc_length_at_origin(PatchProblem& p) {
  p.reference_s = 0.0;
  const double origin_y = p.window_holds(p.grid_origin_y()) ? p.grid_origin_y() : p.y0;
  if (!p.window_holds(origin_y)) return;
  const double origin = interpolate(p.rail_y, p.gap.y_m, origin_y);
  for (double& s : p.gap.y_m) s -= origin;
  if (origin_y != p.y0 && p.window_holds(p.y0)) p.reference_s = interpolate(p.rail_y, p.gap.y_m, p.y0);
}

// Conformal: the reference surface point at arc length s_prev + ds (ds = 0: the reference point itself), by a
// predictor (the normal turned on as over the last step, the point moved along the chord's direction) and
// corrector passes that put the point midway between rail and wheel on its own normal, whose inclination is the
// mean of the two profile inclinations there (CONTACT's averaged normal).
bool PatchBuilder::conformal_sample(const PatchProblem& p, double ds, SampleState& state, Sample& out) const {
  NormalLine line = state.line;
  const double last_angle = state.angle;
  // The turn extrapolated linearly from the last two turns, so that the second corrector pass moves the point by
  // round-off only (1e-14 to 1e-15 m in most samples).
  const double next_turn = state.turns >= 2 ? 2.0 * state.turn - state.turn_before : state.turn;
  const double chord_angle = last_angle + 0.5 * next_turn, predicted = last_angle + next_turn;
  line.y += ds * std::cos(chord_angle);
  line.z += ds * std::sin(chord_angle);
  line.c = std::cos(predicted);
  line.sn = std::sin(predicted);
  WheelSurfacePoint w{};
  double last_turn = 0.0;
  if (!settle_midway(line, p.gap_dz, state, w, last_turn)) return false;
  if (last_turn >= kFirstOrderTurn_rad && !intersect(line, p.gap_dz, state, w)) return false;  // along the final normal
  const double chord = std::hypot(line.y - state.line.y, line.z - state.line.z);
  out.s = state.s + (ds < 0 ? -chord : chord);
  state.s = out.s;
  state.line = line;
  out.y_rail = line.y;  // the surface point's rail y (CONTACT's y_rail of a row)
  out.angle = std::atan2(line.sn, line.c);
  state.angle = out.angle;
  if (ds != 0.0) {
    state.turn_before = state.turn;
    state.turn = out.angle - last_angle;
    ++state.turns;
  }
  fill_strip_geometry(w, state, line, out);
  return true;
}

// The reference point of the conformal surface: the point midway between rail and wheel on the averaged
// normal, started from the rail point; the sampling then marches from it.
bool PatchBuilder::centre_on_surface(const PatchProblem& p, SampleState& state) const {
  WheelSurfacePoint w{};
  double last_turn = 0.0;
  if (!settle_midway(state.line, p.gap_dz, state, w, last_turn)) return false;
  state.s = 0.0;
  state.angle = std::atan2(state.line.sn, state.line.c);
  return true;
}

// Corrector passes (midway) until the point and its normal stand still (kSurfaceMove_m, kSurfaceTurn_rad);
// `last_turn`: how far the last pass turned the normal [rad].
bool PatchBuilder::settle_midway(NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w,
                                 double& last_turn) const {
  double previous_move = 0.0, previous_turn = 0.0;
  NormalLine before;
  double signed_turn = 0.0;
  for (int pass = 0; pass < kSurfacePasses; ++pass) {
    before = line;
    double moved = 0.0;
    if (!midway(line, dz, state, w, moved)) return false;
    // |sin| of the turn between the two normals: the turn itself at the small turns the tolerances test.
    signed_turn = before.c * line.sn - before.sn * line.c;
    const double move = std::abs(moved), turn = std::abs(signed_turn);
    last_turn = turn;
    if (move < kSurfaceMove_m && turn < kSurfaceTurn_rad) break;
    if (kNextMoveMargin * next_move(before, state, w, turn) < kSurfaceMove_m) break;
    // The passes contract geometrically: the next would move the point by about move^2 / previous_move.
    if (pass > 0 && move * move < kSurfaceMove_m * previous_move && turn * turn < kSurfaceTurn_rad * previous_turn)
      break;
    previous_move = move;
    previous_turn = turn;
  }
  // A small last turn moves the intersections to first order (next_move): n -> n (1 - t theta); the sample then
  // needs no re-intersection along the final normal (conformal_sample).
  if (last_turn < kFirstOrderTurn_rad) turn_intersections(before, state, w, signed_turn);
  return true;
}

// How far the next corrector pass would move the point, to first order in this pass's turn [m]: turning the line by
// theta about the midpoint moves each intersection, at n along the line on a profile of slope t relative to the
// line's tangent, by -n t theta, so the midpoint by -theta (n_rail t_rail + n_wheel t_wheel) / 2 = theta h
// (t_wheel - t_rail) / 4 (n_rail = -n_wheel = h / 2); plus the second order's bound |h| theta^2 / 4, which dominates
// after a large turn (the first pass from the rail point turns by about 1e-2 rad).
// `line`: the line before the turn, at whose intersections `state` and `w` hold the slopes. (The turn that such a
// move causes, curvature x move, is below 1e-10 rad.)
double PatchBuilder::next_move(const NormalLine& line, const SampleState& state, const WheelSurfacePoint& w,
                               double turn) {
  const double h = std::abs(state.n_rail - state.n_wheel);
  return 0.25 * turn * h * (std::abs(relative_slope(line, w.slope) - relative_slope(line, state.rail_slope)) + turn);
}

// The intersections after the line turned by theta about its point (first order, next_move): each n by -n t theta,
// t the profile's slope relative to the line before the turn.
void PatchBuilder::turn_intersections(const NormalLine& line, SampleState& state, const WheelSurfacePoint& w,
                                      double theta) {
  state.n_rail -= state.n_rail * relative_slope(line, state.rail_slope) * theta;
  state.n_wheel -= state.n_wheel * relative_slope(line, w.slope) * theta;
}

// A profile's slope relative to the line's tangent (c, sn), dz/dy the profile's: tan(atan(dz/dy) - angle).
double PatchBuilder::relative_slope(const NormalLine& line, double slope) {
  return (slope * line.c - line.sn) / (line.c + slope * line.sn);
}

// One corrector pass (`moved`: how far the point moved along the normal [m]): intersects `line` with both profiles,
// moves its point to the midpoint and turns it to the mean of the rail's and the wheel's inclination at the point's
// own rail y (keeps n_rail, n_wheel relative to the moved point): CONTACT's rule, read off its rows (at its reference
// row, y -42.2747 mm, the local angle -69.563 deg is the mean of the rail's -69.126 and the wheel flank's -70.0 deg
// there). The inclinations are read at the point's own y, not where the normal meets each profile: on the rail's
// 13 mm arc those lie 0.09 mm apart and 1.1 deg steeper (docs/design/wheelrail-solve.md).
bool PatchBuilder::midway(NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w, double& moved) const {
  if (!intersect(line, dz, state, w)) return false;
  const double mid = 0.5 * (state.n_rail + state.n_wheel);
  moved = mid;
  line.y -= mid * line.sn;
  line.z += mid * line.c;
  state.n_rail -= mid;
  state.n_wheel -= mid;
  // The mean inclination's direction bisects the two profiles' unit tangents (1, slope) / |(1, slope)|.
  state.rail_at_point = side_.rail().at(line.y);
  state.rail_at_point_y = line.y;
  const double rail_slope = state.rail_at_point.dz, wheel_slope = wheel_at(line.y, state.s_at_y).slope;
  const double rail_c = 1.0 / std::sqrt(1.0 + rail_slope * rail_slope),
               wheel_c = 1.0 / std::sqrt(1.0 + wheel_slope * wheel_slope);
  const double c = rail_c + wheel_c, sn = rail_slope * rail_c + wheel_slope * wheel_c;
  const double length = std::sqrt(c * c + sn * sn);
  line.c = c / length;
  line.sn = sn / length;
  return true;
}

// Separation h (state.n_rail - state.n_wheel) along the line, A and B of the strip there (with the line's angle).
// `line` is the sample's normal (c, sn: cosine and sine of out.angle).
void PatchBuilder::fill_strip_geometry(const WheelSurfacePoint& w, const SampleState& state, const NormalLine& line,
                                       Sample& out) const {
  // conformal: the rail at the surface point's own y, as the last corrector pass evaluated it
  const ProfilePoint r = out.y_rail == state.rail_at_point_y ? state.rail_at_point : side_.rail().at(out.y_rail);
  // Lateral relative curvature seen along the line's lateral direction: each surface's n'' = kappa (1 + n'^2)^(3/2)
  // with n' its slope relative to the line's tangent. Planar, this is exactly h''/2 (the plane is straight);
  // conformal, n is an offset from the curved surface, whose own curvature kappa_m adds to both surfaces' n''
  // and cancels in h'' = n_rail'' - n_wheel'' (offset curves: kappa(offset) = kappa_m + n'' for small n), so the
  // relative curvature is the difference of the two profile curvatures, not h'' of a flat plane.
  const double tr = relative_slope(line, r.dz), tw = relative_slope(line, w.slope);
  const double gr = 1 + tr * tr, gw = 1 + tw * tw;
  out.B = 0.5 * (r.curvature() * gr * std::sqrt(gr) - w.curvature() * gw * std::sqrt(gw));
  out.h = state.n_rail - state.n_wheel;
  out.weight = 1.0 / (line.c + w.slope * line.sn);  // dn_wheel / dz
  // Along x the wheel (a surface of revolution about the lateral axis) rises vertically by x^2 / (2 r), r its radius
  // at the point; along the normal a vertical shift is seen times dn_wheel/dz (weight): A = weight / (2 r), or
  // cos(phi) / (2 r cos(delta - phi)) with phi the wheel's inclination there. Only where the wheel is parallel to
  // the plane is it cos(delta) / (2 r); that value everywhere would put the flange root's area 1.8 % under CONTACT's in
  // CONTACT's own plane (dy 6.5 mm, bem2d; the wheel's inclination spans about +-10 deg across that patch).
  out.A = out.weight / (2.0 * w.radius_m);
}

// Rail and wheel (lowered by dz) along the line: Newton on n for each; false outside the profiles.
bool PatchBuilder::intersect(const NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w) const {
  if (!intersect_rail(line, state.n_rail, state.rail_slope)) return false;
  return intersect_wheel(line, dz, state, w);
}

// Rail: z_r(y - n sn) = z + n c, Newton on n; `slope`: the rail's dz/dy at the last point evaluated.
bool PatchBuilder::intersect_rail(const NormalLine& line, double& n_rail, double& slope) const {
  const ProfileTable& rail = side_.rail();
  for (int i = 0; i < kIntersectionSteps; ++i) {
    const double y = line.y - n_rail * line.sn;
    if (!rail.contains(y)) return false;
    const ProfilePoint r = rail.at(y);
    const double f = r.z - (line.z + n_rail * line.c), df = -r.dz * line.sn - line.c;
    slope = r.dz;
    n_rail -= f / df;
    if (std::abs(f) < kIntersectionTolerance_m) break;
  }
  return true;
}

// Wheel (lowered by dz): Newton on its parameter S for the point on the line, g(S) = (P(S) - O) . t = 0 with t =
// (c, sn) the line's normal and O its origin; then n_wheel = (P - O) . (-sn, c): one wheel point per step, a third
// of what a Newton on n with a Newton on S inside would evaluate; `w` is the last wheel point evaluated.
bool PatchBuilder::intersect_wheel(const NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w) const {
  for (int i = 0; i < kIntersectionSteps; ++i) {
    if (!side_.wheel().contains(state.s_guess)) return false;
    w = side_.wheel_point(state.s_guess, dy_, cos_roll_, sin_roll_);
    w.z_m += z_first_ + dz;
    if (!side_.rail().contains(w.rail_y_m)) return false;
    const double along = (w.rail_y_m - line.y) * line.c + (w.z_m - line.z) * line.sn;
    state.n_wheel = (w.z_m - line.z) * line.c - (w.rail_y_m - line.y) * line.sn;
    if (std::abs(along) < kIntersectionTolerance_m) return true;
    // S is the wheel profile's own lateral coordinate, rotated by the roll: d rail_y / dS = 1 / (cos(roll) +
    // slope sin(roll)) and d z / dS = slope d rail_y / dS.
    state.s_guess -= along * (cos_roll_ + w.slope * sin_roll_) / (line.c + w.slope * line.sn);
  }
  return side_.wheel().contains(state.s_guess);
}

}  // namespace ctab::gen
