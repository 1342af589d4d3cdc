#include "ctab/contact/mim1d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "ctab/contact/error.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/contact/strip_kernel.hpp"

namespace ctab::gen {

namespace {

constexpr double kPi = std::numbers::pi;
// Relative step and residual below which strips outside the set are checked for interpenetration (chosen: early
// enough that admissions do not wait for full convergence, late enough that the deformation is nearly right).
constexpr double kAdmissionCheckLevel = 1.0e-3;
// Admitted strip's starting load (admit_strip): a quarter of its neighbour's, at least 1e-12 N, refined by
// kAdmissionNewtonSteps Newton steps on its own self term, each step kept within [1/20, 4] x the load (chosen).
constexpr double kAdmissionStartFraction = 0.25;
constexpr double kAdmissionMinimumLoad_N = 1e-12;
constexpr int kAdmissionNewtonSteps = 8;
constexpr double kAdmissionStepFloor = 0.05;
constexpr double kAdmissionStepCeiling = 4.0;
// CONTACT's limit R_y <= 20 R_x: the Hertz start uses B >= A/20 (README, "bottleneck cure").
constexpr double kCurvatureRatioLimit = 20.0;
// Start approach beyond first contact when Hertz fails at the deepest strip [m] (chosen: 1 um).
constexpr double kFallbackStartApproach_m = 1e-6;
// Outer iteration without contact: the approach beyond first contact doubles, plus 1 nm so that it leaves 0.
constexpr double kNoContactGrowth = 2.0;
constexpr double kNoContactNudge_m = 1e-9;
// Warm start along dN/d(delta): a strip predicted non-positive keeps half its load.
constexpr double kWarmStartShrink = 0.5;
// Stall detection (track_progress): a step counts as progress when it lowers the best residual on the current set
// by kProgressFactor; after kStallSteps steps without progress the step is scaled by kDampingFactor, at most down to
// kMinimumDamping (chosen: a Newton 2-cycle is caught within 4 steps; 1/16 still converges in well under the
// iteration limit). Full steps return below kFullStepLevel, where Newton is in its quadratic range.
constexpr double kProgressFactor = 0.9;
constexpr int kStallSteps = 4;
constexpr double kDampingFactor = 0.5;
constexpr double kMinimumDamping = 1.0 / 16.0;
constexpr double kFullStepLevel = 1.0e-6;
// Forward-difference step of the compliances' approach derivative, relative to the depth (fill_approach_column).
// Chosen: 1e-6, well inside the smooth range of the weights, with a round-off error of ~1e-10 in the rate.
constexpr double kComplianceApproachStep = 1.0e-6;
// FNV-1a 64-bit constants (Fowler, Noll, Vo), for the active-set signatures of the cycle detection.
constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
constexpr std::uint64_t kFnvPrime = 1099511628211ull;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Mim1dSolver::Mim1dSolver(const GapProfile& gap, double E_star_Pa, const Mim1dOptions& options)
    : E_star_Pa_(E_star_Pa), options_(options), tolerance_(options.tolerance), solve_tolerance_(options.tolerance) {
  if (!(std::isfinite(E_star_Pa) && E_star_Pa > 0.0))
    throw InputError("material", 0, "effective modulus must be positive and finite");
  if (!(options.tolerance > 0.0 && options.tolerance < 1e-2)) throw InputError("tolerance", 0, "must lie in (0, 0.01)");
  if (options.max_iterations < 1 || options.max_outer_iterations < 1)
    throw InputError("max iterations", 0, "must be at least 1");
  if (options.curvature.smoothing_fraction <= 0.0 || !std::isfinite(options.curvature.smoothing_fraction))
    throw InputError("smoothing fraction", 0, "must be positive and finite");
  (void)StripKernel::instance();  // build the kernel table at setup, not inside the first solve
  reset(gap);
}

bool Mim1dSolver::matches(double E_star_Pa, const Mim1dOptions& o) const noexcept {
  return E_star_Pa == E_star_Pa_ && o.strip_width_m == options_.strip_width_m && o.update == options_.update &&
         o.curvature.treatment == options_.curvature.treatment &&
         o.curvature.smoothing_fraction == options_.curvature.smoothing_fraction && o.tolerance == options_.tolerance &&
         o.max_iterations == options_.max_iterations && o.max_outer_iterations == options_.max_outer_iterations &&
         o.starting_zone_m == options_.starting_zone_m;
}

void Mim1dSolver::reset(const GapProfile& gap) {
  fill_strip_grid(gap, options_.strip_width_m, grid_);
  b_ = grid_.half_width_m();
  kernel_scale_ = 2.0 / (kPi * kPi * E_star_Pa_ * b_);
  const std::size_t n = grid_.size();
  load_.assign(n, 0.0);
  length_.assign(n, 0.0);
  compliance_.assign(n, StripHertz{});
  compliance_approach_ = std::numeric_limits<double>::quiet_NaN();
  active_.clear();
  active_.reserve(n);
  load_weight_.clear();
  column_h_.resize(n + 1);
  column_q_.resize(n + 1);
  column_g_.resize(n + 1);
  column_j_.resize(n + 1);
}

void Mim1dSolver::set_load_weights(const std::vector<double>& weights) {
  if (!weights.empty() && weights.size() != grid_.size())
    throw InputError("MIM-1D load weights", 0,
                     std::to_string(weights.size()) + " weights for " + std::to_string(grid_.size()) + " strips");
  for (const double w : weights)
    if (!(w > 0.0 && std::isfinite(w)))
      throw InputError("MIM-1D load weights", 0, "a weight is not positive and finite: " + std::to_string(w));
  load_weight_ = weights;
}

double Mim1dSolver::prescribed_load() const {
  double sum = 0.0;
  for (const std::size_t i : active_) sum += (load_weight_.empty() ? 1.0 : load_weight_[i]) * load_[i];
  return sum;
}

double Mim1dSolver::load_sum(const Eigen::VectorXd& v) const {
  if (load_weight_.empty()) return v.sum();
  double sum = 0.0;
  for (Eigen::Index r = 0; r < v.size(); ++r) sum += load_weight_[active_[static_cast<std::size_t>(r)]] * v(r);
  return sum;
}

void Mim1dSolver::update_lengths() {
  for (const std::size_t j : active_)
    length_[j] = std::sqrt(compliance_[j].compliance_m_per_Pa * load_[j] / (kPi * b_));
}

void Mim1dSolver::build_matrices(MatrixKind kind, bool with_displacement) {
  const StripKernel& kernel = StripKernel::instance();
  const auto n = static_cast<Eigen::Index>(active_.size());
  const bool jacobian = kind == MatrixKind::Jacobian;
  matrix_entries_ += static_cast<double>(n) * static_cast<double>(n);
  influence_.resize(n, n);
  if (jacobian) jacobian_.resize(n, n);
  displacement_.setZero(n);
  const std::size_t first = active_.front(), last = active_.back();
  // One run of neighbouring strips (the usual case): row r is strip first + r, so entry (r, c) depends on |r - c|
  // alone and a column is two straight copies of its lag arrays.
  const bool contiguous = last - first + 1 == active_.size();
  double* g_lag = column_g_.data();  // G_ij by lag k = |i - j|
  double* j_lag = column_j_.data();  // J_ij by lag
  const double* h_lag = column_h_.data();
  const double* q_lag = column_q_.data();
  const double half_scale = 0.5 * kernel_scale_;
  for (Eigen::Index c = 0; c < n; ++c) {
    const std::size_t j = active_[static_cast<std::size_t>(c)];
    const std::size_t reach = std::max(j - first, last - j);
    // H_k = h((2k+1) b/a_j), Q_k = t h'(t) there; entries are differences of neighbours:
    // G = scale (H_k - H_{k-1}) (2 H_0 at k = 0), and d(G_ij N_j)/dN_j = G_ij + (a_j/2) dG_ij/da_j with
    // dh(c/a)/da = -t h'(t)/a, so J = G - scale/2 (Q_k - Q_{k-1}). The lookups first, then the differences (a
    // loop the compiler vectorises).
    kernel.at_odd_multiples(b_ / length_[j], reach + 1, column_h_.data(), column_q_.data());
    g_lag[0] = kernel_scale_ * (2.0 * h_lag[0]);
    j_lag[0] = g_lag[0] - half_scale * (2.0 * q_lag[0]);
    for (std::size_t k = 1; k <= reach; ++k) {
      g_lag[k] = kernel_scale_ * (h_lag[k] - h_lag[k - 1]);
      j_lag[k] = g_lag[k] - half_scale * (q_lag[k] - q_lag[k - 1]);
    }
    const double load = with_displacement ? load_[j] : 0.0;
    double* column = influence_.col(c).data();
    double* jacobian_column = jacobian ? jacobian_.col(c).data() : nullptr;
    double* u = displacement_.data();
    if (contiguous) {
      const auto cc = static_cast<std::size_t>(c), rows = static_cast<std::size_t>(n);
      for (std::size_t r = 0; r < cc; ++r) column[r] = g_lag[cc - r];
      for (std::size_t r = cc; r < rows; ++r) column[r] = g_lag[r - cc];
      if (jacobian) {
        for (std::size_t r = 0; r < cc; ++r) jacobian_column[r] = j_lag[cc - r];
        for (std::size_t r = cc; r < rows; ++r) jacobian_column[r] = j_lag[r - cc];
      }
      for (std::size_t r = 0; r < rows; ++r) u[r] += column[r] * load;  // u = G N, accumulated column by column
      continue;
    }
    for (Eigen::Index r = 0; r < n; ++r) {
      const std::size_t i = active_[static_cast<std::size_t>(r)];
      const std::size_t k = i > j ? i - j : j - i;
      column[r] = g_lag[k];
      u[r] += g_lag[k] * load;
      if (jacobian) jacobian_column[r] = j_lag[k];
    }
  }
}

double Mim1dSolver::displacement_at(std::size_t strip) const {
  const StripKernel& kernel = StripKernel::instance();
  double u = 0.0;
  for (const std::size_t j : active_) {
    const double d = grid_.y_m[strip] - grid_.y_m[j];
    const double dh = kernel.value((d + b_) / length_[j]) - kernel.value((d - b_) / length_[j]);
    u += kernel_scale_ * dh * load_[j];
  }
  return u;
}

void Mim1dSolver::initialise_zone(double approach_m) {
  active_.clear();
  std::fill(load_.begin(), load_.end(), 0.0);
  refresh_compliances(approach_m);
  const std::size_t n = grid_.size();
  const auto deepest =
      static_cast<std::size_t>(std::min_element(grid_.h_m.begin(), grid_.h_m.end()) - grid_.h_m.begin());
  // ANALYN is local: each strip is measured from the deepest point of its own basin of h (between neighbouring
  // local maxima), so that every separate contact region starts loaded.
  (void)fill_basin_minima(approach_m);
  const std::vector<double>& basin_minimum = basin_scratch_;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(grid_.h_m[i] < approach_m)) continue;  // potential zone = interpenetration zone
    if (options_.starting_zone_m &&
        (grid_.y_m[i] < options_.starting_zone_m->first || grid_.y_m[i] > options_.starting_zone_m->second))
      continue;
    // ANALYN (Eqs. A5-A6); strips it leaves out start unloaded but stay candidates (re-admitted when they
    // interpenetrate after deformation).
    const StripHertz& local = compliance_[i];
    const double d = (approach_m - basin_minimum[i]) - local.depth_factor * (grid_.h_m[i] - basin_minimum[i]);
    if (!(d > 0.0)) continue;
    const double length = std::sqrt(d / (local.length_factor * grid_.A_per_m[i]));
    load_[i] = kPi * b_ * length * length / local.compliance_m_per_Pa;  // N = pi a b p0, p0 = a / c
    active_.push_back(i);
  }
  if (active_.empty()) {
    const double depth = approach_m - grid_.h_m[deepest];
    active_.push_back(deepest);
    load_[deepest] = kPi * b_ * depth / (2.0 * grid_.A_per_m[deepest] * compliance_[deepest].compliance_m_per_Pa);
  }
}

std::size_t Mim1dSolver::fill_basin_minima(double approach_m) {
  const std::size_t n = grid_.size();
  basin_scratch_.assign(n, 0.0);
  std::size_t interpenetrating = 0;
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin + 1;
    while (end < n && !(end + 1 < n && grid_.h_m[end] > grid_.h_m[end - 1] && grid_.h_m[end] >= grid_.h_m[end + 1]))
      ++end;
    const double low = *std::min_element(grid_.h_m.begin() + static_cast<std::ptrdiff_t>(begin),
                                         grid_.h_m.begin() + static_cast<std::ptrdiff_t>(end));
    std::fill(basin_scratch_.begin() + static_cast<std::ptrdiff_t>(begin),
              basin_scratch_.begin() + static_cast<std::ptrdiff_t>(end), low);
    if (low < approach_m) ++interpenetrating;
    begin = end;
  }
  return interpenetrating;
}

void Mim1dSolver::admit_strip(std::size_t strip, double penetration_m) {
  const auto position = std::lower_bound(active_.begin(), active_.end(), strip);
  if (position != active_.end() && *position == strip) return;
  std::size_t neighbour = position == active_.end() ? active_.back() : *position;
  if (position != active_.begin()) {
    const std::size_t before = *(position - 1);
    if (position == active_.end() || strip - before < neighbour - strip) neighbour = before;
  }
  // Start from the load whose own displacement closes the strip's penetration, G_ii(a(N)) N = penetration
  // (a few Newton steps on the monotone self term), capped at the nearest loaded strip's load.
  const double c = compliance_[strip].compliance_m_per_Pa;
  const StripKernel& kernel = StripKernel::instance();
  double load = std::max(load_[neighbour] * kAdmissionStartFraction, kAdmissionMinimumLoad_N);
  for (int i = 0; i < kAdmissionNewtonSteps && penetration_m > 0.0; ++i) {
    const double a = std::sqrt(c * load / (kPi * b_));
    double h = 0.0, t_dh = 0.0;
    kernel.value_and_scaled_slope(b_ / a, h, t_dh);
    const double u = kernel_scale_ * 2.0 * h * load, du = kernel_scale_ * 2.0 * (h - 0.5 * t_dh);
    load = std::clamp(load - (u - penetration_m) / du, kAdmissionStepFloor * load, kAdmissionStepCeiling * load);
  }
  load_[strip] = std::min(load, load_[neighbour]);
  length_[strip] = std::sqrt(c * load_[strip] / (kPi * b_));
  active_.insert(position, strip);
}

void Mim1dSolver::fill_approach_column(double approach_m, double h_min) {
  approach_column_ = ones_;
  if (options_.curvature.treatment == CurvatureTreatment::Pointwise) return;
  // Smoothed compliances c_j depend on the approach (their weights, the virtual half-widths and the merge factor of
  // two runs): a_j = sqrt(c_j N_j / (pi b)), so d(G_ij N_j)/dc_j = (N_j / c_j) (a_j/2) dG_ij/da_j = (N_j / c_j)
  // (J_ij - G_ij). Leaving this out makes the bordered Newton step a fixed-point step along delta: measured at the
  // two-point contact (built-in profiles, wheel mode, dy 5.51 mm, 135.6 kN vertical) the approach alternated with
  // a ratio of -0.945 per step and ran out of iterations. dc_j/d(delta) by a forward difference.
  const double step = kComplianceApproachStep * (approach_m - h_min);
  strip_compliances(grid_, E_star_Pa_, approach_m + step, options_.curvature, shifted_compliance_, scratch_);
  for (Eigen::Index c = 0; c < approach_column_.size(); ++c) {
    const std::size_t j = active_[static_cast<std::size_t>(c)];
    const double compliance = compliance_[j].compliance_m_per_Pa;
    const double rate = (shifted_compliance_[j].compliance_m_per_Pa - compliance) / (step * compliance);
    if (rate == 0.0 || !std::isfinite(rate)) continue;
    approach_column_ -= (rate * load_[j]) * (jacobian_.col(c) - influence_.col(c));
  }
}

void Mim1dSolver::refresh_compliances(double approach_m) {
  // Pointwise compliances do not depend on the approach; smoothed ones do (their weights).
  if (approach_m == compliance_approach_ ||
      (options_.curvature.treatment == CurvatureTreatment::Pointwise && !std::isnan(compliance_approach_)))
    return;
  strip_compliances(grid_, E_star_Pa_, approach_m, options_.curvature, compliance_, scratch_);
  compliance_approach_ = approach_m;
}

bool Mim1dSolver::start_loads(double approach_m, bool warm_start) {
  if (warm_start && !active_.empty()) {  // strips that no longer interpenetrate cannot carry load
    std::erase_if(active_, [&](std::size_t i) {
      if (grid_.h_m[i] < approach_m) return false;
      load_[i] = 0.0;
      return true;
    });
    if (!active_.empty()) return true;
  }
  initialise_zone(approach_m);
  return true;
}

bool Mim1dSolver::active_compliances_valid() const {
  for (const std::size_t i : active_)
    if (!(compliance_[i].compliance_m_per_Pa > 0.0 && std::isfinite(compliance_[i].compliance_m_per_Pa))) return false;
  return true;
}

void Mim1dSolver::gather_active_system(double approach_m) {
  const auto n = static_cast<Eigen::Index>(active_.size());
  rhs_.resize(n);
  active_loads_.resize(n);
  ones_.setOnes(n);
  for (Eigen::Index r = 0; r < n; ++r) {
    const std::size_t i = active_[static_cast<std::size_t>(r)];
    rhs_(r) = approach_m - grid_.h_m[i];
    active_loads_(r) = load_[i];
  }
}

Mim1dSolver::SetCheck Mim1dSolver::check_active_set(const InnerState& state, double residual, double force_mismatch) {
  const bool force_converged = !state.target_load_N || std::abs(force_mismatch) <= tolerance_ * *state.target_load_N;
  // Newton converges quadratically: once the residual is at tolerance a step below sqrt(tol) is final.
  const double change_tolerance = options_.update == Mim1dUpdate::Newton ? std::sqrt(tolerance_) : tolerance_;
  const bool converged_on_set = state.last_change <= change_tolerance && residual <= tolerance_ && force_converged;
  // Check Eq. 4 outside the set once roughly converged (so admissions do not wait for full convergence)
  // and again at convergence.
  const bool roughly_converged =
      state.cycles == 0 && state.last_change <= kAdmissionCheckLevel && residual <= kAdmissionCheckLevel;
  if (!converged_on_set && !(roughly_converged && !state.set_checked)) return SetCheck::Iterate;
  return converged_on_set ? SetCheck::CheckAndFinish : SetCheck::Check;
}

void Mim1dSolver::find_violators(double approach_m, double depth) {
  // Candidates: the unloaded interpenetrating strips next to the contact, and the deepest strip of every
  // unloaded run of the interpenetration zone (where a separate contact would start).
  violators_.clear();
  penetrations_.clear();
  auto check = [&](std::size_t i) {
    const double gap = grid_.h_m[i] + displacement_at(i) - approach_m;
    if (gap < -tolerance_ * depth) violators_.push_back(i), penetrations_.push_back(-gap);
  };
  const std::size_t n_all = grid_.size();
  for (std::size_t i = 0; i < n_all;) {
    if (!(grid_.h_m[i] < approach_m) || load_[i] > 0.0) {
      ++i;
      continue;
    }
    std::size_t end = i, deepest = i;
    while (end < n_all && grid_.h_m[end] < approach_m && !(load_[end] > 0.0)) {
      if (grid_.h_m[end] < grid_.h_m[deepest]) deepest = end;
      ++end;
    }
    if (i > 0 && load_[i - 1] > 0.0) check(i);
    if (end < n_all && load_[end] > 0.0 && end - 1 != i) check(end - 1);
    if (deepest != i && deepest != end - 1) check(deepest);
    i = end;
  }
}

bool Mim1dSolver::active_set_seen_before() {
  std::uint64_t signature = kFnvOffset;  // FNV-1a over the strip indices
  for (const std::size_t i : active_) signature = (signature ^ static_cast<std::uint64_t>(i)) * kFnvPrime;
  if (std::find(checked_sets_.begin(), checked_sets_.end(), signature) != checked_sets_.end()) return true;
  checked_sets_.push_back(signature);
  return false;
}

bool Mim1dSolver::admit_violators(double approach_m, std::size_t& growth) {
  // A violator also brings its interpenetrating neighbours within a reach that doubles each round, so a contact
  // far wider than the starting zone grows in O(log n) rounds (extra strips leave again through a non-positive
  // load).
  const std::size_t n_all = grid_.size();
  for (std::size_t k = 0; k < violators_.size(); ++k) {
    const std::size_t v = violators_[k];
    const std::size_t lo = v > growth ? v - growth : 0, hi = std::min(n_all - 1, v + growth);
    for (std::size_t i = lo; i <= hi; ++i)
      if (grid_.h_m[i] < approach_m && !(load_[i] > 0.0)) admit_strip(i, i == v ? penetrations_[k] : 0.0);
  }
  if (violators_.empty()) return false;
  growth = 2 * growth + 1;
  return true;
}

bool Mim1dSolver::newton_step(const InnerState& state, double force_mismatch, double& next_approach) {
  factorisation_.compute(jacobian_);
  next_loads_ = active_loads_ - factorisation_.solve(residual_);
  if (state.target_load_N) {  // bordered system: J dN - d(delta) v = -R,  w^T dN = -F (v: approach_column_)
    slope_ = factorisation_.solve(approach_column_);
    const double d_approach = (-force_mismatch - load_sum(next_loads_ - active_loads_)) / load_sum(slope_);
    next_loads_ += d_approach * slope_;
    next_approach = state.approach_m + d_approach;
  }
  return !(next_loads_.array() <= 0.0).any();  // Newton overshoots at a patch edge
}

void Mim1dSolver::fixed_point_step(const InnerState& state, double& next_approach) {
  factorisation_.compute(influence_);  // G, built with the Jacobian in this iteration (build_matrices)
  if (state.target_load_N) {           // G N - delta 1 = -h,  w^T N = target
    next_loads_ = factorisation_.solve(rhs_ - state.approach_m * ones_);  // G^-1 (-h)
    slope_ = factorisation_.solve(ones_);
    next_approach = (*state.target_load_N - load_sum(next_loads_)) / load_sum(slope_);
    next_loads_ += next_approach * slope_;
  } else {
    next_loads_ = factorisation_.solve(rhs_);
  }
}

void Mim1dSolver::track_progress(InnerState& state, double merit) {
  if (merit <= kFullStepLevel) state.damping = 1.0;
  if (merit < kProgressFactor * state.best_merit) {
    state.best_merit = merit;
    state.steps_without_progress = 0;
    return;
  }
  if (++state.steps_without_progress < kStallSteps) return;
  state.damping = std::max(kDampingFactor * state.damping, kMinimumDamping);
  state.best_merit = merit;
  state.steps_without_progress = 0;
}

bool Mim1dSolver::take_step(InnerState& state, double next_approach) {
  if (!next_loads_.allFinite() || !std::isfinite(next_approach)) return false;
  if (state.damping < 1.0) {  // a damped step; strips the full step unloads still leave
    for (Eigen::Index r = 0; r < next_loads_.size(); ++r)
      if (next_loads_(r) > 0.0) next_loads_(r) = active_loads_(r) + state.damping * (next_loads_(r) - active_loads_(r));
    next_approach = state.approach_m + state.damping * (next_approach - state.approach_m);
  }
  const double largest = next_loads_.maxCoeff();
  if (!(largest > 0.0)) return false;
  state.approach_m = next_approach;
  // Strips with non-positive load leave the contact (paper Figure 3).
  bool removed = false;
  for (Eigen::Index r = 0; r < next_loads_.size(); ++r) {
    const std::size_t i = active_[static_cast<std::size_t>(r)];
    load_[i] = std::max(next_loads_(r), 0.0);
    removed = removed || next_loads_(r) <= 0.0;
  }
  if (removed) {
    std::erase_if(active_, [&](std::size_t i) { return load_[i] <= 0.0; });
    state.last_change = std::numeric_limits<double>::infinity();
    state.set_checked = false;
    state.best_merit = std::numeric_limits<double>::infinity();
  } else {
    state.last_change = (next_loads_ - active_loads_).cwiseAbs().maxCoeff() / largest;
  }
  return true;
}

Mim1dSolver::IterationOutcome Mim1dSolver::iterate(InnerState& state, InnerResult& result) {
  if (active_.empty() || !(state.approach_m - state.h_min > 0.0)) return IterationOutcome::Failed;
  refresh_compliances(state.approach_m);
  if (!active_compliances_valid()) return result.status = SolveStatus::InvalidInput, IterationOutcome::Failed;
  const double depth = state.approach_m - state.h_min;
  update_lengths();
  const bool newton = options_.update == Mim1dUpdate::Newton;
  build_matrices(newton ? MatrixKind::Jacobian : MatrixKind::Influence, true);
  gather_active_system(state.approach_m);
  const double force_mismatch = state.target_load_N ? load_sum(active_loads_) - *state.target_load_N : 0.0;
  residual_ = displacement_ - rhs_;
  result.residual = residual_.cwiseAbs().maxCoeff() / depth;
  if (!std::isfinite(result.residual)) return IterationOutcome::Failed;
  if (early_stop_)
    tolerance_ = state.approach_m < early_stop_->approach_low_m || state.approach_m > early_stop_->approach_high_m
                     ? early_stop_->tolerance
                     : solve_tolerance_;
  const SetCheck check = check_active_set(state, result.residual, force_mismatch);
  if (check != SetCheck::Iterate) {
    state.set_checked = true;
    find_violators(state.approach_m, depth);
    if (!violators_.empty() && active_set_seen_before()) {
      // The admissions cycle: back to a set already checked. Admit the violators alone from now on, and only
      // once the set has fully converged (so that the check sees accurate displacements).
      ++state.cycles;
      state.growth = 0;
    }
    if (admit_violators(state.approach_m, state.growth)) {
      if (state.cycles > 0) state.growth = 0;
      state.set_checked = false;
      state.last_change = std::numeric_limits<double>::infinity();
      state.best_merit = std::numeric_limits<double>::infinity();
      return IterationOutcome::Continue;
    }
    if (check == SetCheck::CheckAndFinish) return result.status = SolveStatus::Converged, IterationOutcome::Converged;
  }
  track_progress(state, state.target_load_N ? std::max(result.residual, std::abs(force_mismatch) / *state.target_load_N)
                                            : result.residual);
  // The approach column only for a step: an iteration that converges or admits strips needs the residual alone (a
  // quarter of the iterations on the default table; the column's compliances at a shifted approach are the cost).
  if (newton && state.target_load_N) fill_approach_column(state.approach_m, state.h_min);
  else approach_column_ = ones_;
  double next_approach = state.approach_m;
  const bool fixed_point = !newton || std::exchange(state.fixed_point_first, false);
  if (fixed_point || !newton_step(state, force_mismatch, next_approach)) fixed_point_step(state, next_approach);
  return take_step(state, next_approach) ? IterationOutcome::Continue : IterationOutcome::Failed;
}

Mim1dSolver::InnerResult Mim1dSolver::solve_inner(double& approach_m, bool warm_start, const double* target_load_N) {
  InnerResult result;
  const double h_min = *std::min_element(grid_.h_m.begin(), grid_.h_m.end());
  if (!(approach_m - h_min > 0.0)) {
    active_.clear();
    std::fill(load_.begin(), load_.end(), 0.0);
    result.status = SolveStatus::NoContact;
    return result;
  }
  (void)start_loads(approach_m, warm_start);
  checked_sets_.clear();
  InnerState state{approach_m, target_load_N, h_min};
  // From ANALYN's estimate (a cold start) the first Newton step overshot at a patch edge and fell back to the
  // fixed-point step in 123 of 536 cold solves of the default table, after its factorisation: take that step at once.
  state.fixed_point_first = !warm_start;
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    result.iterations = iteration;
    const IterationOutcome outcome = iterate(state, result);
    approach_m = state.approach_m;
    if (outcome != IterationOutcome::Continue) return result;  // Converged, or the failure in result.status
  }
  result.status = SolveStatus::MaxIterations;
  return result;
}

NormalSolution Mim1dSolver::make_solution(SolveStatus status, double approach_m) const {
  NormalSolution solution;
  solution.method = "mim1d";
  solution.status = status;
  solution.approach_m = approach_m;
  if (status == SolveStatus::Converged && !active_.empty() &&
      (active_.front() == 0 || active_.back() + 1 == grid_.size()))
    solution.status = SolveStatus::ZoneTruncated;
  PatchSolution* patch = nullptr;
  std::size_t previous = 0;
  for (const std::size_t i : active_) {
    if (patch == nullptr || i != previous + 1) {
      solution.patches.emplace_back();
      patch = &solution.patches.back();
      patch->y_min_m = grid_.y_m[i] - b_;
    }
    previous = i;
    StripSolution strip;
    strip.y_m = grid_.y_m[i];
    strip.half_length_m = length_[i];
    strip.load_N = load_[i];
    strip.p0_Pa = load_[i] / (kPi * length_[i] * b_);
    patch->strips.push_back(strip);
    patch->normal_force_N += strip.load_N;
    patch->area_m2 += 4.0 * length_[i] * b_;
    patch->max_pressure_Pa = std::max(patch->max_pressure_Pa, strip.p0_Pa);
    patch->centre_of_pressure_y_m += strip.load_N * strip.y_m;
    patch->y_max_m = grid_.y_m[i] + b_;
  }
  for (PatchSolution& p : solution.patches) {
    p.centre_of_pressure_y_m /= p.normal_force_N;
    solution.normal_load_N += p.normal_force_N;
  }
  return solution;
}

NormalSolution Mim1dSolver::solve_for_approach(double approach_m) {
  const auto start = std::chrono::steady_clock::now();
  const double entries_before = matrix_entries_;
  if (!std::isfinite(approach_m)) {
    NormalSolution invalid = make_solution(SolveStatus::InvalidInput, approach_m);
    invalid.patches.clear();
    return invalid;
  }
  double approach = approach_m;
  const InnerResult inner = solve_inner(approach, false, nullptr);
  if (inner.status == SolveStatus::Converged) update_lengths();
  NormalSolution solution = make_solution(inner.status, approach_m);
  if (!is_success(inner.status)) solution.patches.clear(), solution.normal_load_N = 0.0;
  solution.iterations = inner.iterations;
  solution.residual = inner.residual;
  solution.solve_time_s = seconds_since(start);
  solution.matrix_entries = matrix_entries_ - entries_before;
  return solution;
}

double Mim1dSolver::hertz_start_approach(double normal_force_N) const {
  const auto deepest =
      static_cast<std::size_t>(std::min_element(grid_.h_m.begin(), grid_.h_m.end()) - grid_.h_m.begin());
  const double A0 = grid_.A_per_m[deepest];
  // With load weights the prescribed load is sum w_i N_i: the normal force about that over the deepest strip's w.
  const double force = load_weight_.empty() ? normal_force_N : normal_force_N / load_weight_[deepest];
  const HertzContact hertz =
      hertz_from_load(A0, std::max(grid_.B_per_m[deepest], A0 / kCurvatureRatioLimit), E_star_Pa_, force);
  return grid_.h_m[deepest] + (hertz.status == SolveStatus::Converged ? hertz.approach_m : kFallbackStartApproach_m);
}

long Mim1dSolver::first_strip_index() const noexcept {
  return std::lround(grid_.y_m.front() / grid_.strip_width_m - grid_.centre_offset);
}

bool Mim1dSolver::load_warm_start(const Mim1dWarmStart& start, double& approach_m) {
  if (start.empty() || !(start.depth_m > 0.0 && std::isfinite(start.depth_m))) return false;
  approach_m = *std::min_element(grid_.h_m.begin(), grid_.h_m.end()) + start.depth_m;
  // Several basins of h interpenetrate (tread and flange root in one window): the discrete problem may then hold
  // more than one self-consistent set (measured: dy 4.6-4.7 mm, one region or two), so a neighbour's solution does
  // not apply and the gap starts cold, with every basin loaded (initialise_zone), as without a warm start. An
  // earlier solve of the same contact does: its set is the one the cold start chose (the Eq. 4 check still opens an
  // unloaded basin). Cold, every gap pass of the two-point case at dy 5.51 mm, 135.6 kN took 23-24 iterations.
  if (!start.same_contact && fill_basin_minima(approach_m) > 1) return false;
  active_.clear();
  std::fill(load_.begin(), load_.end(), 0.0);
  const long offset = first_strip_index() - start.first_strip;  // start's index of this grid's strip 0
  const auto count = static_cast<long>(start.loads_N.size());
  for (std::size_t i = 0; i < grid_.size(); ++i) {
    const long k = offset + static_cast<long>(i);
    if (k < 0 || k >= count || !(start.loads_N[static_cast<std::size_t>(k)] > 0.0) || !(grid_.h_m[i] < approach_m))
      continue;
    load_[i] = start.loads_N[static_cast<std::size_t>(k)];
    active_.push_back(i);
  }
  return !active_.empty();
}

void Mim1dSolver::save_warm_start(const NormalSolution& solved, Mim1dWarmStart& out) const {
  out.loads_N.clear();
  if (!is_success(solved.status) || active_.empty()) return;
  out.first_strip = first_strip_index() + static_cast<long>(active_.front());
  out.loads_N.assign(load_.begin() + static_cast<std::ptrdiff_t>(active_.front()),
                     load_.begin() + static_cast<std::ptrdiff_t>(active_.back() + 1));
  out.depth_m = solved.approach_m - *std::min_element(grid_.h_m.begin(), grid_.h_m.end());
  if (!(out.depth_m > 0.0)) out.loads_N.clear();
}

Eigen::VectorXd Mim1dSolver::active_gap_change(const std::vector<double>& dh_m) const {
  // The smoothed compliances depend on delta - h: a uniform shift s of h (taken as dh at the deepest strip) moves
  // them as d(delta) = -s would, hence dh - (1 - v) s on the right-hand side (v = approach_column_), so that a
  // uniform shift moves delta by exactly s.
  const auto deepest =
      static_cast<std::size_t>(std::min_element(grid_.h_m.begin(), grid_.h_m.end()) - grid_.h_m.begin());
  const double uniform = dh_m[deepest];
  Eigen::VectorXd dh(approach_column_.size());
  for (Eigen::Index r = 0; r < dh.size(); ++r)
    dh(r) = dh_m[active_[static_cast<std::size_t>(r)]] - (1.0 - approach_column_(r)) * uniform;
  return dh;
}

std::optional<double> Mim1dSolver::approach_sensitivity(const std::vector<double>& dh_m, double load_change_N) const {
  const auto n = static_cast<Eigen::Index>(active_.size());
  if (options_.update != Mim1dUpdate::Newton || n == 0 || factorisation_.rows() != n || approach_column_.size() != n ||
      dh_m.size() != grid_.size())
    return std::nullopt;
  const Eigen::VectorXd dh = active_gap_change(dh_m);
  const double unit = load_sum(factorisation_.solve(approach_column_));
  const double change = (load_change_N + load_sum(factorisation_.solve(dh))) / unit;
  if (!std::isfinite(change)) return std::nullopt;
  return change;
}

bool Mim1dSolver::shift_warm_start(const std::vector<double>& dh_m, double load_change_N, Mim1dWarmStart& start) const {
  const auto n = static_cast<Eigen::Index>(active_.size());
  if (options_.update != Mim1dUpdate::Newton || n == 0 || factorisation_.rows() != n || approach_column_.size() != n ||
      dh_m.size() != grid_.size() || start.empty() ||
      start.first_strip != first_strip_index() + static_cast<long>(active_.front()))
    return false;
  const Eigen::VectorXd dh = active_gap_change(dh_m);
  const Eigen::VectorXd unit = factorisation_.solve(approach_column_);
  const Eigen::VectorXd shift = factorisation_.solve(dh);
  const double d_approach = (load_change_N + load_sum(shift)) / load_sum(unit);
  if (!std::isfinite(d_approach)) return false;
  for (Eigen::Index r = 0; r < n; ++r) {
    double& load = start.loads_N[active_[static_cast<std::size_t>(r)] - active_.front()];
    const double predicted = load + d_approach * unit(r) - shift(r);
    load = predicted > 0.0 ? predicted : kWarmStartShrink * load;
  }
  const auto deepest =
      static_cast<std::size_t>(std::min_element(grid_.h_m.begin(), grid_.h_m.end()) - grid_.h_m.begin());
  start.depth_m += d_approach - dh_m[deepest];
  return true;
}

void move_warm_start_origin(const Mim1dWarmStart& start, double origin_shift_m, double strip_width_m,
                            Mim1dWarmStart& out) {
  out.loads_N.clear();
  out.depth_m = start.depth_m;
  out.origin_y_m = start.origin_y_m;
  out.origin_angle_rad = start.origin_angle_rad;
  out.sampling_approach_m = start.sampling_approach_m;
  out.same_contact = start.same_contact;
  const double shift = origin_shift_m / strip_width_m;  // new strip k sits at the saved fractional index k + shift
  if (start.empty() || !std::isfinite(shift) || std::abs(shift) > static_cast<double>(kMaxStripsPerPatch)) return;
  const auto count = static_cast<long>(start.loads_N.size());
  out.first_strip = static_cast<long>(std::floor(static_cast<double>(start.first_strip) - shift));
  const long last = static_cast<long>(std::ceil(static_cast<double>(start.first_strip + count - 1) - shift));
  auto saved = [&](long j) { return j >= 0 && j < count ? start.loads_N[static_cast<std::size_t>(j)] : 0.0; };
  for (long k = out.first_strip; k <= last; ++k) {
    const double j = static_cast<double>(k) + shift - static_cast<double>(start.first_strip);
    const double j0 = std::floor(j), t = j - j0;
    const auto i = static_cast<long>(j0);
    out.loads_N.push_back((1.0 - t) * saved(i) + t * saved(i + 1));
  }
}

void extrapolate_warm_start(const Mim1dWarmStart& start, Mim1dWarmStart& out) {
  const Mim1dWarmStart::Earlier& earlier = start.earlier;
  out.first_strip = start.first_strip;
  out.loads_N = start.loads_N;
  out.depth_m = start.depth_m;
  out.origin_y_m = start.origin_y_m;
  out.origin_angle_rad = start.origin_angle_rad;
  out.sampling_approach_m = start.sampling_approach_m;
  out.same_contact = false;
  out.earlier.loads_N.clear();
  if (start.empty() || earlier.loads_N.empty()) return;
  const auto count = static_cast<long>(earlier.loads_N.size());
  for (std::size_t i = 0; i < out.loads_N.size(); ++i) {
    double& load = out.loads_N[i];
    if (!(load > 0.0)) continue;
    const long k = start.first_strip + static_cast<long>(i) - earlier.first_strip;  // index into the earlier loads
    const double before = k >= 0 && k < count ? earlier.loads_N[static_cast<std::size_t>(k)] : 0.0;
    const double predicted = 2.0 * load - before;
    load = predicted > 0.0 ? predicted : kWarmStartShrink * load;
  }
  if (const double depth = 2.0 * start.depth_m - earlier.depth_m; depth > 0.0) out.depth_m = depth;
  if (const double x = 2.0 * start.sampling_approach_m - earlier.sampling_approach_m;
      x > 0.0 && earlier.sampling_approach_m > 0.0)
    out.sampling_approach_m = x;
}

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N) {
  return solve_for_load(normal_force_N, Mim1dWarmStart{});
}

// Restores the solver's own tolerance when a solve with a looser or an early-stopping one ends, also by an exception
// (a workspace's solver outlives a case that throws).
class Mim1dSolver::ToleranceScope {
 public:
  explicit ToleranceScope(Mim1dSolver& solver) : solver_(solver) {}
  ToleranceScope(const ToleranceScope&) = delete;
  ToleranceScope& operator=(const ToleranceScope&) = delete;
  ~ToleranceScope() {
    solver_.early_stop_.reset();
    solver_.tolerance_ = solver_.solve_tolerance_ = solver_.options_.tolerance;
  }

 private:
  Mim1dSolver& solver_;
};

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N, const Mim1dWarmStart& warm_start, double tolerance) {
  const ToleranceScope scope(*this);
  tolerance_ = std::max(tolerance, options_.tolerance);
  return solve_for_load(normal_force_N, warm_start);
}

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N, const Mim1dWarmStart& warm_start, double tolerance,
                                           const EarlyStop& early_stop) {
  const ToleranceScope scope(*this);
  solve_tolerance_ = std::max(tolerance, options_.tolerance);
  early_stop_ = early_stop;
  early_stop_->tolerance = std::max(early_stop.tolerance, solve_tolerance_);
  tolerance_ = solve_tolerance_;
  return solve_for_load(normal_force_N, warm_start);
}

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N, const Mim1dWarmStart& warm_start) {
  const auto start = std::chrono::steady_clock::now();
  const double entries_before = matrix_entries_;
  int iterations = 0;
  NormalSolution solution;
  if (std::isfinite(normal_force_N) && normal_force_N > 0.0) {
    // Combined iteration on loads and approach, from the neighbour's solution or from Hertz at the deepest point
    // (the paper's start); a warm start that fails is repeated cold.
    double approach = 0.0;
    const bool warm = load_warm_start(warm_start, approach);
    if (!warm) approach = hertz_start_approach(normal_force_N);
    InnerResult inner = solve_inner(approach, warm, &normal_force_N);
    iterations = inner.iterations;
    if (warm && inner.status != SolveStatus::Converged) {
      approach = hertz_start_approach(normal_force_N);
      inner = solve_inner(approach, false, &normal_force_N);
      iterations += inner.iterations;
    }
    if (inner.status == SolveStatus::Converged) {
      update_lengths();
      solution = make_solution(inner.status, approach);
      solution.iterations = iterations;
      solution.outer_iterations = 1;
      solution.residual = std::abs(prescribed_load() - normal_force_N) / normal_force_N;
    }
  }
  if (solution.status != SolveStatus::Converged && solution.status != SolveStatus::ZoneTruncated)
    solution = solve_for_load_nested(normal_force_N, iterations);
  solution.solve_time_s = seconds_since(start);
  solution.matrix_entries = matrix_entries_ - entries_before;
  return solution;
}

NormalSolution Mim1dSolver::solve_for_load_nested(double normal_force_N, int& iterations) {
  auto finish = [&](SolveStatus status, double approach, int outer, double residual) {
    NormalSolution solution = make_solution(status, approach);
    if (!is_success(status)) solution.patches.clear(), solution.normal_load_N = 0.0;
    solution.iterations = iterations;
    solution.outer_iterations = outer;
    solution.residual = residual;
    return solution;
  };
  const auto deepest =
      static_cast<std::size_t>(std::min_element(grid_.h_m.begin(), grid_.h_m.end()) - grid_.h_m.begin());
  const double h_min = grid_.h_m[deepest];
  if (!(std::isfinite(normal_force_N) && normal_force_N >= 0.0)) {
    active_.clear();
    return finish(SolveStatus::InvalidInput, h_min, 0, 0.0);
  }
  if (normal_force_N == 0.0) {
    active_.clear();
    return finish(SolveStatus::NoContact, h_min, 0, 0.0);
  }
  double approach = hertz_start_approach(normal_force_N);
  double lower = h_min, upper = std::numeric_limits<double>::infinity();
  bool warm = false;
  Eigen::VectorXd ones, slope_vector;
  auto eq16 = [&](double force) {  // paper Eq. 16, with delta measured from first contact
    return h_min + (approach - h_min) * std::cbrt((normal_force_N / force) * (normal_force_N / force));
  };
  for (int outer = 1; outer <= options_.max_outer_iterations; ++outer) {
    double solved_approach = approach;
    const InnerResult inner = solve_inner(solved_approach, warm, nullptr);
    iterations += inner.iterations;
    if (inner.status == SolveStatus::NoContact) {
      lower = approach;
      approach = std::isfinite(upper) ? 0.5 * (lower + upper)
                                      : h_min + kNoContactGrowth * (approach - h_min) + kNoContactNudge_m;
      warm = false;
      continue;
    }
    if (inner.status != SolveStatus::Converged) return finish(inner.status, approach, outer, inner.residual);
    update_lengths();
    const double force = prescribed_load();
    const double mismatch = force - normal_force_N;
    const double force_residual = std::abs(mismatch) / normal_force_N;
    if (force_residual <= tolerance_) return finish(SolveStatus::Converged, approach, outer, force_residual);
    (mismatch < 0.0 ? lower : upper) = approach;
    // Newton on delta with dN/d(delta) = w^T J^-1 1 from the last factorisation.
    const auto n = static_cast<Eigen::Index>(active_.size());
    ones.setOnes(n);
    slope_vector = factorisation_.rows() == n ? Eigen::VectorXd(factorisation_.solve(ones)) : Eigen::VectorXd();
    const double slope = slope_vector.size() == n ? load_sum(slope_vector) : 0.0;
    double next = (slope > 0.0 && std::isfinite(slope)) ? approach - mismatch / slope : eq16(force);
    if (!(next > lower && next < upper)) {
      next = std::isfinite(upper) ? 0.5 * (lower + upper) : eq16(force);
      if (!(next > lower)) next = h_min + kNoContactGrowth * (approach - h_min);
    }
    if (slope_vector.size() == n) {  // warm start along dN/d(delta)
      for (Eigen::Index r = 0; r < n; ++r) {
        const std::size_t i = active_[static_cast<std::size_t>(r)];
        const double predicted = load_[i] + slope_vector(r) * (next - approach);
        load_[i] = predicted > 0.0 ? predicted : kWarmStartShrink * load_[i];
      }
    }
    approach = next;
    warm = true;
  }
  return finish(SolveStatus::MaxIterations, approach, options_.max_outer_iterations, 1.0);
}

}  // namespace ctab::gen
