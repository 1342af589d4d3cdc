// SPDX-License-Identifier: Apache-2.0
#include "gap_passes.hpp"

#include <algorithm>
#include <cmath>

#include "centre_following.hpp"
#include "main_patch_strips.hpp"
#include "patch_forces.hpp"
#include "wheelrail_tuning.hpp"

namespace ctab::gen {

using namespace tuning;

namespace {

// What one successful pass solved.
struct PassOutcome {
  double dz = 0.0;        // the solved vertical approach [m]
  double vertical = 0.0;  // the vertical load it carries (normal load: the prescribed value) [N]
  bool settled = false;   // dz within kGapApproachTolerance_m of the sampling approach
};

// The passes of one case. Each pass: sample the gap at x, prescribe the force, solve, then either stop (settled and
// balanced), retry a failed strip solve, step the force, hold x, or step x.
class GapPasses {
 public:
  GapPasses(WheelCase& c, PatchProblem& main) : c_(c), main_(main) {}

  SolveStatus run(double depth) {
    start();
    for (int pass = 0; pass < kGapPasses; ++pass) {
      if (!sample(pass, depth)) return SolveStatus::InvalidInput;
      prescribe_force(pass);
      const bool predictor = solve(pass);
      if (!is_success(main_.solution.status)) {
        if (!retry_halfway(pass)) return SolveStatus::Converged;
        continue;
      }
      const PassOutcome outcome = measure(predictor);
      if (outcome.settled && std::abs(outcome.vertical - c_.load_value) <= kVerticalBalance * c_.load_value)
        return SolveStatus::Converged;
      const double next_force = force_step(predictor, outcome);
      if (fixed_sampling_) {
        force_ = next_force;
        continue;
      }
      if (hold_sampling(outcome, next_force)) continue;
      step_sampling_approach(pass, outcome.dz, next_force);
    }
    c_.detail =
        "the vertical approach at which the gap is sampled did not settle in " + std::to_string(kGapPasses) + " passes";
    return SolveStatus::MaxIterations;
  }

 private:
  // The first sampling approach: the previous window's or reference point's solve, else (CONTACT's reference rule in
  // a warm chain) the neighbours' sampling approaches extrapolated, so that the plane starts at about the neighbour's
  // centre where its strip loads apply by index; else from Hertz at the reference minimum. The deepest point keeps
  // the cold start's path: x settles anywhere within kGapApproachTolerance_m of the fixed point, so a chained start
  // would make warm and cold tables differ by more than the solver's tolerance.
  void start() {
    const double chained_x = c_.options.at_interpenetration_centre() && c_.warm != nullptr && !c_.ws.chain_start.empty()
                                 ? c_.ws.chain_start.sampling_approach_m
                                 : 0.0;
    const double start_x = c_.result.vertical_approach_m > 0.0 ? c_.result.vertical_approach_m : chained_x;
    from_hertz_ = !(start_x > 0.0);
    main_.gap_dz = fixed_sampling_ ? 0.0
                   : !from_hertz_  ? start_x
                                   : expected_approach(c_.side, main_.reference, c_.dy_m, c_.roll_rad, c_.E_star_Pa,
                                                       c_.load, c_.load_value) /
                                        std::max(std::cos(main_.reference.contact_angle_rad), kCosineFloor);
    vertical_weighted_ = weighted_vertical_load(c_);
    force_ = c_.load_value;
    previous_angle_ = main_.angle;
  }

  // Re-samples the gap at this pass's approach and reference point (the centre followed for the first
  // kCentreFollowingPasses passes). A pass after one that held x samples the same gap and is not re-sampled.
  bool sample(int pass, double depth) {
    const GapMinimum sampled_reference = main_.reference;
    if (!fixed_sampling_ && pass < kCentreFollowingPasses) follow_interpenetration_centre(c_, main_);
    const bool same_sampling = held_ && same_point(sampled_reference, main_.reference);
    held_ = false;
    return same_sampling || build_main(c_, main_, depth);
  }

  // A plane carries the vertical load exactly as F cos(angle): the force is set at the first pass and whenever the
  // plane followed the interpenetration centre to a new angle. A strip whose normal leans beyond kCosineFloor
  // carries too little of the vertical load to prescribe it by (none beyond 90 deg): that case balances it by the
  // secant on the normal force instead.
  void prescribe_force(int pass) {
    if (c_.load == LoadKind::VerticalForce && (pass == 0 || (planar_ && main_.angle != previous_angle_)))
      force_ = vertical_weighted_ ? c_.load_value : c_.load_value / main_.c;
    if (vertical_weighted_ && !set_vertical_load_weights(main_)) {
      vertical_weighted_ = false;
      main_.solver->set_load_weights({});
      force_ = c_.load_value / main_.c;
    }
    previous_angle_ = main_.angle;
  }

  // The strip solve; true for a predictor pass (the first from the Hertz estimate, solved to kPredictorTolerance). A
  // re-solve at a new centre (recentre_main_patch) starts from the last pass: the same contact, its loads moved to the
  // new grid's origin. A pass whose approach lies clearly off its sampling approach only predicts the next x, so its
  // strip solve may stop at kPredictorTolerance there.
  bool solve(int pass) {
    const bool predictor = pass == 0 && from_hertz_ && !fixed_sampling_;
    const bool from_previous_pass = pass > 0 || (c_.recentring && !c_.ws.pass_start.empty());
    const Mim1dSolver::EarlyStop unsettled{main_.c * (main_.gap_dz - kEarlyStopWindow * kGapApproachTolerance_m),
                                           main_.c * (main_.gap_dz + kEarlyStopWindow * kGapApproachTolerance_m),
                                           kPredictorTolerance};
    solve_main_once(c_, main_, force_, from_previous_pass, predictor ? kPredictorTolerance : c_.options.mim1d.tolerance,
                    predictor || fixed_sampling_ ? nullptr : &unsettled);
    return predictor;
  }

  // The strip solve can cycle for one gap and load (max-iterations): after a successful pass, go halfway back towards
  // it (x and F) and on, at most kStripSolveRetries times. False: give up (main.solution says why).
  bool retry_halfway(int pass) {
    if (pass == 0 || main_.solution.status != SolveStatus::MaxIterations) return false;
    if (++retries_ > kStripSolveRetries) return false;
    main_.gap_dz = 0.5 * (main_.gap_dz + previous_x_);
    force_ = 0.5 * (force_ + previous_force_);
    return true;
  }

  PassOutcome measure(bool predictor) {
    PassOutcome out;
    out.dz = main_.solution.approach_m / main_.c;
    c_.result.vertical_approach_m = out.dz;
    out.vertical = c_.load == LoadKind::VerticalForce ? solution_force(main_).vertical_N : c_.load_value;
    out.settled = fixed_sampling_ || (!predictor && std::abs(out.dz - main_.gap_dz) <= kGapApproachTolerance_m);
    return out;
  }

  // The next normal force. It moves only once x has settled (moving both at once alternates): a secant step on
  // vertical(F) from the last settled pass, the first time F V / vertical. The predictor pass already takes the ratio
  // step (the share of the load carried vertically hardly depends on x), not recorded for the secant.
  double force_step(bool predictor, const PassOutcome& outcome) {
    const double value = c_.load_value, vertical = outcome.vertical;
    double next_force = force_;
    if (predictor && vertical > 0.0 && !vertical_weighted_) next_force = force_ * value / vertical;
    if (outcome.settled && vertical > 0.0 && !vertical_weighted_) {
      next_force = force_ * value / vertical;
      if (settled_force_ > 0.0 && vertical != settled_vertical_) {
        const double secant = force_ + (value - vertical) * (force_ - settled_force_) / (vertical - settled_vertical_);
        if (secant > 0.0) next_force = secant;
      }
      settled_force_ = force_;
      settled_vertical_ = vertical;
    }
    return next_force;
  }

  // Conformal, x settled and the load nearly balanced: x is held and the secant on F taken at this gap alone (moving x
  // within its settling moves the conformal surface's vertical load by up to 1e-5 of it on the flank, so the secant
  // would step on noise); the next pass checks that x is still settled. A plane carries F cos(angle) exactly.
  bool hold_sampling(const PassOutcome& outcome, double next_force) {
    const bool nearly_balanced = std::abs(outcome.vertical - c_.load_value) <= kHoldSamplingWindow * c_.load_value;
    if (planar_ || vertical_weighted_ || !outcome.settled || !nearly_balanced) return false;
    held_ = true;
    shift_pass_start(c_, main_, 0.0, next_force - force_);
    record(outcome.dz);
    force_ = next_force;
    return true;
  }

  // The next x solves x = dz_pred + slope (x - x_k), dz_pred = dz_k (F_next / F_k)^q: secant steps on x - dz(x).
  void step_sampling_approach(int pass, double dz, double next_force) {
    const double slope = approach_slope(pass, dz);
    const double predicted = dz * std::pow(next_force / force_, load_exponent(dz, next_force));
    double next_x = (predicted - slope * main_.gap_dz) / (1.0 - slope);
    // The first sampling approach can lie far beyond the solved one (dz < 0: the reference point's angle overstated
    // the normal force, a flank reference with the load on the root), where the prediction runs to x <= 0.
    if (!(next_x > 0.0 && std::isfinite(next_x))) next_x = kSamplingApproachCut * main_.gap_dz;
    const double next_origin = pass + 1 < kCentreFollowingPasses ? next_grid_origin(c_, main_, next_x) : main_.origin_y;
    shift_pass_start(c_, main_, next_x - main_.gap_dz, next_force - force_, next_origin);
    record(dz);
    main_.gap_dz = next_x;
    force_ = next_force;
  }

  // slope = d dz / d x: measured by the secant where it can (it also sees what the first-order geometry misses: the
  // conformal surface moving with x, an active set that changes), at the first pass from the geometry (gap_slope);
  // clamped to [kMinGapSlope, kMaxGapSlope].
  double approach_slope(int pass, double dz) {
    if (pass > 0 && main_.gap_dz != previous_x_) {
      const double at_this_force = previous_dz_ * std::cbrt(std::pow(force_ / previous_force_, 2.0));
      return std::clamp((dz - at_this_force) / (main_.gap_dz - previous_x_), kMinGapSlope, kMaxGapSlope);
    }
    if (const std::optional<double> geometric = gap_slope(c_, main_))
      return std::clamp(*geometric, kMinGapSlope, kMaxGapSlope);
    return 0.0;
  }

  // q in dz ~ F^q: Hertz 2/3; MIM-1D the local exponent of its last strip solve.
  double load_exponent(double dz, double next_force) {
    if (next_force != force_ && dz > 0.0)
      if (const std::optional<double> per_load = load_rate(c_, main_); per_load && *per_load > 0.0)
        return *per_load * force_ / dz;
    return 2.0 / 3.0;
  }

  void record(double dz) {
    previous_x_ = main_.gap_dz;
    previous_dz_ = dz;
    previous_force_ = force_;
  }

  WheelCase& c_;
  PatchProblem& main_;
  // The hertz rung is one ellipse from the curvatures at the rigid contact point (as practised in the field): its gap
  // stays sampled at first contact and the passes only balance the load.
  const bool fixed_sampling_ = c_.options.method == NormalMethod::Hertz;
  const bool planar_ = c_.options.surface == ContactSurface::Planar;
  bool from_hertz_ = true;          // the first sampling approach is Hertz's estimate
  bool vertical_weighted_ = false;  // the solver prescribes the vertical load itself (weighted_vertical_load)
  double force_ = 0.0;              // the normal force prescribed to this pass [N]
  double previous_x_ = 0.0, previous_dz_ = 0.0, previous_force_ = 0.0;  // the last pass's x, dz and force
  double settled_force_ = 0.0, settled_vertical_ = 0.0;  // the last pass with x settled: force and vertical load
  double previous_angle_ = 0.0;                          // the plane's angle at the last pass [rad]
  int retries_ = 0;                                      // strip solves retried halfway back
  bool held_ = false;                                    // the last pass held x: its gap is still the one sampled
};

}  // namespace

SolveStatus solve_main_for_load(WheelCase& c, PatchProblem& main, double depth) {
  return GapPasses(c, main).run(depth);
}

}  // namespace ctab::gen
