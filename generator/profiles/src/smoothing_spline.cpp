#include "ctab/profiles/smoothing_spline.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ctab/profiles/point_noise.hpp"

namespace ctab::gen {

namespace {

// Fits one coordinate; returns smoothed values f and knot second derivatives g (natural ends: g = 0).
// lambda per point (the penalty's weight relative to point i's residual: lambda_i / w_i).
void fit(const std::vector<double>& s, const std::vector<double>& x, const std::vector<double>& w,
         const std::vector<double>& lambda, std::vector<double>& f, std::vector<double>& g) {
  const std::size_t n = s.size();
  const auto m = static_cast<Eigen::Index>(n - 2);
  std::vector<double> h(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) h[i] = s[i + 1] - s[i];
  // Q is n x (n-2): column j (interior knot j+1) has 1/h_j, -1/h_j - 1/h_{j+1}, 1/h_{j+1} at rows j, j+1, j+2.
  auto q = [&](std::size_t row, std::size_t column) -> double {
    if (row == column) return 1.0 / h[column];
    if (row == column + 1) return -1.0 / h[column] - 1.0 / h[column + 1];
    if (row == column + 2) return 1.0 / h[column + 1];
    return 0.0;
  };
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < m; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    for (Eigen::Index k = std::max<Eigen::Index>(0, j - 2); k <= std::min<Eigen::Index>(m - 1, j + 2); ++k) {
      const auto uk = static_cast<std::size_t>(k);
      double value = 0.0;
      if (k == j) value += (h[uj] + h[uj + 1]) / 3.0;
      if (k == j + 1) value += h[uj + 1] / 6.0;
      if (k + 1 == j) value += h[uk + 1] / 6.0;
      for (std::size_t row = std::max(uj, uk); row <= std::min(uj, uk) + 2; ++row)
        if (lambda[row] > 0.0) value += lambda[row] * q(row, uj) * q(row, uk) / w[row];
      if (value != 0.0) entries.emplace_back(j, k, value);
    }
  }
  Eigen::SparseMatrix<double> system(m, m);
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd rhs(m);
  for (Eigen::Index j = 0; j < m; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    rhs(j) = q(uj, uj) * x[uj] + q(uj + 1, uj) * x[uj + 1] + q(uj + 2, uj) * x[uj + 2];
  }
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  const Eigen::VectorXd gamma = solver.solve(rhs);
  g.assign(n, 0.0);
  for (Eigen::Index j = 0; j < m; ++j) g[static_cast<std::size_t>(j) + 1] = gamma(j);
  f = x;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(lambda[i] > 0.0)) continue;
    double qg = 0.0;
    for (std::size_t column = (i >= 2 ? i - 2 : 0); column <= std::min(i, n - 3); ++column)
      qg += q(i, column) * gamma(static_cast<Eigen::Index>(column));
    f[i] = x[i] - lambda[i] * qg / w[i];
  }
}

// Summed-chord arc length s and trapezoid weights w of the points.
void arc_length(const std::vector<double>& y, const std::vector<double>& z, std::vector<double>& s,
                std::vector<double>& w) {
  const std::size_t n = y.size();
  s.assign(n, 0.0);
  for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
  w.resize(n);
  for (std::size_t i = 0; i < n; ++i) w[i] = 0.5 * (s[std::min(i + 1, n - 1)] - s[i == 0 ? 0 : i - 1]);
}

double lambda_of(double smoothing_length_m) {
  return smoothing_length_m > 0.0 ? std::pow(smoothing_length_m / (2.0 * std::numbers::pi), 4) : 0.0;
}

}  // namespace

SmoothingSplineCurve::SmoothingSplineCurve(const std::vector<double>& y, const std::vector<double>& z,
                                           double smoothing_length_m)
    : SmoothingSplineCurve(y, z, std::vector<double>(y.size(), smoothing_length_m)) {}

SmoothingSplineCurve::SmoothingSplineCurve(const std::vector<double>& y, const std::vector<double>& z,
                                           const std::vector<double>& smoothing_lengths_m) {
  std::vector<double> w, lambda(y.size());
  arc_length(y, z, s_, w);
  for (std::size_t i = 0; i < y.size(); ++i) lambda[i] = lambda_of(smoothing_lengths_m[i]);
  fit(s_, y, w, lambda, fy_, gy_);
  fit(s_, z, w, lambda, fz_, gz_);
}

std::vector<double> smoothing_lengths(const std::vector<double>& y, const std::vector<double>& z,
                                      const SmoothingChoice& choice) {
  const std::size_t n = y.size();
  std::vector<double> length(n, choice.length_m);
  if (!(choice.jump_length_m < choice.length_m)) return length;
  // Curvature of the pilot fit (the long length) at the points.
  const SmoothingSplineCurve pilot(y, z, choice.length_m);
  std::vector<double> s, w, kappa(n);
  arc_length(y, z, s, w);
  for (std::size_t i = 0; i < n; ++i) {
    const CurvePoint p = pilot.at(s[i]);
    kappa[i] = (p.dy * p.d2z - p.dz * p.d2y) / std::pow(p.dy * p.dy + p.dz * p.dz, 1.5);
  }
  // Near a jump or kink of the curvature (its second difference over +-reach above the threshold; a curvature
  // that changes linearly, as along a worn tread, passes) the short length; away from it L grows by at most 1 m/m.
  const double reach = kJumpReach * choice.length_m;
  for (std::size_t i = 0, ahead = 0, behind = 0; i < n; ++i) {
    while (ahead + 1 < n && s[ahead] < s[i] + reach) ++ahead;
    while (s[behind] < s[i] - reach) ++behind;
    if (std::abs(kappa[ahead] - 2.0 * kappa[i] + kappa[behind]) > kCurvatureJump_per_m)
      length[i] = choice.jump_length_m;
  }
  for (std::size_t i = 1; i < n; ++i) length[i] = std::min(length[i], length[i - 1] + (s[i] - s[i - 1]));
  for (std::size_t i = n - 1; i-- > 0;) length[i] = std::min(length[i], length[i + 1] + (s[i + 1] - s[i]));
  return length;
}

double curvature_noise_per_m(double noise_sigma_m, double point_spacing_m, double smoothing_length_m) {
  // Var f'' = sigma^2 h / (2 pi) int w^4 / (1 + lambda w^4)^2 dw = sigma^2 h lambda^(-5/4) sqrt(2) / 16
  constexpr double kFactor = 0.29730177875068026;  // sqrt(sqrt(2) / 16)
  return kFactor * noise_sigma_m * std::sqrt(point_spacing_m) * std::pow(lambda_of(smoothing_length_m), -0.625);
}

double length_for_curvature_noise_m(double noise_sigma_m, double point_spacing_m, double curvature_noise_per_m) {
  constexpr double kFactor = 0.29730177875068026;
  return 2.0 * std::numbers::pi *
         std::pow(kFactor * noise_sigma_m * std::sqrt(point_spacing_m) / curvature_noise_per_m, 0.4);
}

SmoothingChoice choose_smoothing(const std::vector<double>& y, const std::vector<double>& z) {
  SmoothingChoice choice{kDefaultSmoothingLength_m, kDefaultSmoothingLength_m, estimate_point_noise_m(y, z)};
  if (!(choice.noise_sigma_m > kNoiseThreshold_m)) return choice;
  double length = 0.0;
  for (std::size_t i = 1; i < y.size(); ++i) length += std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
  const double spacing = length / static_cast<double>(y.size() - 1);
  auto length_for = [&](double curvature_noise) {
    return std::clamp(length_for_curvature_noise_m(choice.noise_sigma_m, spacing, curvature_noise),
                      kDefaultSmoothingLength_m, kMaxAutoSmoothingLength_m);
  };
  choice.length_m = length_for(kCurvatureNoise_per_m);
  choice.jump_length_m = length_for(kJumpCurvatureNoise_per_m);
  return choice;
}

CurvePoint SmoothingSplineCurve::at(double t) const {
  const auto upper = std::upper_bound(s_.begin(), s_.end(), t);
  const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(upper - s_.begin()), 1, s_.size() - 1) - 1;
  const double h = s_[i + 1] - s_[i];
  const double a = (s_[i + 1] - t) / h, b = 1.0 - a;
  auto value = [&](const std::vector<double>& f, const std::vector<double>& g) {
    return a * f[i] + b * f[i + 1] + ((a * a * a - a) * g[i] + (b * b * b - b) * g[i + 1]) * h * h / 6.0;
  };
  auto slope = [&](const std::vector<double>& f, const std::vector<double>& g) {
    return (f[i + 1] - f[i]) / h - (3.0 * a * a - 1.0) * h * g[i] / 6.0 + (3.0 * b * b - 1.0) * h * g[i + 1] / 6.0;
  };
  auto second = [&](const std::vector<double>& g) { return a * g[i] + b * g[i + 1]; };
  return {value(fy_, gy_), value(fz_, gz_), slope(fy_, gy_), slope(fz_, gz_), second(gy_), second(gz_)};
}

}  // namespace ctab::gen
