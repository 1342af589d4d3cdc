// SPDX-License-Identifier: Apache-2.0
#pragma once
//! MIM-1D normal contact solver (Qazi, Yin, Sebes, Chollet, Pozzolini, VSD 60(4):1322-1340, 2022).
//!
//! Method: the potential contact zone is cut into strips of width 2b along y; in strip i the pressure is
//! semi-elliptic along x (Eq. 7) with half-length a_i tied to its peak pressure by the local Hertz relation
//! a_i = c_i p0_i (Eq. 26; c_i from strip_compliance.hpp). Unknowns are the strip loads N_i = pi a_i b p0_i
//! (Appendix 1, Eqs. A1-A4), so that a_i = sqrt(c_i N_i / (pi b)) and the compatibility equations read
//!   sum_j G_ij(a_j) N_j = delta - h_i   for strips in contact (Eqs. 8-9, 13 and A2),
//!   N_i = 0 and delta - h_i - u_i <= 0   elsewhere (Eq. 4),
//! with G_ij = C_ij / (pi a_j b) from strip_kernel.hpp (closed form of Eqs. 10-12).
//! Iteration (Figure 3): start from the interpenetration zone with the ANALYN estimate of every strip, measured
//! from the deepest point of its own basin of h
//! (Appendix 2: exact for an elliptic patch), a_i = sqrt(d_i / ((1 + alpha_i) A_i)), d_i = delta - (1 + beta_i) h_i,
//! p0_i = a_i / c_i; solve; drop strips with non-positive load;
//! update the lengths; re-admit strips that interpenetrate after deformation; repeat. Two update rules:
//!   FixedPoint - the paper's: solve G(a) N = delta - h with the lengths of the previous iterate;
//!   Newton     - (default) Newton's method on the same equations, the Jacobian including dG/da da/dN;
//!                a step that would make a load non-positive falls back to the fixed-point step, and a cold
//!                start's first step is the fixed-point step.
//! Prescribed load (Eqs. 6 and 15): delta becomes one more unknown of the same Newton iteration (bordered
//! system, two back-substitutions with one factorisation). Should that fail, the paper's outer iteration
//! takes over: a safeguarded Newton iteration on delta with slope dN/d(delta) = 1^T J^-1 1 from the last
//! factorisation (Eq. 16 when no slope is available), kept inside a bracket, bisecting when a step leaves
//! it, the loads warm-started along J^-1 1.
//! Validity: half-space (small contact angles across the patch), frictionless, quasi-identical materials;
//! pressure symmetric in x (no yaw).
#include <Eigen/Dense>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "ctab/contact/gap_profile.hpp"
#include "ctab/contact/normal_solution.hpp"
#include "ctab/contact/mim1d_options.hpp"
#include "ctab/contact/strip_compliance.hpp"
#include "ctab/contact/strip_grid.hpp"

namespace ctab::gen {

//! Solver for one gap profile. Construction resamples the gap onto strips (allocates, may throw InputError);
//! solves never throw and report a SolveStatus.
class Mim1dSolver {
 public:
  Mim1dSolver(const GapProfile& gap, double E_star_Pa, const Mim1dOptions& options);
  //! Re-targets the solver to another gap (same material and options), keeping its storage: a workspace
  //! reused case after case allocates only when a case needs more strips than any before. Throws InputError.
  void reset(const GapProfile& gap);

  //! Weights w_i [-] of the strips' loads in the prescribed load of solve_for_load, which is then sum_i w_i N_i [N]
  //! (a wheel-rail conformal patch: w_i = cos of strip i's normal inclination, so that the prescribed load is the
  //! vertical one); one per strip of grid(), each > 0 and finite; empty: all 1 (the normal force). reset() clears
  //! them. Throws InputError on a wrong count or value.
  void set_load_weights(const std::vector<double>& weights);

  //! Solve for a prescribed rigid approach delta [m] (same datum as the gap's h).
  [[nodiscard]] NormalSolution solve_for_approach(double approach_m);
  //! Solve for a prescribed total normal force [N] (with load weights: sum_i w_i N_i, set_load_weights).
  [[nodiscard]] NormalSolution solve_for_load(double normal_force_N);
  //! The same, started from `start` (a neighbouring gap's solution; empty: cold). Strips of `start` that carry
  //! load and interpenetrate at its depth form the starting set; should the warm solve fail, the cold solve runs
  //! (the iterations of both are counted). Converges to the same tolerance as the cold start.
  [[nodiscard]] NormalSolution solve_for_load(double normal_force_N, const Mim1dWarmStart& start);
  //! The same to a looser relative tolerance (at least Mim1dOptions::tolerance) for loads, force and the Eq. 4
  //! check: for a solve that only predicts (the wheel-rail contact's first gap pass, whose gap is re-sampled).
  [[nodiscard]] NormalSolution solve_for_load(double normal_force_N, const Mim1dWarmStart& start, double tolerance);
  //! Where a solve may stop early: while the approach lies outside [approach_low_m, approach_high_m], the looser
  //! relative `tolerance` applies (a wheel-rail gap pass whose approach will not settle only predicts the next).
  struct EarlyStop {
    double approach_low_m = 0.0, approach_high_m = 0.0;  // normal approach [m]
    double tolerance = 0.0;                              // relative tolerance outside the window [-]
  };
  //! The same to `tolerance`, or to early_stop.tolerance where the approach lies outside early_stop's window.
  [[nodiscard]] NormalSolution solve_for_load(double normal_force_N, const Mim1dWarmStart& start, double tolerance,
                                              const EarlyStop& early_stop);
  //! The solve that gave `solved` (the last one) as a warm start for a neighbouring gap; cleared unless it
  //! succeeded with contact.
  void save_warm_start(const NormalSolution& solved, Mim1dWarmStart& out) const;

  //! First-order change of the last solve's approach [m] when every strip's separation changes by dh_m[i] (one
  //! entry per strip of grid()) and the total load by load_change_N: the bordered system at the solution,
  //! J dN - d(delta) v = -dh and w^T dN = dF (w: the load weights, or 1), gives
  //! d(delta) = (dF + w^T J^-1 dh) / w^T J^-1 v (v = -dR/d(delta): 1, less the smoothed compliances' approach term
  //! in a load-prescribed solve; dF a change of the prescribed load, weighted alike), here from the last
  //! Jacobian factorisation of the solve (a prediction only: that of the step before convergence). Empty when it
  //! does not match the active set (fixed-point update, or no contact).
  [[nodiscard]] std::optional<double> approach_sensitivity(const std::vector<double>& dh_m,
                                                           double load_change_N = 0.0) const;

  //! Moves `start` (save_warm_start of the last solve) to first order to the solution after every strip's
  //! separation changed by dh_m[i] and the total load by load_change_N (the bordered system of
  //! approach_sensitivity: dN = J^-1 (d(delta) v - dh)); a strip predicted non-positive keeps half its load. False,
  //! and `start` unchanged, when no factorisation matches the last solve's active set.
  bool shift_warm_start(const std::vector<double>& dh_m, double load_change_N, Mim1dWarmStart& start) const;

  [[nodiscard]] const StripGrid& grid() const noexcept { return grid_; }
  //! True when this solver was set up for the same material and options (so reset() may reuse it).
  [[nodiscard]] bool matches(double E_star_Pa, const Mim1dOptions& options) const noexcept;

 private:
  struct InnerResult {
    SolveStatus status = SolveStatus::NumericalFailure;
    int iterations = 0;
    double residual = 0.0;
  };
  //! State of the inner iteration (Figure 3, with Newton steps).
  struct InnerState {
    double approach_m;            // current approach [m] (an unknown when a load is prescribed)
    const double* target_load_N;  // prescribed total load [N], or null
    double h_min;                 // deepest separation of the grid [m]
    double last_change = std::numeric_limits<double>::infinity();  // relative load change of the last step
    bool set_checked = false;                                      // Eq. 4 checked since the active set last changed
    std::size_t growth = 0;                                        // admission reach, in strips
    int cycles = 0;  // times an active set came back to one already checked (cycle detection)
    double best_merit = std::numeric_limits<double>::infinity();  // lowest residual on this set (stall detection)
    int steps_without_progress = 0;
    double damping = 1.0;            // fraction of the Newton/fixed-point step taken (1: full steps)
    bool fixed_point_first = false;  // a cold start's first step is the paper's fixed-point step (solve_inner)
  };
  enum class SetCheck { Iterate, Check, CheckAndFinish };
  enum class IterationOutcome { Continue, Converged, Failed };
  //! Solves for the approach (in/out) or, with a target load, for both loads and approach.
  InnerResult solve_inner(double& approach_m, bool warm_start, const double* target_load_N);
  //! One iteration: residual, Eq. 4 check and admissions, then a Newton or fixed-point step.
  IterationOutcome iterate(InnerState& state, InnerResult& result);
  //! Loads to start from: the warm-started set (strips that still interpenetrate) or ANALYN's zone.
  bool start_loads(double approach_m, bool warm_start);
  [[nodiscard]] bool active_compliances_valid() const;
  //! rhs_ = delta - h and active_loads_ = N on the active set.
  void gather_active_system(double approach_m);
  //! Whether to check Eq. 4 outside the set now, and whether the set has converged.
  [[nodiscard]] SetCheck check_active_set(const InnerState& state, double residual, double force_mismatch);
  //! Unloaded strips that interpenetrate after deformation (Eq. 4) into violators_/penetrations_.
  void find_violators(double approach_m, double depth);
  //! True when the active set was already checked in this solve (then the admissions cycle); records it.
  bool active_set_seen_before();
  //! Admits the violators and their neighbours within `growth` (which then doubles); false if none.
  bool admit_violators(double approach_m, std::size_t& growth);
  //! Newton step (bordered with a target load) into next_loads_; false if a load would be non-positive.
  bool newton_step(const InnerState& state, double force_mismatch, double& next_approach);
  //! The paper's fixed-point step with the current lengths into next_loads_.
  void fixed_point_step(const InnerState& state, double& next_approach);
  //! Stall detection: halves the step (down to a floor) when the residual has not improved for a few steps,
  //! as when Newton alternates between two states; full steps again once close to the solution.
  static void track_progress(InnerState& state, double merit);
  //! Accepts next_loads_ and drops non-positive strips (Figure 3); false on a non-finite or empty result.
  bool take_step(InnerState& state, double next_approach);
  [[nodiscard]] NormalSolution solve_for_load_nested(double normal_force_N, int& iterations);
  void refresh_compliances(double approach_m);
  //! approach_column_ = -d R / d(delta) on the active set, R = u - (delta - h): 1 less the change of u through the
  //! smoothed compliances' dependence on the approach (from build_matrices' Jacobian and G at the current loads).
  void fill_approach_column(double approach_m, double h_min);
  //! The right-hand side of the sensitivity systems on the active set for a change dh_m of every strip's h.
  [[nodiscard]] Eigen::VectorXd active_gap_change(const std::vector<double>& dh_m) const;
  //! Loads and active set from a warm start at approach h_min + start.depth_m; false when no strip of it applies.
  bool load_warm_start(const Mim1dWarmStart& start, double& approach_m);
  //! Strip index k of the grid's first strip (centre (k + 1/2) 2b).
  [[nodiscard]] long first_strip_index() const noexcept;
  //! Approach of Hertz at the deepest strip for the given load (the paper's starting value) [m].
  [[nodiscard]] double hertz_start_approach(double normal_force_N) const;
  //! sum_r w(active_[r]) v(r) over the active set (v one entry per active strip): the prescribed load's measure.
  [[nodiscard]] double load_sum(const Eigen::VectorXd& v) const;
  //! sum_i w_i N_i over the active set: the load that solve_for_load prescribes [N].
  [[nodiscard]] double prescribed_load() const;
  void update_lengths();
  enum class MatrixKind { Influence, Jacobian };
  //! Fills G, or the Jacobian and G together (a Newton step that unloads a strip falls back to G in the same
  //! iteration), on the active set and, with_displacement, u = G N (the residual's part).
  void build_matrices(MatrixKind kind, bool with_displacement);
  [[nodiscard]] double displacement_at(std::size_t strip) const;
  void initialise_zone(double approach_m);
  //! basin_scratch_[i]: the deepest h of strip i's basin (between neighbouring local maxima of h); returns the
  //! number of basins whose deepest point lies below approach_m.
  std::size_t fill_basin_minima(double approach_m);
  void admit_strip(std::size_t strip, double penetration_m);
  [[nodiscard]] NormalSolution make_solution(SolveStatus status, double approach_m) const;

  StripGrid grid_;
  double E_star_Pa_;
  Mim1dOptions options_;
  class ToleranceScope;     // restores tolerance_ and early_stop_ after a solve with its own tolerance
  double tolerance_;        // the current solve's relative tolerance (options_.tolerance, or looser for one solve)
  double solve_tolerance_;  // the solve's tolerance where early_stop_ does not apply
  std::optional<EarlyStop> early_stop_;
  double matrix_entries_ = 0.0;         // influence-matrix entries built so far (NormalSolution::matrix_entries)
  double b_;                            // strip half-width [m]
  double kernel_scale_;                 // 2 / (pi^2 E* b) [m/N]
  std::vector<StripHertz> compliance_;  // local Hertz data per strip (all strips)
  std::vector<StripHertz> shifted_compliance_;  // compliance_ at a slightly larger approach (fill_approach_column)
  double compliance_approach_ = std::numeric_limits<double>::quiet_NaN();  // delta they were computed for
  std::vector<double> scratch_;
  std::vector<double> load_;                 // N_i [N] (all strips; 0 outside the active set)
  std::vector<double> load_weight_;          // w_i of the prescribed load (all strips), empty: all 1
  std::vector<double> length_;               // a_i [m] (all strips)
  std::vector<std::size_t> active_;          // strips in contact, increasing
  std::vector<std::size_t> violators_;       // strips that interpenetrate after deformation (scratch)
  std::vector<double> penetrations_;         // their penetration [m] (scratch)
  std::vector<double> basin_scratch_;        // deepest h of each strip's basin (initial guess)
  std::vector<std::uint64_t> checked_sets_;  // signatures of the active sets checked for Eq. 4 in this solve
  Eigen::MatrixXd influence_;                // G on the active set
  Eigen::MatrixXd jacobian_;                 // dR/dN on the active set
  Eigen::VectorXd displacement_;             // u = G N on the active set
  Eigen::PartialPivLU<Eigen::MatrixXd> factorisation_;
  Eigen::VectorXd rhs_, active_loads_, ones_, residual_, next_loads_, slope_;  // the active system (scratch)
  Eigen::VectorXd approach_column_;  // -d R / d(delta) on the active set (fill_approach_column; 1 at fixed delta)
  std::vector<double> column_h_, column_q_, column_g_, column_j_;
};

//! Re-samples `start` onto the strip lattice of a grid whose y = 0 lies at y = origin_shift_m of the saved grid
//! (strip centres (k + 1/2) strip_width_m in either frame): each new strip takes the saved loads linearly
//! interpolated at its centre, so a start moves with the contact when the grid's origin moves (the wheel-rail
//! reference point following the interpenetration centre). `out` receives the result (its storage is reused).
void move_warm_start_origin(const Mim1dWarmStart& start, double origin_shift_m, double strip_width_m,
                            Mim1dWarmStart& out);

//! The start of the next solve of an equally spaced chain: the last solve (`start`) and the one before it
//! (start.earlier) extrapolated linearly, strip by strip (by strip index), with the depth and the sampling approach.
//! A strip of the last solve that the extrapolation unloads keeps half its load; a strip outside the last solve
//! stays out (the Eq. 4 check admits it). Without an earlier solve, `start` itself. On a finely spaced chain the
//! first residual is an order of magnitude below that of `start` alone. `out` receives the result (its storage is
//! reused; its earlier solve is left empty).
void extrapolate_warm_start(const Mim1dWarmStart& start, Mim1dWarmStart& out);

}  // namespace ctab::gen
