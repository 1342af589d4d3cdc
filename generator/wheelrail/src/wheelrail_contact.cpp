#include "ctab/wheelrail/wheelrail_contact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/contact/normal_contact.hpp"
#include "ctab/contact/resolution.hpp"
#include "ctab/contact/root_finding.hpp"
#include "ctab/contact/strip_grid.hpp"

namespace ctab::gen {

namespace {

// Patch window (README "Contact search"): h is sampled while h < kWindowFactor x the expected approach, at least
// kMinimumWindowDepth_m; chosen so that close minima (tread and flange root at dy = 5 mm) share a patch as CONTACT
// combines them. A contact that reaches the window's end doubles the depth, at most kWindowAttempts times.
constexpr double kWindowFactor = 2.0;
constexpr double kMinimumWindowDepth_m = 50e-6;
constexpr double kWindowGrowth = 2.0;
constexpr int kWindowAttempts = 4;
constexpr int kMaxSamplesPerSide = 4000;     // chosen: 0.4 m at the 0.1 mm sample step, beyond any profile
constexpr std::size_t kMinPatchSamples = 8;  // chosen: a window with fewer samples cannot hold 3 strips
// Newton on the wheel parameter S and on the plane-normal intersections: quadratic, 3-5 steps in practice.
constexpr int kWheelPointSteps = 20;
constexpr double kWheelPointTolerance_m = 1e-13;
constexpr int kIntersectionSteps = 30;
constexpr double kIntersectionTolerance_m = 1e-14;
// Conformal surface: corrector passes that put a surface point midway between rail and wheel on its averaged
// normal, until a pass moves the point by less than kSurfaceMove_m and turns the normal by less than
// kSurfaceTurn_rad, at most kSurfacePasses. Measured (flange root, dy 6.5 mm): from the last sample's normal a pass
// turns it by 7e-3, 5e-8, 2e-13 rad, then 0; from the normal extrapolated from the last two samples the first
// turn is about 1e-5 rad. Chosen: 1e-12 rad and 1e-13 m, at round-off of the intersections (1e-14 m).
constexpr int kSurfacePasses = 4;
constexpr double kSurfaceMove_m = 1e-13;
constexpr double kSurfaceTurn_rad = 1e-12;
// After a last pass that turned the normal by less than this the intersections follow the turn to first order instead
// of a re-intersection along the final normal (settle_midway's turn_intersections: the second order,
// n (t theta)^2 and curvature x (n theta)^2 / 2, below 1e-16 m). Chosen.
constexpr double kFirstOrderTurn_rad = 1e-5;
// A pass whose turn would move the point by less than kSurfaceMove_m / kNextMoveMargin on the next pass (first order,
// settle_midway's next_move) is the last. Chosen: 10, for the slopes taken where the last Newton steps evaluated them.
constexpr double kNextMoveMargin = 10.0;
// Window sizing only: Hertz at the gap minimum with B >= A/20 (CONTACT's R_y <= 20 R_x) and a cosine floor for
// steep flanks (cos 87 deg); 0.1 mm when Hertz fails.
constexpr double kCurvatureRatioLimit = 20.0;
constexpr double kCosineFloor = 0.05;
constexpr double kFallbackApproach_m = 1e-4;
// Several patches: vertical approach by the Illinois root finder to a force tolerance of 10x the solver's.
constexpr double kSharedApproachTolerance_m = 1e-15;
constexpr double kSharedForceToleranceFactor = 10.0;
constexpr int kSharedApproachIterations = 100;
// Reference point at the centre of the interpenetration region (recentre_main_patch): at least kCentreSamples
// samples over the region (interpenetration_centre), re-solves until the point moves less than 1 um, at most 4 passes
// (2 in practice).
constexpr int kCentreSamples = 64;  // chosen: the centre moves < 0.1 um from 64 to 1000 samples
constexpr double kFinestCentreStep_m = 1e-6;
constexpr double kRecentreTolerance_m = 1e-6;
constexpr int kRecentrePasses = 4;
// Secant steps on the centre (recentre_main_patch): a measured slope of C above this is taken as 0.5 (chosen; a
// slope near +1 would make the step unbounded).
constexpr double kMaxCentreSlope = 0.5;
// The gap passes follow the centre for at most this many passes (then the plane stays, and recentre_main_patch
// re-solves whole): where one region spans tread and flange root the centre moves by about 10 um per 0.2 um of
// approach and following it alternates (90 max-iterations in the 0.01 mm sweep, built-in profiles, single wheel).
// Chosen: planar cases settle in 2-4 passes.
constexpr int kCentreFollowingPasses = 6;
// A conformal grid that follows the centre moves a pass's warm start to first order (shift_pass_start) while the move
// stays below this share of a strip (chosen: the strips keep their index up to half a strip).
constexpr double kPredictedGridMove = 0.5;
// Prescribed load: the gap is re-sampled at the solved vertical approach until it moves by less than 1 nm (1e-5 of
// a typical 0.1 mm approach) and the vertical load balances to 1e-10 (issue 8: 1e-9; the warm-started strip solves
// scatter by about 2e-11). Planar 2-4 passes (up to 9 where the flank and the root share a window), conformal
// with a vertical load 5-15 (up to about 40 at dy 6.6 mm, where the patch spreads from the flank to the root).
constexpr double kGapApproachTolerance_m = 1e-9;
constexpr double kVerticalBalance = 1e-10;
// Settled x and the vertical load within this share of its value: x is held and the force alone balanced at that gap
// (solve_main_for_load). Chosen: the noise that x's 1 nm settling puts on the vertical load is up to 1e-5 of it on
// the conformal flank, where V(F) at a fixed gap is smooth.
constexpr double kHoldSamplingWindow = 1e-4;
// A first pass from the Hertz estimate only predicts the next x (it is never the last: the gap is re-sampled), so it
// is solved to this looser relative tolerance: the approach to ~1e-7 x 0.1 mm = 1e-11 m, 1 % of
// kGapApproachTolerance_m. Measured (default table, pass 0): 7.21 MIM-1D iterations at 1e-11, 6.62 at 1e-8, 6.25 at
// 1e-7, 5.97 at 1e-6; 1e-6 moves the final x by up to the tolerance between warm and cold starts (warm_start_test:
// strip fields 5e-8 of their largest value, over its 1e-8), 1e-7 not (1.6e-9, as at 1e-8).
constexpr double kPredictorTolerance = 1e-7;
// A later pass stops at kPredictorTolerance while its approach lies more than this many kGapApproachTolerance_m off
// its sampling approach (it cannot settle; at kPredictorTolerance the approach is known to ~1e-11 m). Chosen: 2.
constexpr double kEarlyStopWindow = 2.0;
constexpr int kGapPasses = 60;
// Factor on the sampling approach where the secant step predicts x <= 0 (solve_main_for_load). Chosen: halving.
constexpr double kSamplingApproachCut = 0.5;
constexpr int kStripSolveRetries = 4;  // failed strip solves after a successful pass, each halfway back (chosen)
// Slope d dz / d x of the solved approach on the sampling approach: negative where the vertical shift reaches some
// strips more than dz cos(delta_ref) (a plane on the flank over the flange root: -2 at dy 6.63 mm, where the fixed
// point alternates); clamped to [kMinGapSlope, kMaxGapSlope] (chosen; beyond them it is taken for noise).
constexpr double kMinGapSlope = -20.0;
constexpr double kMaxGapSlope = 0.8;

// With CONTACT's reference rule the strips take CONTACT's wheel-rail grid too: a strip centred on the reference point
// (its strip files hold rows at s = 0, +-ds, ...), so that ctab's strip k is CONTACT's row k. Off by half a strip,
// CONTACT's edge row of the flank patch (dy 7.5 mm, normal force, 8 rows) fell between ctab's edge strip and the
// next: p0 profile RMS 17 % against 3.4 % aligned (flange_reference_test). The conformal surface centres its grid
// on CONTACT's reference point at the deepest point too (follow_interpenetration_centre); the planar deepest point
// keeps the edges at the origin (its tables as they were validated).
GridAlignment strip_alignment(const WheelRailOptions& options) {
  return options.reference_at_interpenetration_centre || options.surface == ContactSurface::Conformal
             ? GridAlignment::CentresAtOrigin
             : GridAlignment::EdgesAtOrigin;
}

// Whether two reference points are the same point (every field equal: a patch built at either is the same).
bool same_point(const GapMinimum& a, const GapMinimum& b) {
  return a.wheel_s_m == b.wheel_s_m && a.rail_y_m == b.rail_y_m && a.gap_m == b.gap_m &&
         a.contact_angle_rad == b.contact_angle_rad && a.rolling_radius_m == b.rolling_radius_m;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

// One patch's strip problem. Planar: the plane tangent to the rail at the reference point, s along it, every
// sample's normal the plane's. Conformal: a curved reference surface midway between rail and wheel, s its arc
// length, every sample with its own normal (normal_angle).
struct PatchProblem {
  GapMinimum reference;
  double angle = 0, c = 1, sn = 0;  // reference angle (rail inclination at the reference point), cos, sin
  double y0 = 0, z0 = 0;            // reference point on the rail (rail y, track z)
  // Conformal at the deepest point: the rail y of the surface point at s = 0, where the strip grid is centred
  // (grid_origin_y); NaN: the reference point's. reference_s: s of the reference point on the surface (0 unless
  // the origin moved).
  double origin_y = std::numeric_limits<double>::quiet_NaN();
  double reference_s = 0;
  // Vertical approach of the wheel beyond first contact at which h was sampled [m] (the wheel lowered by it); h
  // holds the separation there plus gap_dz c, so that the strip solver's approach is gap_dz c at that position.
  double gap_dz = 0;
  double window_depth = 0;           // the window's depth [m] (build)
  GapProfile gap;                    // y_m holds s
  std::vector<double> rail_y;        // planar: rail y below each sample; conformal: rail y of the surface point
  std::vector<double> normal_angle;  // each sample's normal (inclination from the vertical, < 0 on the gauge side)
  // Each sample's d(separation)/d(dz), the vertical shift of the wheel seen along its normal: cos(delta_w) /
  // cos(delta_w - alpha) (intersect_wheel's Newton: f = z_w(y - n sn) + dz - z - n c); for gap_slope.
  std::vector<double> approach_weight;
  std::vector<double> strip_gap_rate;  // scratch (gap_slope): d h_i / d gap_dz at each strip of the solver's grid
  std::vector<double> load_weight;     // scratch: cos of each strip's normal inclination (set_vertical_load_weights)
  std::unique_ptr<Mim1dSolver> solver;
  NormalSolution solution;

  [[nodiscard]] double grid_origin_y() const { return std::isnan(origin_y) ? y0 : origin_y; }
  //! Whether rail y lies strictly inside the sampled window (between the first and last samples' rail y).
  [[nodiscard]] bool window_holds(double y) const {
    return rail_y.size() >= 2 && y > rail_y.front() && y < rail_y.back();
  }
};

// Creates the patch's MIM-1D solver, or re-targets the one it already has. Returns an empty string, or why not.
std::string prepare_mim1d_solver(std::unique_ptr<Mim1dSolver>& solver, const GapProfile& gap, double E_star,
                                 const Mim1dOptions& options) {
  const double strips = strip_count(gap, options.strip_width_m);
  if (!(strips <= static_cast<double>(kMaxStripsPerPatch)))
    return "patch needs " + number_text(strips) + " strips (max " + std::to_string(kMaxStripsPerPatch) +
           "): strip width too small";
  try {
    if (solver && solver->matches(E_star, options)) solver->reset(gap);
    else solver = std::make_unique<Mim1dSolver>(gap, E_star, options);
  } catch (const std::exception& e) {
    return std::string("MIM-1D set-up: ") + e.what();
  }
  return {};
}

// A line in the side frame through (y, z) (rail y, track z) along the normal of inclination angle: the points
// (y - n sin, z + n cos), n > 0 into the rail.
struct NormalLine {
  double y = 0, z = 0, c = 1, sn = 0;
};

// y between x[i - 1] and x[i], linear.
double interpolate_in(const std::vector<double>& x, const std::vector<double>& y, std::size_t upper, double at) {
  const std::size_t i = std::clamp<std::size_t>(upper, 1, x.size() - 1);
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return (1 - t) * y[i - 1] + t * y[i];
}

// y at `at`, linear in the increasing x (extrapolated from the end segments).
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  return interpolate_in(x, y, static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin()), at);
}

// interpolate() at non-decreasing positions (a strip grid's centres), its segment search walked on from the last
// query instead of a binary search per query: the same values.
class ForwardInterpolation {
 public:
  ForwardInterpolation(const std::vector<double>& x, const std::vector<double>& y) : x_(x), y_(y) {}
  double operator()(double at) {
    if (upper_ > 0 && x_[upper_ - 1] > at)
      upper_ = static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), at) - x_.begin());
    while (upper_ < x_.size() && x_[upper_] <= at) ++upper_;
    return interpolate_in(x_, y_, upper_, at);
  }

 private:
  const std::vector<double>& x_;
  const std::vector<double>& y_;
  std::size_t upper_ = 0;  // the first x beyond the last query
};

class PatchBuilder {
 public:
  PatchBuilder(const SideGeometry& side, double dy, double roll, double z_first, ContactSurface surface,
               GridAlignment strips)
      : side_(side), dy_(dy), roll_(roll), cos_roll_(std::cos(roll)), sin_roll_(std::sin(roll)), z_first_(z_first),
        surface_(surface), strips_(strips) {}
  //! z_ws of first contact: the wheel is placed touching the rail.
  void set_first_contact_height(double z_first) { z_first_ = z_first; }

  // Wheel surface (touching position) at rail coordinate y: Newton on S.
  WheelSurfacePoint wheel_at(double y, double& s_guess) const {
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
  bool build(PatchProblem& p, double depth, double step) const {
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

  static std::vector<std::vector<double>*> columns(PatchProblem& p) {
    return {&p.gap.y_m, &p.gap.h_m, &p.gap.A_per_m, &p.gap.B_per_m, &p.rail_y, &p.normal_angle, &p.approach_weight};
  }
  static void clear(PatchProblem& p) {
    for (std::vector<double>* v : columns(p)) v->clear();
  }

  void sample_side(PatchProblem& p, int direction, double depth, double step) const {
    SampleState state{0, 0, p.reference.wheel_s_m, {p.y0, p.z0, p.c, p.sn}, 0.0, p.reference.wheel_s_m, 0.0};
    if (surface_ == ContactSurface::Conformal && !centre_on_surface(p, state)) return;
    // Planar samples are equally spaced: each Newton starts from the last two samples' solutions extrapolated
    // (from the last one alone they took one step more).
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
  bool planar_sample(const PatchProblem& p, double s, SampleState& state, Sample& out) const {
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
  // (its row at s = 0 has the reference point's y_rail). The marching starts where the rail point's normal meets
  // the surface instead, which on the flank (69 deg, the surface 0.05 mm inside the rail) lies 0.13 mm further
  // along the surface: the strips sat 2/3 of a row off CONTACT's.
  static void start_arc_length_at_origin(PatchProblem& p) {
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
  bool conformal_sample(const PatchProblem& p, double ds, SampleState& state, Sample& out) const {
    NormalLine line = state.line;
    const double last_angle = state.angle;
    // The turn extrapolated linearly from the last two turns: the second corrector pass then moves the point by
    // 1e-14 to 1e-15 m in most samples, 1e-12 to 1e-13 m with the last turn repeated (conformal default table).
    const double next_turn = state.turns >= 2 ? 2.0 * state.turn - state.turn_before : state.turn;
    const double chord_angle = last_angle + 0.5 * next_turn, predicted = last_angle + next_turn;
    line.y += ds * std::cos(chord_angle);
    line.z += ds * std::sin(chord_angle);
    line.c = std::cos(predicted);
    line.sn = std::sin(predicted);
    WheelSurfacePoint w{};
    double last_turn = 0.0;
    if (!settle_midway(line, p.gap_dz, state, w, last_turn)) return false;
    if (last_turn >= kFirstOrderTurn_rad && !intersect(line, p.gap_dz, state, w))
      return false;  // along the final normal
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
  bool centre_on_surface(const PatchProblem& p, SampleState& state) const {
    WheelSurfacePoint w{};
    double last_turn = 0.0;
    if (!settle_midway(state.line, p.gap_dz, state, w, last_turn)) return false;
    state.s = 0.0;
    state.angle = std::atan2(state.line.sn, state.line.c);
    return true;
  }

  // Corrector passes (midway) until the point and its normal stand still (kSurfaceMove_m, kSurfaceTurn_rad);
  // `last_turn`: how far the last pass turned the normal [rad].
  bool settle_midway(NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w, double& last_turn) const {
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
  // (t_wheel - t_rail) / 4 (n_rail = -n_wheel = h / 2); plus the second order's bound |h| theta^2 / 4 (measured: the
  // first pass from the rail point turns by 1e-2 rad, where the first order said 6e-15 m and the pass moved 2e-11 m).
  // `line`: the line before the turn, at whose intersections `state` and `w` hold the slopes. (The turn that such a
  // move causes, curvature x move, is below 1e-10 rad.)
  static double next_move(const NormalLine& line, const SampleState& state, const WheelSurfacePoint& w, double turn) {
    const double h = std::abs(state.n_rail - state.n_wheel);
    return 0.25 * turn * h * (std::abs(relative_slope(line, w.slope) - relative_slope(line, state.rail_slope)) + turn);
  }

  // The intersections after the line turned by theta about its point (first order, next_move): each n by -n t theta,
  // t the profile's slope relative to the line before the turn.
  static void turn_intersections(const NormalLine& line, SampleState& state, const WheelSurfacePoint& w, double theta) {
    state.n_rail -= state.n_rail * relative_slope(line, state.rail_slope) * theta;
    state.n_wheel -= state.n_wheel * relative_slope(line, w.slope) * theta;
  }

  // A profile's slope relative to the line's tangent (c, sn), dz/dy the profile's: tan(atan(dz/dy) - angle).
  static double relative_slope(const NormalLine& line, double slope) {
    return (slope * line.c - line.sn) / (line.c + slope * line.sn);
  }

  // One corrector pass (`moved`: how far the point moved along the normal [m]): intersects `line` with both profiles,
  // moves its point to the midpoint and turns it to the mean of the rail's and the wheel's inclination at the point's
  // own rail y (keeps n_rail, n_wheel relative to the moved point): CONTACT's rule, read off its rows (at its reference
  // row, y -42.2747 mm, the local angle -69.563 deg is the mean of the rail's -69.126 and the wheel flank's -70.0 deg
  // there). Taken where the normal meets each profile instead, the rail's 13 mm arc was read 0.09 mm further along
  // and 1.1 deg steeper: the flank's force direction -0.59 deg from CONTACT's, its lateral force +8.6 % of FZ (README
  // "Which inclinations make the normal").
  bool midway(NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w, double& moved) const {
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
  void fill_strip_geometry(const WheelSurfacePoint& w, const SampleState& state, const NormalLine& line,
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
    // the plane is it cos(delta) / (2 r); taking that everywhere put the flange root's area 1.8 % under CONTACT's in
    // CONTACT's own plane (dy 6.5 mm, bem2d; the wheel's inclination spans about +-10 deg across that patch).
    out.A = out.weight / (2.0 * w.radius_m);
  }

  // Rail and wheel (lowered by dz) along the line: Newton on n for each; false outside the profiles.
  bool intersect(const NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w) const {
    if (!intersect_rail(line, state.n_rail, state.rail_slope)) return false;
    return intersect_wheel(line, dz, state, w);
  }

  // Rail: z_r(y - n sn) = z + n c, Newton on n; `slope`: the rail's dz/dy at the last point evaluated.
  bool intersect_rail(const NormalLine& line, double& n_rail, double& slope) const {
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
  // (c, sn) the line's normal and O its origin; then n_wheel = (P - O) . (-sn, c). One wheel point per step (a
  // Newton on n with a Newton on S inside for each wheel point took about three times as many: 11 % of the default
  // table's instructions); `w` is the last wheel point evaluated.
  bool intersect_wheel(const NormalLine& line, double dz, SampleState& state, WheelSurfacePoint& w) const {
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

  const SideGeometry& side_;
  double dy_, roll_, cos_roll_, sin_roll_, z_first_;
  ContactSurface surface_;
  GridAlignment strips_;
};

// Expected normal approach from Hertz with the curvatures at the gap minimum (window sizing only).
double expected_approach(const SideGeometry& side, const GapMinimum& m, double dy, double roll, double E_star,
                         LoadKind load, double value) {
  const double c = std::cos(m.contact_angle_rad);
  if (load == LoadKind::Approach) return value * c;
  const WheelSurfacePoint w = side.wheel_point(m.wheel_s_m, dy, roll);
  const double A = c / (2.0 * w.radius_m);
  const double B = std::max(0.5 * (side.rail().at(m.rail_y_m).curvature() - w.curvature()), A / kCurvatureRatioLimit);
  const double force = load == LoadKind::VerticalForce ? value / std::max(c, kCosineFloor) : value;
  const HertzContact h = hertz_from_load(A, B, E_star, force);
  return h.status == SolveStatus::Converged ? h.approach_m : kFallbackApproach_m;
}

// Force of the wheel on the rail in the side frame [N]: lateral + towards the field side, vertical + down.
struct ForceComponents {
  double lateral_N = 0.0, vertical_N = 0.0;
};

// Direction of strip `strip`'s normal force (inclination from the vertical, < 0 on the gauge side) [rad]: the
// normal of the surface at the strip's centre (planar: the plane's for every strip).
double strip_normal_angle(const PatchProblem& p, const StripSolution& strip) {
  return interpolate(p.gap.y_m, p.normal_angle, strip.y_m);
}

// One run of strips' force, summed strip by strip along each strip's normal: the components that the load balance
// uses and that are reported (so that they add up to the prescribed vertical load).
ForceComponents run_force(const PatchProblem& p, const PatchSolution& run) {
  ForceComponents f;
  for (const StripSolution& st : run.strips) {
    const double angle = strip_normal_angle(p, st);
    f.lateral_N -= st.load_N * std::sin(angle);
    f.vertical_N += st.load_N * std::cos(angle);
  }
  return f;
}

// Why a patch's normal solve failed, in words.
std::string patch_failure(NormalMethod method, const NormalSolution& solution, std::size_t slot) {
  const std::string at = " at patch " + std::to_string(slot + 1);
  const std::string solver = method == NormalMethod::Mim1d ? std::string("MIM-1D") : std::string(method_name(method));
  if (!solution.detail.empty()) return solver + ": " + solution.detail + at;
  switch (solution.status) {
    case SolveStatus::MaxIterations:
      return solver + " did not converge in " + std::to_string(solution.iterations) + " iterations" + at;
    case SolveStatus::InvalidInput:
      return solver + " rejected the strip problem" + at + " (non-finite input or curvature out of range)";
    case SolveStatus::NumericalFailure:
      return solver + " failed numerically" + at + " (singular system or non-finite value)";
    case SolveStatus::ZoneTruncated:
      return "the contact reaches the end of the window" + at + " (the profiles end inside the contact)";
    default: return std::string(status_name(solution.status)) + at;
  }
}

}  // namespace

struct WheelContactWorkspace::Impl {
  std::vector<GapMinimum> minima;
  std::vector<PatchProblem> pool;  // patch problems; the first `used` are this case's
  Mim1dWarmStart pass_start;       // the main patch's previous pass (solve_main_for_load), when not warm-started
  Mim1dWarmStart moved_start;      // pass_start moved onto a grid with another origin (start_on_grid)
  Mim1dWarmStart chain_start;      // the chain's last two solves extrapolated (extrapolate_warm_start)
  std::unique_ptr<Mim1dSolver> other_width;  // resolve_at_strip_width's solver
  std::size_t used = 0;
  PatchProblem& acquire() {  // the pool is sized before use
    PatchProblem& p = pool[used++];
    p.origin_y = std::numeric_limits<double>::quiet_NaN();
    return p;
  }
};

WheelContactWorkspace::WheelContactWorkspace() : impl_(std::make_unique<Impl>()) {}
WheelContactWorkspace::~WheelContactWorkspace() = default;
WheelContactWorkspace::WheelContactWorkspace(WheelContactWorkspace&&) noexcept = default;
WheelContactWorkspace& WheelContactWorkspace::operator=(WheelContactWorkspace&&) noexcept = default;

WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                 LoadKind load, double load_value, const WheelRailOptions& options) {
  WheelContactWorkspace workspace;
  return solve_wheel_contact(side, dy_m, roll_rad, E_star_Pa, load, load_value, options, workspace);
}

namespace {

// One wheel-rail case: the steps of solve_wheel_contact, sharing the case's inputs, result and workspace.
class WheelCase {
 public:
  WheelCase(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa, LoadKind load, double load_value,
            const WheelRailOptions& options, WheelContactWorkspace::Impl& workspace, Mim1dWarmStart* warm_start)
      : side_(side), dy_(dy_m), roll_(roll_rad), E_star_(E_star_Pa), load_(load), value_(load_value), options_(options),
        ws_(workspace), warm_(warm_start),
        builder_(side, dy_m, roll_rad, 0.0, options.surface, strip_alignment(options)) {}

  WheelContact solve() {
    ws_.used = 0;
    if (warm_ != nullptr) extrapolate_warm_start(*warm_, ws_.chain_start);
    result_.dy_m = dy_;
    result_.roll_rad = roll_;
    if (std::string why = invalid_input(); !why.empty()) return finish(SolveStatus::InvalidInput, std::move(why));
    if (!find_rigid_contact())
      return finish(SolveStatus::InvalidInput, "the wheel does not reach the rail at dy = " + number_text(dy_) +
                                                   " m, roll = " + number_text(roll_) +
                                                   " rad (lateral shift beyond the profiles)");
    if (value_ == 0.0) {
      result_.near_misses = ws_.minima;
      return finish(SolveStatus::NoContact);
    }
    if (const SolveStatus status = solve_in_growing_window(); status != SolveStatus::Converged)
      return finish(status, std::move(detail_));
    const SolveStatus status = collect_patches();
    collect_near_misses();
    return finish(status, std::move(detail_));
  }

 private:
  std::string invalid_input() const {
    if (!std::isfinite(dy_)) return "lateral shift dy is not finite";
    if (!std::isfinite(roll_)) return "roll angle is not finite";
    if (!std::isfinite(value_)) return "load is not finite";
    if (value_ < 0.0) return load_ == LoadKind::Approach ? "negative approach" : "negative load";
    if (options_.reference_at_interpenetration_centre && options_.reference_angle == ReferenceAngle::Tangent)
      return "CONTACT's reference point (the interpenetration centre) takes CONTACT's reference angle, not the tangent";
    if (const auto& reference = options_.prescribed_reference) {
      if (options_.surface != ContactSurface::Planar) return "a prescribed reference point needs the planar surface";
      if (!std::isfinite(reference->contact_angle_rad) || !side_.rail().contains(reference->rail_y_m))
        return "the prescribed reference point (rail y " + number_text(reference->rail_y_m) + " m, angle " +
               number_text(reference->contact_angle_rad) + " rad) is not on the rail profile";
    }
    return {};
  }

  // Gap minima and the height of first contact; false when the wheel is not over the rail.
  bool find_rigid_contact() {
    double z_first = 0.0;
    side_.gap_minima(dy_, roll_, ws_.minima, z_first);
    if (ws_.minima.empty() || !std::isfinite(z_first)) return false;
    result_.first_contact_z_m = z_first + side_.track().nominal_radius_m;
    result_.rigid_contact = ws_.minima[0];
    builder_.set_first_contact_height(z_first);
    // At most one patch per gap minimum: size the pool now so that references into it stay valid.
    if (ws_.pool.size() < ws_.minima.size()) ws_.pool.resize(ws_.minima.size());
    return true;
  }

  // Solves in a window that doubles while the main contact reaches its end. Converged, or the failure (with
  // detail_); a contact still truncated after kWindowAttempts is left for collect_patches to report.
  SolveStatus solve_in_growing_window() {
    double depth = std::max(kWindowFactor * expected_approach(side_, ws_.minima[0], dy_, roll_, E_star_, load_, value_),
                            kMinimumWindowDepth_m);
    for (int attempt = 0; attempt < kWindowAttempts; ++attempt) {
      const SolveStatus status = solve_main_patch(depth);
      if (status == SolveStatus::ZoneTruncated) {
        depth *= kWindowGrowth;
        continue;
      }
      if (status != SolveStatus::Converged) return status;
      if (const SolveStatus recentred = recentre_main_patch(depth); recentred != SolveStatus::Converged) {
        if (recentred == SolveStatus::ZoneTruncated) {
          depth *= kWindowGrowth;
          continue;
        }
        return recentred;
      }
      open_further_patches(depth);
      return solve_further_patches();
    }
    detail_ = "the contact reaches the end of the window after " + std::to_string(kWindowAttempts) +
              " widenings (depth " + number_text(depth / kWindowGrowth) + " m): the profiles end inside the contact";
    return SolveStatus::Converged;
  }

  // The deepest minimum's patch on its own. The gap is sampled with the wheel at the vertical approach dz
  // (PatchProblem::gap_dz): a vertical shift of the wheel is seen along a normal of inclination alpha at a wheel
  // surface of inclination delta_w as dz cos(delta_w) / cos(delta_w - alpha), not dz cos(alpha), because it also
  // slides the wheel along the surface; on a curved patch (flange root) that tilts h(s) (issue 8: +17.7 % area at
  // dy 6.5 mm with h sampled at first contact). A prescribed approach samples at it; a prescribed load repeats the
  // solve with h re-sampled at the solved dz (secant steps on dz) until dz moves by less than
  // kGapApproachTolerance_m and, vertical load, sum N_i cos(alpha_i) matches it (the normal force is rescaled).
  SolveStatus solve_main_patch(double depth) { return solve_main_patch(depth, main_reference()); }

  // The main patch's reference point: the deepest gap minimum, or the prescribed point (WheelRailOptions).
  GapMinimum main_reference() {
    GapMinimum point = ws_.minima[0];
    if (!options_.prescribed_reference) return point;
    point.rail_y_m = options_.prescribed_reference->rail_y_m;
    point.contact_angle_rad = options_.prescribed_reference->contact_angle_rad;
    const WheelSurfacePoint w = builder_.wheel_at(point.rail_y_m, point.wheel_s_m);
    point.rolling_radius_m = w.radius_m;
    return point;
  }
  SolveStatus solve_main_patch(double depth, const GapMinimum& reference) {
    ws_.used = 0;
    PatchProblem& main = ws_.acquire();
    main.reference = reference;
    if (load_ == LoadKind::Approach) {
      main.gap_dz = value_;
      follow_interpenetration_centre(main);
      if (!build_main(main, depth)) return SolveStatus::InvalidInput;
      result_.vertical_approach_m = value_;
      solve_patch_at(main, value_);
    } else if (const SolveStatus status = solve_main_for_load(main, depth); status != SolveStatus::Converged) {
      return status;
    }
    const SolveStatus status = main.solution.status;
    if (!is_success(status) && status != SolveStatus::ZoneTruncated)
      detail_ = patch_failure(options_.method, main.solution, 0);
    return is_success(status) ? SolveStatus::Converged : status;
  }

  bool build_main(PatchProblem& main, double depth) {
    if (!builder_.build(main, depth, options_.sample_step_m)) {
      detail_ = "the patch window at rail y = " + number_text(main.reference.rail_y_m) + " m has fewer than " +
                std::to_string(kMinPatchSamples) + " samples (contact at the end of a profile)";
      return false;
    }
    return prepare(main);
  }

  // Prescribed normal or vertical load on the main patch (solve_main_patch); Converged also when the strip solve
  // failed (main.solution holds why), else InvalidInput or MaxIterations with detail_.
  SolveStatus solve_main_for_load(PatchProblem& main, double depth) {
    // Start from the previous window's or reference point's solve, else from Hertz at the reference minimum. With
    // CONTACT's reference rule a warm chain's neighbours (their sampling approaches extrapolated, the chain start)
    // give the first sampling approach instead: the plane then starts at about the neighbour's centre, where its strip
    // loads apply by index (from Hertz's estimate the centre lay elsewhere and a warm chain saved no iterations).
    // The deepest point keeps the cold start's path (tried: from the chain, half the cases of a 0.01 mm chain settle
    // in the first pass, 2.22 -> 1.62 passes per case, -12 % CPU; but x settles anywhere within
    // kGapApproachTolerance_m of the fixed point, so the tables then differed from cold ones by up to 1e-6 of the
    // strip fields and 4e-7 of a two-point split of the load, against warm_start_test's 1e-8 and 2e-10).
    const double chained_x = options_.reference_at_interpenetration_centre && !options_.prescribed_reference &&
                                     warm_ != nullptr && !ws_.chain_start.empty()
                                 ? ws_.chain_start.sampling_approach_m
                                 : 0.0;
    const double start_x = result_.vertical_approach_m > 0.0 ? result_.vertical_approach_m : chained_x;
    const bool from_hertz = !(start_x > 0.0);
    // The hertz rung is one ellipse from the curvatures at the rigid contact point (as practised in the field): its
    // gap stays sampled at first contact and the passes only balance the load. Re-sampled at the approach, its
    // deepest point (and the ellipse with it) jumped between passes next to the contact jumps: 60 passes without
    // settling at dy 5.205 and 6.675 mm (built-in profiles, single wheel, 78.5 kN).
    const bool fixed_sampling = options_.method == NormalMethod::Hertz;
    main.gap_dz = fixed_sampling ? 0.0
                  : !from_hertz  ? start_x
                                 : expected_approach(side_, main.reference, dy_, roll_, E_star_, load_, value_) /
                                      std::max(std::cos(main.reference.contact_angle_rad), kCosineFloor);
    // MIM-1D on a conformal surface under a vertical load prescribes the vertical load itself (the strips' loads
    // weighted by the cosines of their normals, set_vertical_load_weights): no secant on the normal force, whose share
    // carried vertically a conformal patch does not know beforehand (one held pass in nearly every case before).
    bool vertical_weighted = weighted_vertical_load();
    double force = value_;
    // Fixed point x = dz(x, F) on the sampling approach x, F then rescaled to the vertical load: the next x solves
    // x = dz_pred + slope (x - x_k), dz_pred = dz_k (F_next/F_k)^(2/3) (Hertz: dz ~ F^(2/3)), slope = d dz/dx
    // estimated from the last two passes (0 at first; clamped): secant steps on x - dz(x).
    double previous_x = 0.0, previous_dz = 0.0, previous_force = 0.0;
    double settled_force = 0.0, settled_vertical = 0.0;  // the last pass with x settled
    double previous_angle = main.angle;
    int retries = 0;
    bool held = false;  // the last pass held x (conformal): its gap is still the one sampled
    for (int pass = 0; pass < kGapPasses; ++pass) {
      const GapMinimum sampled_reference = main.reference;
      if (!fixed_sampling && pass < kCentreFollowingPasses) follow_interpenetration_centre(main);
      // A held pass samples at the same approach and reference point as the last: the same gap, so it is not
      // re-sampled (29 % of the conformal default table's samplings).
      const bool same_sampling = held && same_point(sampled_reference, main.reference);
      held = false;
      if (!same_sampling && !build_main(main, depth)) return SolveStatus::InvalidInput;
      // A plane carries the vertical load exactly as F cos(angle): at the first pass, and whenever the plane followed
      // the interpenetration centre to a new angle.
      const bool planar = options_.surface == ContactSurface::Planar;
      if (load_ == LoadKind::VerticalForce && (pass == 0 || (planar && main.angle != previous_angle)))
        force = vertical_weighted ? value_ : value_ / main.c;
      // A strip whose normal leans beyond kCosineFloor carries too little of the vertical load to prescribe it by
      // (none beyond 90 deg): this case balances it by the secant on the normal force instead.
      if (vertical_weighted && !set_vertical_load_weights(main)) {
        vertical_weighted = false;
        main.solver->set_load_weights({});
        force = value_ / main.c;
      }
      previous_angle = main.angle;
      const bool predictor = pass == 0 && from_hertz && !fixed_sampling;
      // A re-solve at a new centre (recentre_main_patch) starts from the last pass: the same contact, its loads moved
      // to the new grid's origin (cold, each took 23-25 iterations in the two-point case at dy 5.51 mm, 135.6 kN).
      const bool from_previous_pass = pass > 0 || (recentring_ && !ws_.pass_start.empty());
      // A pass whose approach lies clearly off its sampling approach will not settle: it only predicts the next x, so
      // its strip solve may stop at kPredictorTolerance there (saves the last Newton step of ~1 in 4 passes: the
      // flank's, where the first-order gap slope misses by ~30 %).
      const Mim1dSolver::EarlyStop unsettled{main.c * (main.gap_dz - kEarlyStopWindow * kGapApproachTolerance_m),
                                             main.c * (main.gap_dz + kEarlyStopWindow * kGapApproachTolerance_m),
                                             kPredictorTolerance};
      solve_main_once(main, force, from_previous_pass, predictor ? kPredictorTolerance : options_.mim1d.tolerance,
                      predictor || fixed_sampling ? nullptr : &unsettled);
      if (!is_success(main.solution.status)) {
        // The strip solve can cycle for one gap and load (max-iterations): after a successful pass, go halfway back
        // towards it (x and F) and on, at most kStripSolveRetries times. (The cycle that once failed at the balancing
        // load itself, dy 5.5 mm, 135.6 kN, was MIM-1D's Newton step missing the compliances' approach term.)
        if (pass == 0 || main.solution.status != SolveStatus::MaxIterations) return SolveStatus::Converged;
        if (++retries > kStripSolveRetries) return SolveStatus::Converged;
        main.gap_dz = 0.5 * (main.gap_dz + previous_x);
        force = 0.5 * (force + previous_force);
        continue;
      }
      const double dz = main.solution.approach_m / main.c;
      result_.vertical_approach_m = dz;
      const double vertical = load_ == LoadKind::VerticalForce ? solution_force(main).vertical_N : value_;
      const bool settled = fixed_sampling || (!predictor && std::abs(dz - main.gap_dz) <= kGapApproachTolerance_m);
      if (settled && std::abs(vertical - value_) <= kVerticalBalance * value_) return SolveStatus::Converged;
      // The force moves only once x has settled (updating both at once alternates, conformal at dy 6.63 mm): a secant
      // step on vertical(F) from the last settled pass, the first time F V / vertical. The predictor pass already
      // takes the ratio step (the share of the load carried vertically hardly depends on x), not recorded for the
      // secant.
      double next_force = force;
      if (predictor && vertical > 0.0 && !vertical_weighted) next_force = force * value_ / vertical;
      if (settled && vertical > 0.0 && !vertical_weighted) {
        next_force = force * value_ / vertical;
        if (settled_force > 0.0 && vertical != settled_vertical) {
          const double secant = force + (value_ - vertical) * (force - settled_force) / (vertical - settled_vertical);
          if (secant > 0.0) next_force = secant;
        }
        settled_force = force;
        settled_vertical = vertical;
      }
      if (fixed_sampling) {
        force = next_force;
        continue;
      }
      // Conformal, x settled and the load nearly balanced: hold x and take the secant on F at this gap alone. Moving x
      // within its 1 nm settling moves the conformal surface's vertical load by up to 1e-5 of it on the flank, so
      // re-predicting x at every step left the secant on noise (CONTACT's rule, dy 6.65-6.82 mm, vertical load: 60
      // passes without balancing to 1e-10, 370 of 576 240 sweep cases); the next pass checks that x is still settled.
      // (A plane carries F cos(angle) exactly; planar tables are unchanged by this.)
      if (!planar && !vertical_weighted && settled && std::abs(vertical - value_) <= kHoldSamplingWindow * value_) {
        held = true;
        shift_pass_start(main, 0.0, next_force - force);
        previous_x = main.gap_dz;
        previous_dz = dz;
        previous_force = force;
        force = next_force;
        continue;
      }
      // The secant measures the slope where it can (it also sees what the first-order geometry misses: the conformal
      // surface moving with x, an active set that changes; measured at dy 6.3 mm conformal: secant -0.68, geometry
      // +0.002); the first pass takes it from the geometry (gap_slope) instead of 0.
      double slope = 0.0;
      if (pass > 0 && main.gap_dz != previous_x) {
        const double at_this_force = previous_dz * std::cbrt(std::pow(force / previous_force, 2.0));
        slope = std::clamp((dz - at_this_force) / (main.gap_dz - previous_x), kMinGapSlope, kMaxGapSlope);
      } else if (const std::optional<double> geometric = gap_slope(main)) {
        slope = std::clamp(*geometric, kMinGapSlope, kMaxGapSlope);
      }
      // dz ~ F^q: Hertz q = 2/3; MIM-1D the local exponent from the strip solve (approach_sensitivity with dF).
      double exponent = 2.0 / 3.0;
      if (next_force != force && dz > 0.0)
        if (const std::optional<double> per_load = load_rate(main); per_load && *per_load > 0.0)
          exponent = *per_load * force / dz;
      const double predicted = dz * std::pow(next_force / force, exponent);
      double next_x = (predicted - slope * main.gap_dz) / (1.0 - slope);
      // The first sampling approach can lie far beyond the solved one (dz < 0: the reference point's angle
      // overstated the normal force, flank reference with the load on the root; conformal, dy 6.65 mm, 48.9 kN:
      // x 0.43 mm, dz -8 um), where the prediction runs to x <= 0: halve x instead.
      if (!(next_x > 0.0 && std::isfinite(next_x))) next_x = kSamplingApproachCut * main.gap_dz;
      const double next_origin = pass + 1 < kCentreFollowingPasses ? next_grid_origin(main, next_x) : main.origin_y;
      shift_pass_start(main, next_x - main.gap_dz, next_force - force, next_origin);
      previous_x = main.gap_dz;
      previous_dz = dz;
      previous_force = force;
      main.gap_dz = next_x;
      force = next_force;
    }
    detail_ =
        "the vertical approach at which the gap is sampled did not settle in " + std::to_string(kGapPasses) + " passes";
    return SolveStatus::MaxIterations;
  }

  // d dz / d x of the solved approach dz on the sampling approach x at this force, to first order: every strip's h
  // (sampled at x, plus x c) moves by c - w_i (w_i = PatchProblem::approach_weight at the strip), and the strip
  // solver turns that into d delta = c d dz (Mim1dSolver::approach_sensitivity). Empty for the other rungs.
  std::optional<double> gap_slope(PatchProblem& p) const {
    if (options_.method != NormalMethod::Mim1d || !p.solver) return std::nullopt;
    fill_strip_gap_rate(p, 1.0);
    const std::optional<double> approach_rate = p.solver->approach_sensitivity(p.strip_gap_rate);
    if (!approach_rate) return std::nullopt;
    return *approach_rate / p.c;
  }

  // p.strip_gap_rate: the change of every strip's h (sampled at gap_dz, plus gap_dz c) when gap_dz moves by dx.
  static void fill_strip_gap_rate(PatchProblem& p, double dx) {
    const StripGrid& grid = p.solver->grid();
    p.strip_gap_rate.resize(grid.size());
    ForwardInterpolation weight(p.gap.y_m, p.approach_weight);
    for (std::size_t i = 0; i < grid.size(); ++i) p.strip_gap_rate[i] = dx * (p.c - weight(grid.y_m[i]));
  }

  // The next pass's warm start: the last solve moved to first order to the next sampling approach (x + dx) and
  // normal force (F + dF), so that the confirming pass starts next to its solution (Mim1dSolver::shift_warm_start).
  // With a grid origin that moves to rail y next_origin_y (the conformal grid following the centre), strip k then
  // lies where this pass's s was s_k + ds, ds the new origin's s: its separation changes by h(s_k + ds) - h(s_k)
  // and its load stays by index. Re-sampling the loads onto the moved grid instead (start_on_grid) cost 1.45x the
  // MIM-1D iterations of a fixed grid on the conformal default table (3740 against 2585); a move beyond half a strip,
  // or a failed prediction, still takes that way.
  void shift_pass_start(PatchProblem& p, double dx, double dF,
                        double next_origin_y = std::numeric_limits<double>::quiet_NaN()) {
    if (options_.method != NormalMethod::Mim1d || !p.solver || ws_.pass_start.empty()) return;
    fill_strip_gap_rate(p, dx);
    const bool moves = add_grid_move(p, next_origin_y);
    if (p.solver->shift_warm_start(p.strip_gap_rate, dF, ws_.pass_start) && moves)
      ws_.pass_start.origin_y_m = next_origin_y;
  }

  // shift_pass_start's separation change of a grid origin moving to rail y next_origin_y; false where it does not
  // move or moves too far for the first order.
  bool add_grid_move(PatchProblem& p, double next_origin_y) const {
    const double from_y = p.grid_origin_y();
    if (!std::isfinite(next_origin_y) || next_origin_y == from_y) return false;
    if (!p.window_holds(from_y) || !p.window_holds(next_origin_y)) return false;
    const double ds = interpolate(p.rail_y, p.gap.y_m, next_origin_y) - interpolate(p.rail_y, p.gap.y_m, from_y);
    const StripGrid& grid = p.solver->grid();
    if (!(std::abs(ds) < kPredictedGridMove * grid.strip_width_m)) return false;
    ForwardInterpolation moved(p.gap.y_m, p.gap.h_m), here(p.gap.y_m, p.gap.h_m);
    for (std::size_t i = 0; i < grid.size(); ++i) p.strip_gap_rate[i] += moved(grid.y_m[i] + ds) - here(grid.y_m[i]);
    return true;
  }

  // The grid origin (rail y) of a pass at sampling approach x: the centre there where the conformal grid follows it,
  // else the present one.
  double next_grid_origin(const PatchProblem& p, double x) const {
    GapMinimum centre;
    if (!centres_conformal_grid() || !centre_at(x, centre)) return p.origin_y;
    return centre.rail_y_m;
  }

  // d dz / d F of the main patch's last strip solve at the same sampling approach [m/N]; empty for the other rungs.
  std::optional<double> load_rate(PatchProblem& p) const {
    if (options_.method != NormalMethod::Mim1d || !p.solver) return std::nullopt;
    fill_strip_gap_rate(p, 0.0);
    const std::optional<double> approach_rate = p.solver->approach_sensitivity(p.strip_gap_rate, 1.0);
    if (!approach_rate) return std::nullopt;
    return *approach_rate / p.c;
  }

  // One strip solve of the main patch: warm-started from the neighbour (pass 0, when given) or from the last
  // successful pass of this case (kept through a failed pass, so that a retry starts from it), else cold; MIM-1D to
  // the relative tolerance given (kPredictorTolerance for a first pass that only predicts).
  void solve_main_once(PatchProblem& main, double force, bool from_previous_pass, double tolerance,
                       const Mim1dSolver::EarlyStop* early_stop = nullptr) {
    if (options_.method != NormalMethod::Mim1d) {
      main.solution = solve_other_rung(main, Loading::normal_force(force));
    } else {
      static const Mim1dWarmStart cold;
      // The chain's start on this grid where the conformal grid follows the centre: a neighbour's centre lies up to
      // a strip away from the one at this case's first sampling approach (by strip index alone, a 0.01 mm chain took
      // 605 MIM-1D iterations against 568 cold; warm_start_test).
      const Mim1dWarmStart& start = from_previous_pass         ? start_on_grid(ws_.pass_start, main)
                                    : warm_ == nullptr         ? cold
                                    : centres_conformal_grid() ? start_on_grid(ws_.chain_start, main)
                                                               : ws_.chain_start;
      main.solution = early_stop != nullptr ? main.solver->solve_for_load(force, start, tolerance, *early_stop)
                                            : main.solver->solve_for_load(force, start, tolerance);
    }
    if (options_.method == NormalMethod::Mim1d && is_success(main.solution.status)) {
      main.solver->save_warm_start(main.solution, ws_.pass_start);
      ws_.pass_start.origin_y_m = main.grid_origin_y();
      ws_.pass_start.origin_angle_rad = main.angle;
      ws_.pass_start.same_contact = true;
    }
    result_.iterations += main.solution.iterations;
    result_.matrix_entries += main.solution.matrix_entries;
  }

  // A saved solution (the previous pass's) on this pass's grid: where the plane followed the interpenetration centre,
  // its loads are moved to the same places on the rail (the contact has not moved, only the grid's origin); by strip
  // index alone they were up to a strip off and the pass took 4-7 MIM-1D iterations instead of 2-3.
  const Mim1dWarmStart& start_on_grid(const Mim1dWarmStart& saved, const PatchProblem& main) {
    const double origin_y = main.grid_origin_y();
    if (saved.empty() || (saved.origin_y_m == origin_y && saved.origin_angle_rad == main.angle)) return saved;
    const double shift_m = (origin_y - saved.origin_y_m) / std::cos(0.5 * (main.angle + saved.origin_angle_rad));
    move_warm_start_origin(saved, shift_m, options_.mim1d.strip_width_m, ws_.moved_start);
    return ws_.moved_start;
  }

  bool weighted_vertical_load() const {
    return options_.method == NormalMethod::Mim1d && options_.surface == ContactSurface::Conformal &&
           load_ == LoadKind::VerticalForce;
  }

  // The main patch's solver prescribes sum N_i cos(alpha_i), alpha_i each strip's normal as run_force takes it;
  // false (nothing set) where a normal leans beyond kCosineFloor.
  bool set_vertical_load_weights(PatchProblem& main) {
    const StripGrid& grid = main.solver->grid();
    main.load_weight.resize(grid.size());
    ForwardInterpolation normal_angle(main.gap.y_m, main.normal_angle);
    for (std::size_t i = 0; i < grid.size(); ++i) {
      main.load_weight[i] = std::cos(normal_angle(grid.y_m[i]));
      if (!(main.load_weight[i] > kCosineFloor)) return false;
    }
    main.solver->set_load_weights(main.load_weight);
    return true;
  }

  ForceComponents solution_force(const PatchProblem& p) const {
    ForceComponents total;
    for (const PatchSolution& run : p.solution.patches) {
      const ForceComponents f = run_force(p, run);
      total.lateral_N += f.lateral_N;
      total.vertical_N += f.vertical_N;
    }
    return total;
  }

  // With CONTACT's reference rule every gap pass samples in the plane at the interpenetration centre of its own
  // sampling approach, so the passes settle the approach and the reference point together (one fixed point); before,
  // the whole load solve was repeated at each new centre (2.2x the CPU of the deepest point on the default table).
  // With CONTACT's reference angle at the deepest point only the plane's inclination follows: the passes then settle
  // the approach alone (a plane's gap is the same through any of its points; the point places the strip grid).
  // The conformal surface at the deepest point centres its strip grid on the centre at each pass's sampling approach
  // (CONTACT's grid: its strip k is CONTACT's row k) and keeps the deepest point as the contact point: its surface
  // does not depend on the point it is marched from, so the point only places the grid. From the deepest point's own
  // grid the flank's p0 profile was 9.8 % RMS off CONTACT's rows (dy 7.5 mm, vertical load; target 5 %). Centred once,
  // at the first sampling approach, the grid depended on the path (a load solve and an approach solve at its settled
  // approach 2.5e-3 of the load apart at dy 5.2 mm, gap_passes_test); shift_pass_start moves the warm start with it.
  void follow_interpenetration_centre(PatchProblem& main) const {
    if (!follows_centre()) return;
    GapMinimum centre;
    if (!centre_at(main.gap_dz, centre)) return;
    if (options_.reference_at_interpenetration_centre) {
      main.reference = centre;
      return;
    }
    if (options_.interpenetration_mean_angle()) main.reference.contact_angle_rad = centre.contact_angle_rad;
    if (centres_conformal_grid()) main.origin_y = centre.rail_y_m;
  }

  bool follows_centre() const {
    return !options_.prescribed_reference && !recentring_ &&
           (options_.interpenetration_mean_angle() || centres_conformal_grid());
  }
  // The conformal surface at the deepest point centres its strips on CONTACT's reference point (the grid's origin).
  bool centres_conformal_grid() const {
    return options_.surface == ContactSurface::Conformal && !options_.reference_at_interpenetration_centre;
  }

  // interpenetration_centre at approach x, kept for the next call at the same x (a pass predicts the next pass's
  // grid at the approach that pass then samples at).
  bool centre_at(double x, GapMinimum& centre) const {
    if (x != centre_cache_.approach_m) {
      centre_cache_.approach_m = x;
      centre_cache_.centre = ws_.minima[0];
      centre_cache_.found = interpenetration_centre(centre_cache_.centre, x);
    }
    centre = centre_cache_.centre;
    return centre_cache_.found;
  }

  // CONTACT's contact reference point (m_wr_locatecp step 5): the centre of the interpenetration region at the
  // current vertical approach, weighted by the squared gap integrated along x (~ pen^(5/2) for gap(x) = -pen +
  // A x^2), not the deepest rigid point. Against CONTACT's planar reference points at dy 6.5 and 7.5 mm this
  // weight agrees within 0.013 mm, the weight integral(-gap) dx ~ pen^(3/2) only within 0.12 mm. On the flank a
  // rail arc (13 mm) meets the straight 70 deg wheel flank: the deepest point is where the rail slope is -70 deg for
  // every dy, while the interpenetration region, measured vertically, is lopsided and its centre moves with the
  // approach. The main patch is re-solved in the plane at that centre until the reference point moves by less than
  // kRecentreTolerance_m (at most kRecentrePasses passes).
  //
  // The re-solves are secant steps on the fixed point c = C(c) (C: the centre at the approach solved in the plane at
  // c): where one region spans tread and flange root the centre moves by about 30 m per m of approach and C has a
  // slope near -1 (measured -0.94 at dy 5.51 mm, 135.6 kN), so plain re-solves alternated between two centres
  // 6.7 um apart until kRecentrePasses ran out.
  SolveStatus recentre_main_patch(double depth) {
    if (!options_.reference_at_interpenetration_centre || options_.prescribed_reference) return SolveStatus::Converged;
    GapMinimum previous_at{}, previous_centre{};
    for (int pass = 0; pass < kRecentrePasses; ++pass) {
      const GapMinimum at = ws_.pool[0].reference;
      GapMinimum centre = ws_.minima[0];
      if (!interpenetration_centre(centre, result_.vertical_approach_m)) return SolveStatus::Converged;
      if (std::abs(centre.rail_y_m - at.rail_y_m) < kRecentreTolerance_m) return SolveStatus::Converged;
      GapMinimum next = centre;
      const double moved = at.rail_y_m - previous_at.rail_y_m;
      if (pass > 0 && moved != 0.0) {
        const double slope = std::min((centre.rail_y_m - previous_centre.rail_y_m) / moved, kMaxCentreSlope);
        if (!secant_centre(at, centre, 1.0 / (1.0 - slope), next)) next = centre;
      }
      previous_at = at;
      previous_centre = centre;
      recentring_ = true;  // the plane stays at this centre through the re-solve's passes
      const SolveStatus status = solve_main_patch(depth, next);
      recentring_ = false;
      if (status != SolveStatus::Converged) return status;
    }
    return SolveStatus::Converged;
  }

  // at + step (centre - at) on the wheel parameter and the plane angle, the rail point and radius from the wheel
  // point there; false when it leaves the profiles.
  bool secant_centre(const GapMinimum& at, const GapMinimum& centre, double step, GapMinimum& out) const {
    out = centre;
    out.wheel_s_m = at.wheel_s_m + step * (centre.wheel_s_m - at.wheel_s_m);
    out.contact_angle_rad = at.contact_angle_rad + step * (centre.contact_angle_rad - at.contact_angle_rad);
    if (!side_.wheel().contains(out.wheel_s_m)) return false;
    const WheelSurfacePoint w = side_.wheel_point(out.wheel_s_m, dy_, roll_);
    if (!side_.rail().contains(w.rail_y_m)) return false;
    out.rail_y_m = w.rail_y_m;
    out.rolling_radius_m = w.radius_m;
    return true;
  }

  // Weighted centre of the contiguous interpenetration region around the deepest minimum, on the wheel parameter S,
  // and CONTACT's reference angle: the mean of the rail's inclination over the region with the same weights, not the
  // inclination at the centre. Measured against CONTACT's planar results (flange_reference_test): the inclination at
  // the centre was 0.33-0.38 deg shallower at the root (dy 6.5 mm) and 0.27 deg at the flank (7.5 mm), where the
  // rail's 13 mm arc turns the slope non-linearly across the region; at dy 5.5 mm, where the region spans tread and
  // flange root (CONTACT combines them into one patch), the centre's own inclination was 2.6 deg too shallow, and
  // keeping the deepest point instead 1.5 deg too steep. The weighted mean meets CONTACT's reference angle within
  // 0.012 deg in all six planar cases. False when the region holds fewer than three samples at the finest step (1 um).
  bool interpenetration_centre(GapMinimum& point, double approach_m) const {
    // Samples at the rigid scan's step, refined until the region holds kCentreSamples (the sums are smooth
    // quadratures of pen^(5/2), which vanishes at the region's edges); a fixed 10 um step cost a third of the default
    // table's CPU on the 10-15 mm wide tread regions.
    double step = SideGeometry::kScanStep_m;
    CentreSums sums = centre_sums(point.wheel_s_m, approach_m, step);
    while (sums.samples < kCentreSamples && step > kFinestCentreStep_m) {
      step = std::max(kFinestCentreStep_m, step * std::max(sums.samples, 1) / kCentreSamples);
      sums = centre_sums(point.wheel_s_m, approach_m, step);
    }
    if (sums.samples < 3 || !(sums.weight > 0.0)) return false;
    point.wheel_s_m = sums.moment / sums.weight;
    const WheelSurfacePoint w = side_.wheel_point(point.wheel_s_m, dy_, roll_);
    if (!side_.rail().contains(w.rail_y_m)) return false;
    point.rail_y_m = w.rail_y_m;
    point.contact_angle_rad = sums.angle_moment / sums.weight;
    point.rolling_radius_m = w.radius_m;
    return true;
  }

  // The weights pen^(5/2) (integral of gap^2 along x) over the contiguous interpenetration region around the wheel
  // parameter s0 at this step, with their moments in s and in the rail's inclination.
  struct CentreSums {
    double weight = 0.0, moment = 0.0, angle_moment = 0.0;
    int samples = 0;
  };
  CentreSums centre_sums(double s0, double approach_m, double step) const {
    const double z_first = result_.first_contact_z_m - side_.track().nominal_radius_m;
    CentreSums sums;
    for (int direction : {-1, +1})
      for (int k = direction < 0 ? 1 : 0; k < kMaxSamplesPerSide * 10; ++k) {
        const double s = s0 + direction * step * k;
        if (!side_.wheel().contains(s)) break;
        const double penetration = approach_m - (side_.gap(s, dy_, roll_) - z_first);
        if (!(penetration > 0.0)) break;
        const double rail_y = side_.wheel_point(s, dy_, roll_).rail_y_m;
        if (!side_.rail().contains(rail_y)) break;
        const double weight = penetration * penetration * std::sqrt(penetration);
        sums.weight += weight;
        sums.moment += weight * s;
        sums.angle_moment += weight * std::atan(side_.rail().at(rail_y).dz);
        ++sums.samples;
      }
    return sums;
  }

  // Only MIM-1D keeps a strip solver per patch (reused from case to case); the other rungs are one-shot.
  bool prepare(PatchProblem& p) {
    if (options_.method != NormalMethod::Mim1d) return true;
    detail_ = prepare_mim1d_solver(p.solver, p.gap, E_star_, options_.mim1d);
    return detail_.empty();
  }

  // Further patches: minima outside every window whose gap the approach closes.
  void open_further_patches(double depth) {
    for (std::size_t k = 1; k < ws_.minima.size(); ++k) {
      const GapMinimum& m = ws_.minima[k];
      if (m.gap_m >= result_.vertical_approach_m || inside_window(m)) continue;
      PatchProblem& extra = ws_.acquire();
      extra.reference = m;
      extra.gap_dz = result_.vertical_approach_m;
      if (!builder_.build(extra, m.gap_m + depth, options_.sample_step_m) || !prepare(extra))
        --ws_.used;  // give the slot back
    }
    detail_.clear();  // a minimum that could not open a patch stays a near miss
  }

  // With several patches a prescribed force is shared through one vertical approach (root finder).
  SolveStatus solve_further_patches() {
    if (ws_.used < 2) return SolveStatus::Converged;
    if (load_ == LoadKind::Approach) {
      for (std::size_t k = 1; k < ws_.used; ++k) solve_patch_at(ws_.pool[k], value_);
      return SolveStatus::Converged;
    }
    auto mismatch = [&](double dz) { return load_at(dz) - value_; };
    const double hi = result_.vertical_approach_m;
    const RootResult root =
        find_root_bracketed(mismatch, 0.0, -value_, hi, mismatch(hi), kSharedApproachTolerance_m,
                            options_.mim1d.tolerance * value_ * kSharedForceToleranceFactor, kSharedApproachIterations);
    if (!root.converged) {
      detail_ = "the vertical approach shared by " + std::to_string(ws_.used) + " patches did not converge in " +
                std::to_string(kSharedApproachIterations) + " root-finding steps";
      return SolveStatus::MaxIterations;
    }
    result_.vertical_approach_m = root.x;
    (void)load_at(root.x);
    return SolveStatus::Converged;
  }

  // Total normal or vertical load of all patches at vertical approach dz [N].
  double load_at(double dz) {
    double sum = 0.0;
    for (std::size_t k = 0; k < ws_.used; ++k) {
      PatchProblem& p = ws_.pool[k];
      solve_patch_at(p, dz);
      if (!is_success(p.solution.status)) continue;
      if (load_ != LoadKind::VerticalForce) sum += p.solution.normal_load_N;
      else
        for (const PatchSolution& run : p.solution.patches) sum += run_force(p, run).vertical_N;
    }
    return sum;
  }

  // Solves patch p at vertical approach dz, its gap re-sampled there first (solve_main_patch).
  void solve_patch_at(PatchProblem& p, double vertical_approach) {
    if (p.gap_dz != vertical_approach) {
      p.gap_dz = vertical_approach;
      if (!builder_.build(p, p.window_depth, options_.sample_step_m) || !prepare(p)) {
        p.solution = NormalSolution{};
        p.solution.status = SolveStatus::InvalidInput;
        return;
      }
    }
    const double approach = vertical_approach * p.c;
    p.solution = options_.method == NormalMethod::Mim1d ? p.solver->solve_for_approach(approach)
                                                        : solve_other_rung(p, Loading::approach(approach));
    result_.iterations += p.solution.iterations;
    result_.matrix_entries += p.solution.matrix_entries;
  }

  // A rung other than MIM-1D on a patch's strip problem (normal_contact.hpp).
  NormalSolution solve_other_rung(const PatchProblem& p, Loading loading) const {
    MethodOptions method;
    method.method = options_.method;
    method.E_star_Pa = E_star_;
    method.strip_width_m = options_.mim1d.strip_width_m;
    method.bem2d_alignment = options_.bem2d_alignment;
    method.bem2d_element_length_m = options_.bem2d_element_length_m;
    return solve_normal_contact(p.gap, method, loading);
  }

  bool inside_window(const GapMinimum& m) const {
    for (std::size_t k = 0; k < ws_.used; ++k) {
      const PatchProblem& p = ws_.pool[k];
      if (!p.rail_y.empty() && m.rail_y_m >= p.rail_y.front() && m.rail_y_m <= p.rail_y.back()) return true;
    }
    return false;
  }

  // Every loaded run of strips of every patch becomes a ContactPatch; the status is the last failing patch's.
  SolveStatus collect_patches() {
    SolveStatus status = SolveStatus::Converged;
    for (std::size_t slot = 0; slot < ws_.used; ++slot) {
      const PatchProblem& p = ws_.pool[slot];
      if (p.solution.status == SolveStatus::NoContact) continue;
      if (!is_success(p.solution.status)) {
        status = p.solution.status;
        if (detail_.empty() || p.solution.status != SolveStatus::ZoneTruncated)
          detail_ = patch_failure(options_.method, p.solution, slot);
      }
      for (const PatchSolution& ps : p.solution.patches) add_patch(p, ps);
    }
    if (result_.patches.empty() && status == SolveStatus::Converged) {
      // An approach too small to reach any strip centre (e.g. 1 nm) is no contact, as on a gap file.
      if (all_patches_out_of_contact()) return SolveStatus::NoContact;
      detail_ = "no loaded strip in any patch";
      status = SolveStatus::NumericalFailure;
    }
    return status;
  }

  // The loaded patches' extents in their contact planes (resolution.hpp).
  std::vector<PatchExtent> patch_extents() const {
    std::vector<PatchExtent> extents;
    for (const ContactPatch& p : result_.patches)
      extents.push_back(patch_extent(p.s_max_m - p.s_min_m, p.normal_force_N, p.strips));
    return extents;
  }

  bool all_patches_out_of_contact() const {
    for (std::size_t slot = 0; slot < ws_.used; ++slot)
      if (ws_.pool[slot].solution.status != SolveStatus::NoContact) return false;
    return true;
  }

  void add_patch(const PatchProblem& p, const PatchSolution& ps) {
    const GapMinimum point = contact_point(p, ps);
    ContactPatch out;
    out.zone = point.wheel_s_m > kFlangeRootS_m ? "tread" : "flange";
    out.normal_force_N = ps.normal_force_N;
    out.area_m2 = ps.area_m2;
    out.max_pressure_Pa = ps.max_pressure_Pa;
    out.approach_m = p.solution.approach_m;
    out.plane_angle_rad = p.angle;
    out.y_rail_m = point.rail_y_m;
    out.y_wheel_m = point.wheel_s_m;
    out.rolling_radius_m = point.rolling_radius_m;
    out.y_cop_rail_m = interpolate(p.gap.y_m, p.rail_y, ps.centre_of_pressure_y_m);
    out.s_min_m = ps.y_min_m;
    out.s_max_m = ps.y_max_m;
    // Planar contact angle: direction of the resultant normal force, the load-weighted mean of the rail normals.
    double weighted_angle = 0.0, weighted_y = 0.0;
    for (const StripSolution& st : ps.strips) {
      const double y = interpolate(p.gap.y_m, p.rail_y, st.y_m);
      out.strips.push_back({st.y_m, y, st.half_length_m, st.p0_Pa});
      weighted_angle += st.load_N * std::atan(side_.rail().at(y).dz);
      weighted_y += st.load_N * y;
    }
    out.contact_angle_rad = weighted_angle / ps.normal_force_N;
    result_.normal_force_N += out.normal_force_N;
    const ForceComponents force = run_force(p, ps);
    out.force_lateral_N = force.lateral_N;
    out.force_vertical_N = force.vertical_N;
    if (options_.surface == ContactSurface::Conformal) {
      // Conformal: the resultant of the strips' own normals, and CONTACT's y_cop_rail (sum q_i y_i / sum q_i over
      // the strips' points on the curved surface).
      out.contact_angle_rad = std::atan2(-force.lateral_N, force.vertical_N);
      out.y_cop_rail_m = weighted_y / ps.normal_force_N;
      out.s_origin_y_rail_m = interpolate(p.gap.y_m, p.rail_y, 0.0);
    }
    result_.vertical_force_N += out.force_vertical_N;
    result_.patches.push_back(std::move(out));
  }

  // Contact point of a run of strips: its deepest rigid point (the reference minimum for the run that holds it).
  GapMinimum contact_point(const PatchProblem& p, const PatchSolution& ps) const {
    std::size_t deepest = p.gap.size();
    for (std::size_t i = 0; i < p.gap.size(); ++i)
      if (p.gap.y_m[i] >= ps.y_min_m && p.gap.y_m[i] <= ps.y_max_m &&
          (deepest == p.gap.size() || p.gap.h_m[i] < p.gap.h_m[deepest]))
        deepest = i;
    const bool holds_reference = ps.y_min_m <= p.reference_s && ps.y_max_m >= p.reference_s;
    GapMinimum point = p.reference;
    if (!holds_reference && deepest < p.gap.size()) {
      double s_guess = p.reference.wheel_s_m;
      point.rail_y_m = p.rail_y[deepest];
      (void)builder_.wheel_at(point.rail_y_m, s_guess);
      point.wheel_s_m = s_guess;
      point.rolling_radius_m = side_.track().nominal_radius_m + side_.wheel().at(s_guess).z;
    }
    return point;
  }

  void collect_near_misses() {
    for (std::size_t k = 1; k < ws_.minima.size(); ++k)
      if (ws_.minima[k].gap_m >= result_.vertical_approach_m && !inside_window(ws_.minima[k]))
        result_.near_misses.push_back(ws_.minima[k]);
  }

  // The main patch's last solve as the next shift's warm start (cleared when this case failed).
  void save_warm_start(SolveStatus status) {
    if (warm_ == nullptr) return;
    const PatchProblem* main = ws_.used > 0 ? &ws_.pool[0] : nullptr;
    if (is_success(status) && main != nullptr && main->solver && options_.method == NormalMethod::Mim1d) {
      warm_->push_back_to_earlier();  // the next shift extrapolates from this case and the one before
      main->solver->save_warm_start(main->solution, *warm_);
      warm_->origin_y_m = main->grid_origin_y();
      warm_->origin_angle_rad = main->angle;
      warm_->sampling_approach_m = main->gap_dz;
      warm_->same_contact = false;  // the next shift's contact
    } else {
      warm_->clear();
    }
  }

  WheelContact finish(SolveStatus status, std::string detail = {}) {
    save_warm_start(status);
    result_.status = resolution_status(status, options_.method, patch_extents(), options_.mim1d.strip_width_m);
    if (!is_success(status)) {
      result_.patches.clear();
      result_.detail = detail.empty() ? status_name(status) : std::move(detail);
    }
    result_.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return std::move(result_);
  }

  const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  const SideGeometry& side_;
  double dy_, roll_, E_star_;
  LoadKind load_;
  double value_;
  const WheelRailOptions& options_;
  WheelContactWorkspace::Impl& ws_;
  Mim1dWarmStart* warm_;     // in/out, or null: cold
  bool recentring_ = false;  // recentre_main_patch's re-solve: the gap passes keep its plane
  struct CentreCache {
    double approach_m = std::numeric_limits<double>::quiet_NaN();
    GapMinimum centre;
    bool found = false;
  };
  mutable CentreCache centre_cache_;  // centre_at's last centre
  PatchBuilder builder_;
  WheelContact result_;
  std::string detail_;  // why the case failed (empty while it has not)
};

}  // namespace

WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                 LoadKind load, double load_value, const WheelRailOptions& options,
                                 WheelContactWorkspace& workspace) {
  return WheelCase(side, dy_m, roll_rad, E_star_Pa, load, load_value, options, workspace.impl(), nullptr).solve();
}

WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa,
                                 LoadKind load, double load_value, const WheelRailOptions& options,
                                 WheelContactWorkspace& workspace, Mim1dWarmStart& warm_start) {
  return WheelCase(side, dy_m, roll_rad, E_star_Pa, load, load_value, options, workspace.impl(), &warm_start).solve();
}

StripWidthTotals resolve_at_strip_width(WheelContactWorkspace& workspace, double E_star_Pa,
                                        const Mim1dOptions& options) noexcept {
  WheelContactWorkspace::Impl& ws = workspace.impl();
  StripWidthTotals totals;
  for (std::size_t k = 0; k < ws.used; ++k) {
    const PatchProblem& p = ws.pool[k];
    double force_N = 0.0;
    for (const PatchSolution& run : p.solution.patches) force_N += run.normal_force_N;
    if (!is_success(p.solution.status) || !(force_N > 0.0)) continue;
    if (!prepare_mim1d_solver(ws.other_width, p.gap, E_star_Pa, options).empty()) return {};
    const NormalSolution solution = ws.other_width->solve_for_load(force_N, Mim1dWarmStart{}, options.tolerance);
    if (!is_success(solution.status)) return {};
    totals.matrix_entries += solution.matrix_entries;
    for (const PatchSolution& run : solution.patches) {
      totals.area_m2 += run.area_m2;
      totals.max_pressure_Pa = std::max(totals.max_pressure_Pa, run.max_pressure_Pa);
    }
    totals.solved = true;
  }
  return totals;
}

}  // namespace ctab::gen
