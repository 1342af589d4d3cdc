#include "ctab/gen/hertz.hpp"

#include <cmath>
#include <numbers>

#include "ctab/gen/elliptic.hpp"
#include "ctab/gen/root_finding.hpp"

namespace ctab::gen {

namespace {

// Curvature ratio A_small/B_large of the ellipse with squared semi-axis ratio mc = g^2 = 1 - m_e.
double curvature_ratio(double mc) noexcept {
  const CompleteElliptic ce = complete_elliptic_from_complement(mc);
  const double b_associate = ce.K - ce.D;  // (E - mc K)/m_e
  return mc * ce.D / b_associate;
}

// Squared semi-axis ratio g^2 for a curvature ratio rho = A_small/B_large in (0, 1].
double squared_axis_ratio(double rho) noexcept {
  if (rho >= 1.0 - 1.0e-14) return 1.0;
  const double log_rho = std::log(rho);
  auto f = [log_rho](double s) { return std::log(curvature_ratio(std::exp(s))) - log_rho; };
  // Greenwood (1985): a/b ~ (B/A)^(2/3), so log(g^2) ~ (4/3) log(rho); widen until bracketed.
  double s_lo = 1.5 * (4.0 / 3.0) * log_rho - 0.5;
  double f_lo = f(s_lo);
  while (f_lo > 0.0 && s_lo > -700.0) {
    s_lo *= 2.0;
    f_lo = f(s_lo);
  }
  const RootResult root = find_root_bracketed(f, s_lo, f_lo, 0.0, f(0.0), 1.0e-15, 1.0e-15, 200);
  return std::exp(root.x);
}

}  // namespace

bool hertz_coefficients(double A_per_m, double B_per_m, HertzCoefficients& out) noexcept {
  out = HertzCoefficients{};
  if (!(std::isfinite(A_per_m) && std::isfinite(B_per_m) && A_per_m > 0.0 && B_per_m > 0.0)) return false;
  const double rho = std::min(A_per_m, B_per_m) / std::max(A_per_m, B_per_m);
  const double mc = squared_axis_ratio(rho);
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
