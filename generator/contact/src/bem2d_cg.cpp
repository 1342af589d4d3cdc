// bem2d constrained conjugate gradients: Polonsky & Keer (1999, Wear 231:206-219), steps as in
// ../shared/facts/methods_and_tables.md 1.6.3, for a prescribed load (as published) or a prescribed approach
// (the bound-constrained QP min 1/2 p'Ap + p'(h - delta), p >= 0: no mean subtraction, no rescaling).
#include <algorithm>
#include <cmath>

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

}  // namespace

void initial_pressure(InfluenceConvolution& influence, const ElementGrid& grid, Prescribed prescribed, double target,
                      double estimated_approach, std::vector<double>& pressure) {
  pressure.assign(grid.h.size(), 0.0);
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

CgResult solve_constrained_cg(InfluenceConvolution& influence, const ElementGrid& grid, Prescribed prescribed,
                              double target, const Bem2dGrid& options, std::vector<double>& p) {
  const bool load = prescribed == Prescribed::Load;
  const double element_area = grid.dx * grid.dy;
  const std::size_t n = p.size();
  Workspace w;
  w.g.assign(n, 0.0);
  w.t.assign(n, 0.0);
  w.previous.assign(n, 0.0);
  influence.apply(p, w.u);
  CgResult result;
  result.approach = load ? 0.0 : target;
  double G_old = 1.0;
  bool conjugate = false;
  int since_refresh = 0;
  const int cap = std::clamp(options.max_iterations, 1, kBem2dMaxIterations);
  for (int it = 1; it <= cap; ++it) {
    result.iterations = it;
    // Step 1: deformed distance on the potential area, measured from the mean over the contact set (load) or from
    // the prescribed approach.
    for (std::size_t e = 0; e < n; ++e) w.g[e] = w.u[e] + grid.h[e];
    const double datum = load ? contact_mean(w.g, p) : target;
    if (load) result.approach = datum;
    double G = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
      w.g[e] -= datum;
      if (p[e] > 0.0) G += w.g[e] * w.g[e];
    }
    // Steps 2-3: conjugate direction on the contact set.
    const double beta = conjugate ? G / G_old : 0.0;
    for (std::size_t e = 0; e < n; ++e) w.t[e] = p[e] > 0.0 ? w.g[e] + beta * w.t[e] : 0.0;
    G_old = G;
    // Steps 4-5: step length.
    influence.apply(w.t, w.r);
    const double r_mean = load ? contact_mean(w.r, p) : 0.0;
    double gt = 0.0, rt = 0.0;
    for (std::size_t e = 0; e < n; ++e)
      if (p[e] > 0.0) {
        gt += w.g[e] * w.t[e];
        rt += (w.r[e] - r_mean) * w.t[e];
      }
    if (std::none_of(p.begin(), p.end(), [](double v) { return v > 0.0; })) {
      result.status = SolveStatus::NoContact;
      return result;
    }
    if (G == 0.0) {  // exact solution on the set (all residuals zero)
      result.status = SolveStatus::Converged;
      result.residual = 0.0;
      return result;
    }
    if (!(rt > 0.0) || !std::isfinite(gt)) {
      result.status = SolveStatus::NumericalFailure;
      return result;
    }
    const double tau = gt / rt;
    // Steps 6-7: update, project onto p >= 0, open overlapping elements.
    w.previous = p;
    bool projected = false, overlap = false;
    for (std::size_t e = 0; e < n; ++e) {
      if (p[e] > 0.0) {
        p[e] -= tau * w.t[e];
        if (p[e] <= 0.0) {
          p[e] = 0.0;
          projected = true;
        }
      } else if (grid.potential[e] && w.g[e] < 0.0) {
        p[e] = -tau * w.g[e];
        overlap = true;
      }
    }
    conjugate = !overlap;
    // Step 8: rescale to the load.
    double scale = 1.0;
    if (load) {
      const double force = total(p) * element_area;
      if (!(force > 0.0)) {
        result.status = SolveStatus::NumericalFailure;
        return result;
      }
      scale = target / force;
      for (double& v : p) v *= scale;
    }
    // u = A p: incremental when the step was a plain CG step, else afresh.
    if (projected || overlap || ++since_refresh >= kRefreshInterval) {
      influence.apply(p, w.u);
      since_refresh = 0;
    } else {
      for (std::size_t e = 0; e < n; ++e) w.u[e] = scale * (w.u[e] - tau * w.r[e]);
    }
    // Step 9: relative change of the pressure.
    double change = 0.0, sum = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
      change += std::abs(p[e] - w.previous[e]);
      sum += p[e];
    }
    if (!std::isfinite(change) || !std::isfinite(sum)) {
      result.status = SolveStatus::NumericalFailure;
      return result;
    }
    if (sum == 0.0) {  // approach too small for any element to stay loaded: no contact
      result.status = SolveStatus::NoContact;
      return result;
    }
    result.residual = change / sum;
    if (result.residual < options.tolerance && !projected && !overlap) {
      if (load) {  // the approach of the final field
        for (std::size_t e = 0; e < n; ++e) w.g[e] = w.u[e] + grid.h[e];
        result.approach = contact_mean(w.g, p);
      }
      result.status = SolveStatus::Converged;
      return result;
    }
  }
  result.status = SolveStatus::MaxIterations;
  return result;
}

}  // namespace ctab::gen::bem2d
