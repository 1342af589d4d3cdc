// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/hertz.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <vector>
#include <numbers>

#include "ctab/contact/elliptic.hpp"
#include "ctab/contact/root_finding.hpp"
#ifndef CTAB_RUNTIME_CONTACT_TABLES
#include "contact_tables.inc"  // generated at build time by contact_tables_gen (generator/CMakeLists.txt)
#endif

namespace ctab::gen {

namespace {

// Curvature ratio A_small/B_large of the ellipse with squared semi-axis ratio mc = g^2 = 1 - m_e.
double curvature_ratio(double mc) noexcept {
  const CompleteElliptic ce = complete_elliptic_from_complement(mc);
  const double b_associate = ce.K - ce.D;  // (E - mc K)/m_e
  return mc * ce.D / b_associate;
}

// Squared semi-axis ratio g^2 for a curvature ratio rho = A_small/B_large in (0, 1]. `log_hint` (ln g^2 of a
// nearby ratio, or NaN) narrows the starting bracket.
double squared_axis_ratio(double rho, double log_hint = std::numeric_limits<double>::quiet_NaN()) noexcept {
  if (rho >= 1.0 - 1.0e-14) return 1.0;
  const double log_rho = std::log(rho);
  auto f = [log_rho](double s) { return std::log(curvature_ratio(std::exp(s))) - log_rho; };
  // f decreases towards s -> -inf and is -log(rho) > 0 at s = 0.
  double s_lo = 0.0, s_hi = 0.0, f_lo = 0.0, f_hi = f(0.0);
  if (std::isfinite(log_hint)) {
    s_hi = std::min(0.0, log_hint + 0.02);
    f_hi = f(s_hi);
    s_lo = log_hint - 0.02;
    f_lo = f(s_lo);
    if (f_hi < 0.0) {  // hint too low: fall back to the full bracket
      s_hi = 0.0;
      f_hi = f(0.0);
    }
  } else {
    // Greenwood (1985): a/b ~ (B/A)^(2/3), so log(g^2) ~ (4/3) log(rho); widen until bracketed.
    s_lo = 1.5 * (4.0 / 3.0) * log_rho - 0.5;
    f_lo = f(s_lo);
  }
  while (f_lo > 0.0 && s_lo > -700.0) {
    s_lo = 2.0 * s_lo - 0.5;
    f_lo = f(s_lo);
  }
  const RootResult root = find_root_bracketed(f, s_lo, f_lo, s_hi, f_hi, 1.0e-15, 1.0e-15, 200);
  return std::exp(root.x);
}

bool coefficients_from_ratio(double A_per_m, double B_per_m, double log_hint, HertzCoefficients& out, double* log_mc) {
  out = HertzCoefficients{};
  if (!(std::isfinite(A_per_m) && std::isfinite(B_per_m) && A_per_m > 0.0 && B_per_m > 0.0)) return false;
  const double rho = std::min(A_per_m, B_per_m) / std::max(A_per_m, B_per_m);
  const double mc = squared_axis_ratio(rho, log_hint);
  if (log_mc) *log_mc = std::log(mc);
  const double g = std::sqrt(mc);
  const CompleteElliptic ce = complete_elliptic_from_complement(mc);
  const double small = std::cbrt(2.0 * g * ce.E / std::numbers::pi);  // coefficient of the shorter semi-axis
  const double large = small / g;
  out.r = small * small * ce.K / ce.E;
  if (A_per_m <= B_per_m) {
    out.m = large;
    out.n = small;
  } else {
    out.m = small;
    out.n = large;
  }
  return true;
}

}  // namespace

bool hertz_coefficients(double A_per_m, double B_per_m, HertzCoefficients& out) noexcept {
  return coefficients_from_ratio(A_per_m, B_per_m, std::numeric_limits<double>::quiet_NaN(), out, nullptr);
}

namespace {

constexpr double kHalfRange = 12.0, kNodesPerUnit = 64.0;  // nodes of the coefficient table in x = ln(B/A)
constexpr std::size_t kNodeCount = static_cast<std::size_t>(2 * kHalfRange * kNodesPerUnit) + 1;
static_assert(kNodeCount == kHertzTableNodes);

std::array<double, 3> coefficients_at(double x, double& log_hint) {
  HertzCoefficients c;
  (void)coefficients_from_ratio(1.0, std::exp(x), log_hint, c, &log_hint);
  return {c.m, c.n, c.r};
}

// The table in use: compiled in (contact_tables_gen), or computed once per process in a build without it.
const HertzTableNode* table_in_use() {
#ifndef CTAB_RUNTIME_CONTACT_TABLES
  return generated::kHertzTable.data();
#else
  static const std::vector<HertzTableNode> table = build_hertz_table();
  return table.data();
#endif
}

// Cubic Hermite in x between the nodes; false outside |x| < kHalfRange.
bool table_lookup(double x, HertzCoefficients& out) {
  if (!(std::abs(x) < kHalfRange)) return false;
  const HertzTableNode* nodes = table_in_use();
  const double u = (x + kHalfRange) * kNodesPerUnit;
  const auto k = std::min(static_cast<std::size_t>(u), kNodeCount - 2);
  const double t = u - static_cast<double>(k), h = 1.0 / kNodesPerUnit;
  const double t2 = t * t, t3 = t2 * t;
  std::array<double, 3> v{};
  for (std::size_t c = 0; c < 3; ++c)
    v[c] = (2 * t3 - 3 * t2 + 1) * nodes[k].value[c] + (t3 - 2 * t2 + t) * h * nodes[k].slope[c] +
           (-2 * t3 + 3 * t2) * nodes[k + 1].value[c] + (t3 - t2) * h * nodes[k + 1].slope[c];
  out = {v[0], v[1], v[2]};
  return true;
}

}  // namespace

std::vector<HertzTableNode> build_hertz_table() {
  std::vector<HertzTableNode> nodes(kNodeCount);
  // Nodes from the circle outwards (x = 0 is a circle), each inversion bracketed by its neighbour's solution.
  const auto centre = static_cast<std::size_t>(kHalfRange * kNodesPerUnit);
  for (const int direction : {+1, -1}) {
    double hint = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t k = centre;; k += static_cast<std::size_t>(direction)) {
      nodes[k].value = coefficients_at(-kHalfRange + static_cast<double>(k) / kNodesPerUnit, hint);
      if (k == 0 || k + 1 == kNodeCount) break;
    }
  }
  // Slopes by the fourth-order 5-point stencil on the nodes (one-sided near the ends).
  const double h = 1.0 / kNodesPerUnit;
  for (std::size_t k = 0; k < kNodeCount; ++k)
    for (std::size_t c = 0; c < 3; ++c) {
      auto v = [&](std::size_t i) { return nodes[i].value[c]; };
      double& slope = nodes[k].slope[c];
      if (k >= 2 && k + 2 < kNodeCount) slope = (v(k - 2) - 8 * v(k - 1) + 8 * v(k + 1) - v(k + 2)) / (12 * h);
      else if (k < 2) slope = (-25 * v(k) + 48 * v(k + 1) - 36 * v(k + 2) + 16 * v(k + 3) - 3 * v(k + 4)) / (12 * h);
      else slope = (25 * v(k) - 48 * v(k - 1) + 36 * v(k - 2) - 16 * v(k - 3) + 3 * v(k - 4)) / (12 * h);
    }
  return nodes;
}

const HertzTableNode* hertz_table() { return table_in_use(); }

bool hertz_coefficients_tabulated(double A_per_m, double B_per_m, HertzCoefficients& out) noexcept {
  if (!(std::isfinite(A_per_m) && std::isfinite(B_per_m) && A_per_m > 0.0 && B_per_m > 0.0)) {
    out = HertzCoefficients{};
    return false;
  }
  if (table_lookup(std::log(B_per_m / A_per_m), out)) return true;
  return hertz_coefficients(A_per_m, B_per_m, out);
}

HertzContact hertz_from_load(double A_per_m, double B_per_m, double E_star_Pa, double normal_force_N) noexcept {
  HertzContact contact;
  HertzCoefficients c;
  if (!hertz_coefficients(A_per_m, B_per_m, c) || !(E_star_Pa > 0.0) || !std::isfinite(E_star_Pa) ||
      !(normal_force_N >= 0.0) || !std::isfinite(normal_force_N))
    return contact;
  if (normal_force_N == 0.0) {
    contact.status = SolveStatus::NoContact;
    return contact;
  }
  const double sum = A_per_m + B_per_m;
  const double alpha = std::cbrt(3.0 * normal_force_N / (4.0 * E_star_Pa * sum));
  contact.status = SolveStatus::Converged;
  contact.normal_force_N = normal_force_N;
  contact.semi_axis_x_m = c.m * alpha;
  contact.semi_axis_y_m = c.n * alpha;
  contact.area_m2 = std::numbers::pi * contact.semi_axis_x_m * contact.semi_axis_y_m;
  contact.max_pressure_Pa = 1.5 * normal_force_N / contact.area_m2;
  const double force_term = std::cbrt(3.0 * normal_force_N / (4.0 * E_star_Pa));
  contact.approach_m = c.r * force_term * force_term * std::cbrt(sum);
  // Finite inputs can still over- or underflow (a gap scaled by 1e300): a status, never an infinite pressure.
  if (!(contact.area_m2 > 0.0 && std::isfinite(contact.area_m2) && std::isfinite(contact.max_pressure_Pa) &&
        std::isfinite(contact.approach_m) && contact.approach_m > 0.0))
    return HertzContact{.status = SolveStatus::NumericalFailure};
  return contact;
}

HertzContact hertz_from_approach(double A_per_m, double B_per_m, double E_star_Pa, double approach_m) noexcept {
  HertzCoefficients c;
  if (!hertz_coefficients(A_per_m, B_per_m, c) || !(approach_m >= 0.0) || !std::isfinite(approach_m)) return {};
  // Inverse of delta = r (3N/(4E*))^(2/3) (A+B)^(1/3):  N = (4E*/3) (delta/r)^(3/2) / sqrt(A+B).
  const double force = (4.0 * E_star_Pa / 3.0) * std::pow(approach_m / c.r, 1.5) / std::sqrt(A_per_m + B_per_m);
  HertzContact contact = hertz_from_load(A_per_m, B_per_m, E_star_Pa, force);
  if (contact.status == SolveStatus::Converged) contact.approach_m = approach_m;
  return contact;
}

double strip_length_compliance(double A_per_m, double B_per_m, double E_star_Pa) noexcept {
  HertzCoefficients c;
  if (!hertz_coefficients(A_per_m, B_per_m, c)) return 0.0;
  return std::numbers::pi * c.m * c.m * c.n / (2.0 * E_star_Pa * (A_per_m + B_per_m));
}

}  // namespace ctab::gen
