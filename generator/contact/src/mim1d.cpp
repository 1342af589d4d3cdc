// SPDX-License-Identifier: Apache-2.0
// MIM-1D solver (mim1d.hpp): set-up on a gap, the prescribed load's measure, the strip lengths of the loads and
// the solution reported from the active set.
#include "ctab/contact/mim1d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ctab/core/error.hpp"
#include "ctab/contact/strip_kernel.hpp"
#include "mim1d_constants.hpp"

namespace ctab::gen {

using namespace mim1d_detail;

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

// Half-lengths from the loads, a_i = sqrt(c_i N_i / (pi b)): Eq. A4 with c_i the strip's compliance of Eq. 26.
void Mim1dSolver::update_lengths() {
  for (const std::size_t j : active_)
    length_[j] = std::sqrt(compliance_[j].compliance_m_per_Pa * load_[j] / (kPi * b_));
}

// The active set as patches of neighbouring strips: p0_i = N_i / (pi a_i b) (Eq. A1), the total force the sum of
// the strip loads (Eq. 15); a converged set that reaches the grid's edge is ZoneTruncated.
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

}  // namespace ctab::gen
