// SPDX-License-Identifier: Apache-2.0
// MIM-1D solver (mim1d.hpp): warm starts: a neighbouring solve's loads as the starting set, saved, shifted to
// first order along a gap change, moved with the grid's origin and extrapolated along a chain.
#include <algorithm>
#include <cmath>

#include "ctab/contact/mim1d.hpp"
#include "mim1d_constants.hpp"

namespace ctab::gen {

using namespace mim1d_detail;

long Mim1dSolver::first_strip_index() const noexcept {
  return std::lround(grid_.y_m.front() / grid_.strip_width_m - grid_.centre_offset);
}

bool Mim1dSolver::load_warm_start(const Mim1dWarmStart& start, double& approach_m) {
  if (start.empty() || !(start.depth_m > 0.0 && std::isfinite(start.depth_m))) return false;
  approach_m = *std::min_element(grid_.h_m.begin(), grid_.h_m.end()) + start.depth_m;
  // Several basins of h interpenetrate (tread and flange root in one window): the discrete problem may then hold
  // more than one self-consistent set (one region or two), so a neighbour's solution does not apply and the gap
  // starts cold, with every basin loaded (initialise_zone), as without a warm start. An earlier solve of the same
  // contact does: its set is the one the cold start chose (the Eq. 4 check still opens an unloaded basin), and it
  // spares the repeated gap passes of a two-point contact their cold iterations.
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

}  // namespace ctab::gen
