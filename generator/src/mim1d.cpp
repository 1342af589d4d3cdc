#include "ctab/gen/mim1d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "ctab/gen/error.hpp"
#include "ctab/gen/hertz.hpp"
#include "ctab/gen/strip_kernel.hpp"

namespace ctab::gen {

namespace {

constexpr double kPi = std::numbers::pi;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Mim1dSolver::Mim1dSolver(const GapProfile& gap, double E_star_Pa, const Mim1dOptions& options)
    : grid_(make_strip_grid(gap, options.strip_width_m)), E_star_Pa_(E_star_Pa), options_(options) {
  if (!(std::isfinite(E_star_Pa) && E_star_Pa > 0.0))
    throw InputError("material", 0, "effective modulus must be positive and finite");
  if (!(options.tolerance > 0.0 && options.tolerance < 1e-2))
    throw InputError("tolerance", 0, "must lie in (0, 0.01)");
  if (options.max_iterations < 1 || options.max_outer_iterations < 1)
    throw InputError("max iterations", 0, "must be at least 1");
  if (options.curvature.smoothing_fraction <= 0.0 || !std::isfinite(options.curvature.smoothing_fraction))
    throw InputError("smoothing fraction", 0, "must be positive and finite");
  b_ = grid_.half_width_m();
  kernel_scale_ = 2.0 / (kPi * kPi * E_star_Pa_ * b_);
  const std::size_t n = grid_.size();
  load_.assign(n, 0.0);
  length_.assign(n, 0.0);
  compliance_.assign(n, 0.0);
  active_.reserve(n);
  column_h_.resize(n + 1);
  column_q_.resize(n + 1);
  (void)StripKernel::instance();  // build the kernel table at setup, not inside the first solve
}

void Mim1dSolver::update_lengths() {
  for (const std::size_t j : active_) length_[j] = std::sqrt(compliance_[j] * load_[j] / (kPi * b_));
}

void Mim1dSolver::build_matrices(bool with_jacobian) {
  const StripKernel& kernel = StripKernel::instance();
  const auto n = static_cast<Eigen::Index>(active_.size());
  influence_.resize(n, n);
  if (with_jacobian) jacobian_.resize(n, n);
  const std::size_t first = active_.front(), last = active_.back();
  for (Eigen::Index c = 0; c < n; ++c) {
    const std::size_t j = active_[static_cast<std::size_t>(c)];
    const double beta = b_ / length_[j];
    const std::size_t reach = std::max(j - first, last - j);
    // H_k = h((2k+1) b/a_j), Q_k = t h'(t) there; column entries are differences of neighbours.
    for (std::size_t k = 0; k <= reach; ++k)
      kernel.value_and_scaled_slope(static_cast<double>(2 * k + 1) * beta, column_h_[k], column_q_[k]);
    for (Eigen::Index r = 0; r < n; ++r) {
      const std::size_t i = active_[static_cast<std::size_t>(r)];
      const std::size_t k = i > j ? i - j : j - i;
      const double dh = k == 0 ? 2.0 * column_h_[0] : column_h_[k] - column_h_[k - 1];
      influence_(r, c) = kernel_scale_ * dh;
      if (with_jacobian) {
        // d(G_ij N_j)/dN_j = G_ij + (a_j/2) dG_ij/da_j, with dh(c/a)/da = -t h'(t)/a.
        const double dq = k == 0 ? 2.0 * column_q_[0] : column_q_[k] - column_q_[k - 1];
        jacobian_(r, c) = kernel_scale_ * (dh - 0.5 * dq);
      }
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
  std::size_t deepest = 0;
  for (std::size_t i = 0; i < grid_.size(); ++i) {
    if (grid_.h_m[i] < grid_.h_m[deepest]) deepest = i;
    if (!(grid_.h_m[i] < approach_m)) continue;
    if (options_.starting_zone_m &&
        (grid_.y_m[i] < options_.starting_zone_m->first || grid_.y_m[i] > options_.starting_zone_m->second))
      continue;
    active_.push_back(i);
  }
  if (active_.empty()) active_.push_back(deepest);
  // Geometric first guess of the strip lengths: rigid half-length at the local interpenetration.
  for (const std::size_t i : active_)
    length_[i] = std::sqrt(std::max(approach_m - grid_.h_m[i], 1e-3 * (approach_m - grid_.h_m[deepest])) /
                           (2.0 * grid_.A_per_m[i]));
}

void Mim1dSolver::admit_strip(std::size_t strip) {
  const auto position = std::lower_bound(active_.begin(), active_.end(), strip);
  std::size_t neighbour = position == active_.end() ? active_.back() : *position;
  if (position != active_.begin()) {
    const std::size_t before = *(position - 1);
    if (position == active_.end() || strip - before < neighbour - strip) neighbour = before;
  }
  const double guess_length = 0.5 * length_[neighbour];
  load_[strip] = kPi * b_ * guess_length * guess_length / compliance_[strip];
  active_.insert(position, strip);
}

Mim1dSolver::InnerResult Mim1dSolver::solve_inner(double approach_m, bool warm_start) {
  InnerResult result;
  const std::size_t n_all = grid_.size();
  const double h_min = *std::min_element(grid_.h_m.begin(), grid_.h_m.end());
  const double depth = approach_m - h_min;
  if (!(depth > 0.0)) {
    active_.clear();
    std::fill(load_.begin(), load_.end(), 0.0);
    result.status = SolveStatus::NoContact;
    return result;
  }
  strip_compliances(grid_, E_star_Pa_, approach_m, options_.curvature, compliance_, scratch_);
  for (std::size_t i = 0; i < n_all; ++i)
    if (grid_.h_m[i] < approach_m && !(compliance_[i] > 0.0 && std::isfinite(compliance_[i]))) {
      result.status = SolveStatus::InvalidInput;
      return result;
    }
  bool loads_known = warm_start && !active_.empty();
  if (loads_known) {  // strips that no longer interpenetrate cannot carry load
    std::erase_if(active_, [&](std::size_t i) {
      if (grid_.h_m[i] < approach_m) return false;
      load_[i] = 0.0;
      return true;
    });
    loads_known = !active_.empty();
  }
  if (!loads_known) initialise_zone(approach_m);

  const double displacement_tolerance = options_.tolerance * depth;
  const bool newton = options_.update == Mim1dUpdate::Newton;
  double last_change = std::numeric_limits<double>::infinity();
  Eigen::VectorXd rhs, residual, next;
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    result.iterations = iteration;
    if (active_.empty()) return result;  // NumericalFailure
    if (loads_known) update_lengths();
    build_matrices(newton && loads_known);
    const auto n = static_cast<Eigen::Index>(active_.size());
    rhs.resize(n);
    next.resize(n);
    Eigen::VectorXd loads(n);
    for (Eigen::Index r = 0; r < n; ++r) {
      const std::size_t i = active_[static_cast<std::size_t>(r)];
      rhs(r) = approach_m - grid_.h_m[i];
      loads(r) = load_[i];
    }
    if (loads_known) {
      residual = influence_ * loads - rhs;
      result.residual = residual.cwiseAbs().maxCoeff() / depth;
      if (!std::isfinite(result.residual)) return result;
      if (last_change <= options_.tolerance && result.residual <= options_.tolerance) {
        // Converged on this set: re-admit strips that interpenetrate after deformation (Eq. 4).
        bool admitted = false;
        for (std::size_t i = 0; i < n_all; ++i) {
          if (!(grid_.h_m[i] < approach_m) || load_[i] > 0.0) continue;
          if (grid_.h_m[i] + displacement_at(i) - approach_m < -displacement_tolerance) {
            admit_strip(i);
            admitted = true;
          }
        }
        if (!admitted) {
          result.status = SolveStatus::Converged;
          return result;
        }
        last_change = std::numeric_limits<double>::infinity();
        continue;
      }
    }
    bool fixed_point_step = !(newton && loads_known);
    if (!fixed_point_step) {
      factorisation_.compute(jacobian_);
      next = loads - factorisation_.solve(residual);
      factorisation_is_jacobian_ = true;
      if ((next.array() <= 0.0).any()) fixed_point_step = true;  // Newton overshoots at a patch edge
    }
    if (fixed_point_step) {
      factorisation_.compute(influence_);
      next = factorisation_.solve(rhs);
      factorisation_is_jacobian_ = false;
    }
    if (!next.allFinite()) return result;
    const double largest = next.maxCoeff();
    if (!(largest > 0.0)) return result;
    // Strips with non-positive load leave the contact (paper Figure 3).
    bool removed = false;
    for (Eigen::Index r = 0; r < n; ++r)
      if (next(r) <= 0.0) {
        load_[active_[static_cast<std::size_t>(r)]] = 0.0;
        removed = true;
      }
    if (removed) {
      for (Eigen::Index r = 0; r < n; ++r)
        if (next(r) > 0.0) load_[active_[static_cast<std::size_t>(r)]] = next(r);
      std::erase_if(active_, [&](std::size_t i) { return load_[i] <= 0.0; });
      loads_known = true;
      last_change = std::numeric_limits<double>::infinity();
      continue;
    }
    last_change = loads_known ? (next - loads).cwiseAbs().maxCoeff() / largest : std::numeric_limits<double>::infinity();
    for (Eigen::Index r = 0; r < n; ++r) load_[active_[static_cast<std::size_t>(r)]] = next(r);
    loads_known = true;
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
  total_iterations_ = 0;
  if (!std::isfinite(approach_m)) {
    NormalSolution invalid = make_solution(SolveStatus::InvalidInput, approach_m);
    invalid.patches.clear();
    return invalid;
  }
  const InnerResult inner = solve_inner(approach_m, false);
  if (inner.status == SolveStatus::Converged) update_lengths();
  NormalSolution solution = make_solution(inner.status, approach_m);
  if (!is_success(inner.status)) solution.patches.clear(), solution.normal_load_N = 0.0;
  solution.iterations = inner.iterations;
  solution.residual = inner.residual;
  solution.solve_time_s = seconds_since(start);
  return solution;
}

NormalSolution Mim1dSolver::solve_for_load(double normal_force_N) {
  const auto start = std::chrono::steady_clock::now();
  auto finish = [&](SolveStatus status, double approach, int iterations, int outer, double residual) {
    NormalSolution solution = make_solution(status, approach);
    if (!is_success(status)) solution.patches.clear(), solution.normal_load_N = 0.0;
    solution.iterations = iterations;
    solution.outer_iterations = outer;
    solution.residual = residual;
    solution.solve_time_s = seconds_since(start);
    return solution;
  };
  const auto deepest = static_cast<std::size_t>(
      std::min_element(grid_.h_m.begin(), grid_.h_m.end()) - grid_.h_m.begin());
  const double h_min = grid_.h_m[deepest];
  if (!(std::isfinite(normal_force_N) && normal_force_N >= 0.0)) {
    active_.clear();
    return finish(SolveStatus::InvalidInput, h_min, 0, 0, 0.0);
  }
  if (normal_force_N == 0.0) {
    active_.clear();
    return finish(SolveStatus::NoContact, h_min, 0, 0, 0.0);
  }
  // Start from Hertz at the deepest point (paper: "the Hertzian rigid body approach").
  const double A0 = grid_.A_per_m[deepest];
  const double B0 = std::max(grid_.B_per_m[deepest], A0 / 20.0);
  const HertzContact hertz = hertz_from_load(A0, B0, E_star_Pa_, normal_force_N);
  double approach = h_min + (hertz.status == SolveStatus::Converged ? hertz.approach_m : 1e-6);
  double lower = h_min, upper = std::numeric_limits<double>::infinity();
  int iterations = 0;
  bool warm = false;
  Eigen::VectorXd ones, slope_vector;
  for (int outer = 1; outer <= options_.max_outer_iterations; ++outer) {
    const InnerResult inner = solve_inner(approach, warm);
    iterations += inner.iterations;
    if (inner.status == SolveStatus::NoContact) {
      lower = approach;
      approach = std::isfinite(upper) ? 0.5 * (lower + upper) : h_min + 2.0 * (approach - h_min) + 1e-9;
      warm = false;
      continue;
    }
    if (inner.status != SolveStatus::Converged) return finish(inner.status, approach, iterations, outer, inner.residual);
    update_lengths();
    double force = 0.0;
    for (const std::size_t i : active_) force += load_[i];
    const double mismatch = force - normal_force_N;
    const double force_residual = std::abs(mismatch) / normal_force_N;
    if (force_residual <= options_.tolerance) return finish(SolveStatus::Converged, approach, iterations, outer, force_residual);
    (mismatch < 0.0 ? lower : upper) = approach;
    // Newton on delta with dN/d(delta) = 1^T J^-1 1 from the last factorisation.
    const auto n = static_cast<Eigen::Index>(active_.size());
    ones.setOnes(n);
    slope_vector = factorisation_.rows() == n ? Eigen::VectorXd(factorisation_.solve(ones)) : Eigen::VectorXd();
    const double slope = slope_vector.size() == n ? slope_vector.sum() : 0.0;
    double next = (slope > 0.0 && std::isfinite(slope)) ? approach - mismatch / slope
                                                        : h_min + (approach - h_min) * std::cbrt(std::pow(normal_force_N / force, 2.0));
    if (!(next > lower && next < upper)) {
      next = std::isfinite(upper) ? 0.5 * (lower + upper)
                                  : h_min + (approach - h_min) * std::cbrt(std::pow(normal_force_N / force, 2.0));  // Eq. 16
      if (!(next > lower)) next = h_min + 2.0 * (approach - h_min);
    }
    if (slope_vector.size() == n) {  // warm start along dN/d(delta)
      for (Eigen::Index r = 0; r < n; ++r) {
        const std::size_t i = active_[static_cast<std::size_t>(r)];
        const double predicted = load_[i] + slope_vector(r) * (next - approach);
        load_[i] = predicted > 0.0 ? predicted : 0.5 * load_[i];
      }
    }
    approach = next;
    warm = true;
  }
  return finish(SolveStatus::MaxIterations, approach, iterations, options_.max_outer_iterations, 1.0);
}

}  // namespace ctab::gen
