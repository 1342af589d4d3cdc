// SPDX-License-Identifier: Apache-2.0
#include "ctab/profiles/smoothing_spline.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ctab/profiles/adaptive_smoothing.hpp"
#include "ctab/profiles/arc_length.hpp"
#include "ctab/profiles/point_noise.hpp"

namespace ctab::gen {

namespace {

// Fits one coordinate; returns smoothed values f and knot second derivatives g (natural ends: g = 0).
void fit(const std::vector<double>& s, const std::vector<double>& x, const std::vector<double>& w, double lambda,
         std::vector<double>& f, std::vector<double>& g) {
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
        if (lambda > 0.0) value += lambda * q(row, uj) * q(row, uk) / w[row];
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
  for (std::size_t i = 0; i < n && lambda > 0.0; ++i) {
    double qg = 0.0;
    for (std::size_t column = (i >= 2 ? i - 2 : 0); column <= std::min(i, n - 3); ++column)
      qg += q(i, column) * gamma(static_cast<Eigen::Index>(column));
    f[i] = x[i] - lambda * qg / w[i];
  }
}

double lambda_of(double smoothing_length_m) {
  return smoothing_length_m > 0.0 ? std::pow(smoothing_length_m / (2.0 * std::numbers::pi), 4) : 0.0;
}

}  // namespace

SmoothingSplineCurve::SmoothingSplineCurve(const std::vector<double>& y, const std::vector<double>& z,
                                           double smoothing_length_m) {
  std::vector<double> w;
  summed_chord_arc_length(y, z, s_, w);
  fit(s_, y, w, lambda_of(smoothing_length_m), fy_, gy_);
  fit(s_, z, w, lambda_of(smoothing_length_m), fz_, gz_);
}

SmoothingChoice choose_smoothing(const std::vector<double>& y, const std::vector<double>& z) {
  SmoothingChoice choice{kDefaultSmoothingLength_m, estimate_point_noise_m(y, z), false};
  if (!(choice.noise_sigma_m > kNoiseThreshold_m)) return choice;
  double length = 0.0;
  for (std::size_t i = 1; i < y.size(); ++i) length += std::hypot(y[i] - y[i - 1], z[i] - z[i - 1]);
  const double spacing = length / static_cast<double>(y.size() - 1);
  choice.length_m =
      std::clamp(adaptive_length_for_curvature_noise_m(choice.noise_sigma_m, spacing, kCurvatureNoise_per_m),
                 kDefaultSmoothingLength_m, kMaxAutoSmoothingLength_m);
  choice.adaptive = true;
  return choice;
}

SmoothedPointCurve smooth_point_profile(const std::vector<double>& y, const std::vector<double>& z,
                                        const SmoothingChoice& choice) {
  if (!choice.adaptive)
    return {std::make_shared<SmoothingSplineCurve>(y, z, choice.length_m), choice.length_m, choice.length_m};
  const AdaptivelySmoothedPoints smoothed =
      smooth_adaptively(y, z, choice.length_m, choice.noise_sigma_m, choice.prior);
  return {std::make_shared<SmoothingSplineCurve>(smoothed.y_m, smoothed.z_m, 0.0), smoothed.length_m,
          smoothed.shortest_length_m, static_cast<int>(smoothed.junction_y_m.size())};
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
