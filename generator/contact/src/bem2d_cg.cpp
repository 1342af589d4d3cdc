// SPDX-License-Identifier: Apache-2.0
// bem2d constrained conjugate gradients: Polonsky & Keer (1999, Wear 231:206-219), steps as in
// ../shared/facts/methods_and_tables.md 1.6.3, for a prescribed load (as published) or a prescribed approach
// (the bound-constrained QP min 1/2 p'Ap + p'(h - delta), p >= 0: no mean subtraction, no rescaling).
#include <algorithm>
#include <cmath>
#include <optional>

#include "bem2d_internal.hpp"

namespace ctab::gen::bem2d {

namespace {

// Re-evaluate u = A p from scratch at least this often, against drift of the incremental update [iterations].
constexpr int kRefreshInterval = 25;

struct Workspace {
  std::vector<double> u, g, t, r, previous;
};

// Mean of v over the contact set (p > 0); 0 for an empty set.
double contact_mean(const std::vector<double>& v, const std::vector<double>& p) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t e = 0; e < p.size(); ++e)
    if (p[e] > 0.0) {
      sum += v[e];
      ++count;
    }
  return count ? sum / static_cast<double>(count) : 0.0;
}

double total(const std::vector<double>& p) {
  double sum = 0.0;
  for (const double v : p) sum += v;
  return sum;
}

// `start`'s pressure at the nearest of its element centres to each potential element of `grid` (0 outside it).
void pressure_from_field(const ElementGrid& grid, const Bem2dPressureField& start, std::vector<double>& pressure) {
  for (std::size_t j = 0; j < grid.ny; ++j) {
    const double sj = std::round((grid.y0 + static_cast<double>(j) * grid.dy - start.y0_m) / start.dy_m);
    if (!(sj >= 0.0 && sj < static_cast<double>(start.ny))) continue;
    for (std::size_t i = 0; i < grid.nx; ++i) {
      const double si = std::round((grid.x0 + static_cast<double>(i) * grid.dx - start.x0_m) / start.dx_m);
      const std::size_t e = j * grid.nx + i;
      if (grid.potential[e] && si >= 0.0 && si < static_cast<double>(start.nx))
        pressure[e] = start.at(static_cast<std::size_t>(si), static_cast<std::size_t>(sj));
    }
  }
}

}  // namespace

void initial_pressure(InfluenceConvolution& influence, const ElementGrid& grid, Prescribed prescribed, double target,
                      double estimated_approach, std::vector<double>& pressure, const Bem2dPressureField* start) {
  pressure.assign(grid.h.size(), 0.0);
  if (start != nullptr && !start->empty()) pressure_from_field(grid, *start, pressure);
  if (total(pressure) == 0.0)
    for (std::size_t e = 0; e < pressure.size(); ++e)
      if (grid.potential[e]) pressure[e] = std::sqrt(std::max(estimated_approach - grid.h[e], 0.0));
  if (total(pressure) == 0.0)  // the estimate lies below every element centre: start uniform on the potential area
    for (std::size_t e = 0; e < pressure.size(); ++e) pressure[e] = grid.potential[e] ? 1.0 : 0.0;
  if (prescribed == Prescribed::Load) {
    const double sum = total(pressure) * grid.dx * grid.dy;
    if (sum > 0.0)
      for (double& p : pressure) p *= target / sum;
    return;
  }
  // Line search along q = pressure on 1/2 s^2 q'Aq - s q'(delta - h).
  std::vector<double> u;
  influence.apply(pressure, u);
  double numerator = 0.0, denominator = 0.0;
  for (std::size_t e = 0; e < pressure.size(); ++e) {
    numerator += pressure[e] * (target - grid.h[e]);
    denominator += pressure[e] * u[e];
  }
  const double scale = denominator > 0.0 && numerator > 0.0 ? numerator / denominator : 0.0;
  for (double& p : pressure) p *= scale;
}

namespace {

// How a step of the pressure ended (steps 6-7): elements set to zero by the projection, or opened where the
// deformed surfaces overlap; either makes the next direction steepest descent and u = A p be evaluated afresh.
struct StepKind {
  bool projected = false, overlap = false;
};

// One constrained CG solve: the pressure p (in/out) and the iteration's vectors and scalars, one method per step
// of the published algorithm.
class ConstrainedCg {
 public:
  ConstrainedCg(InfluenceConvolution& influence, const ElementGrid& grid, Prescribed prescribed, double target,
                std::vector<double>& p)
      : influence_(influence), grid_(grid), load_(prescribed == Prescribed::Load), target_(target),
        element_area_(grid.dx * grid.dy), p_(p) {
    const std::size_t n = p.size();
    w_.g.assign(n, 0.0);
    w_.t.assign(n, 0.0);
    w_.previous.assign(n, 0.0);
    influence_.apply(p_, w_.u);
  }

  // One iteration (steps 1-9); a status when the solve ends there.
  std::optional<SolveStatus> iteration(double tolerance, CgResult& result) {
    const double G = deformed_distance(result);
    conjugate_direction(G);
    double gt = 0.0, rt = 0.0;
    step_products(gt, rt);
    if (std::none_of(p_.begin(), p_.end(), [](double v) { return v > 0.0; })) return SolveStatus::NoContact;
    if (G == 0.0) {  // exact solution on the set (all residuals zero)
      result.residual = 0.0;
      return SolveStatus::Converged;
    }
    if (!(rt > 0.0) || !std::isfinite(gt)) return SolveStatus::NumericalFailure;
    const double tau = gt / rt;
    const StepKind step = update_pressure(tau);
    double scale = 1.0;
    if (load_ && !rescale_to_load(scale)) return SolveStatus::NumericalFailure;
    update_displacement(step, tau, scale);
    return relative_change(tolerance, step, result);
  }

 private:
  // Step 1: deformed distance on the potential area, measured from the mean over the contact set (load) or from
  // the prescribed approach; returns its squared norm over the contact set.
  double deformed_distance(CgResult& result) {
    const std::size_t n = p_.size();
    for (std::size_t e = 0; e < n; ++e) w_.g[e] = w_.u[e] + grid_.h[e];
    const double datum = load_ ? contact_mean(w_.g, p_) : target_;
    if (load_) result.approach = datum;
    double G = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
      w_.g[e] -= datum;
      if (p_[e] > 0.0) G += w_.g[e] * w_.g[e];
    }
    return G;
  }

  // Steps 2-3: conjugate direction on the contact set.
  void conjugate_direction(double G) {
    const double beta = conjugate_ ? G / G_old_ : 0.0;
    for (std::size_t e = 0; e < p_.size(); ++e) w_.t[e] = p_[e] > 0.0 ? w_.g[e] + beta * w_.t[e] : 0.0;
    G_old_ = G;
  }

  // Steps 4-5: the products of the step length tau = g't / r't, r = A t (less its contact mean for a load).
  void step_products(double& gt, double& rt) {
    influence_.apply(w_.t, w_.r);
    const double r_mean = load_ ? contact_mean(w_.r, p_) : 0.0;
    for (std::size_t e = 0; e < p_.size(); ++e)
      if (p_[e] > 0.0) {
        gt += w_.g[e] * w_.t[e];
        rt += (w_.r[e] - r_mean) * w_.t[e];
      }
  }

  // Steps 6-7: update, project onto p >= 0, open overlapping elements.
  StepKind update_pressure(double tau) {
    w_.previous = p_;
    StepKind step;
    for (std::size_t e = 0; e < p_.size(); ++e) {
      if (p_[e] > 0.0) {
        p_[e] -= tau * w_.t[e];
        if (p_[e] <= 0.0) {
          p_[e] = 0.0;
          step.projected = true;
        }
      } else if (grid_.potential[e] && w_.g[e] < 0.0) {
        p_[e] = -tau * w_.g[e];
        step.overlap = true;
      }
    }
    conjugate_ = !step.overlap;
    return step;
  }

  // Step 8: rescale to the load; false when no force is left.
  bool rescale_to_load(double& scale) {
    const double force = total(p_) * element_area_;
    if (!(force > 0.0)) return false;
    scale = target_ / force;
    for (double& v : p_) v *= scale;
    return true;
  }

  // u = A p: incremental when the step was a plain CG step, else afresh.
  void update_displacement(const StepKind& step, double tau, double scale) {
    if (step.projected || step.overlap || ++since_refresh_ >= kRefreshInterval) {
      influence_.apply(p_, w_.u);
      since_refresh_ = 0;
    } else {
      for (std::size_t e = 0; e < p_.size(); ++e) w_.u[e] = scale * (w_.u[e] - tau * w_.r[e]);
    }
  }

  // Step 9: relative change of the pressure; converged below `tolerance` after a plain CG step.
  std::optional<SolveStatus> relative_change(double tolerance, const StepKind& step, CgResult& result) {
    const std::size_t n = p_.size();
    double change = 0.0, sum = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
      change += std::abs(p_[e] - w_.previous[e]);
      sum += p_[e];
    }
    if (!std::isfinite(change) || !std::isfinite(sum)) return SolveStatus::NumericalFailure;
    if (sum == 0.0) return SolveStatus::NoContact;  // approach too small for any element to stay loaded
    result.residual = change / sum;
    if (!(result.residual < tolerance && !step.projected && !step.overlap)) return std::nullopt;
    if (load_) {  // the approach of the final field
      for (std::size_t e = 0; e < n; ++e) w_.g[e] = w_.u[e] + grid_.h[e];
      result.approach = contact_mean(w_.g, p_);
    }
    return SolveStatus::Converged;
  }

  InfluenceConvolution& influence_;
  const ElementGrid& grid_;
  const bool load_;
  const double target_;
  const double element_area_;  // [m^2]
  std::vector<double>& p_;
  Workspace w_;
  double G_old_ = 1.0;
  bool conjugate_ = false;
  int since_refresh_ = 0;
};

}  // namespace

CgResult solve_constrained_cg(InfluenceConvolution& influence, const ElementGrid& grid, Prescribed prescribed,
                              double target, const Bem2dGrid& options, std::vector<double>& p) {
  ConstrainedCg cg(influence, grid, prescribed, target, p);
  CgResult result;
  result.approach = prescribed == Prescribed::Load ? 0.0 : target;
  const int cap = std::clamp(options.max_iterations, 1, kBem2dMaxIterations);
  for (int it = 1; it <= cap; ++it) {
    result.iterations = it;
    if (const std::optional<SolveStatus> status = cg.iteration(options.tolerance, result)) {
      result.status = *status;
      return result;
    }
  }
  result.status = SolveStatus::MaxIterations;
  return result;
}

}  // namespace ctab::gen::bem2d
