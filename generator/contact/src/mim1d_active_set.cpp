// SPDX-License-Identifier: Apache-2.0
// MIM-1D solver (mim1d.hpp): the active set of loaded strips: the starting zone (ANALYN), strips admitted when
// they interpenetrate after deformation (Eq. 4), and the cycle detection of the admissions.
#include <algorithm>
#include <cmath>

#include "ctab/contact/mim1d.hpp"
#include "ctab/contact/strip_kernel.hpp"
#include "mim1d_constants.hpp"

namespace ctab::gen {

using namespace mim1d_detail;

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
    load_[i] = kPi * b_ * length * length / local.compliance_m_per_Pa;  // N = pi a b p0 (A1), p0 = a / c (26)
    active_.push_back(i);
  }
  if (active_.empty()) {  // no strip deep enough for ANALYN: the deepest one alone, with a^2 = depth / (2 A)
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
  // Eq. 4 outside the set: an unloaded strip violates it where delta - u_i - h_i exceeds the tolerance. Candidates: the
  // unloaded interpenetrating strips next to the contact, and the deepest strip of every unloaded run of the
  // interpenetration zone (where a separate contact would start).
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

}  // namespace ctab::gen
