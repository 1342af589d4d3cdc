#include "ctab/profiles/adaptive_smoothing.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ctab/profiles/arc_length.hpp"

namespace ctab::gen {

namespace {

constexpr std::size_t kOrder = 3;  // the penalised derivative
// (1/2pi) int u^4 / (1 + u^6)^2 du = (1/2pi) int u^6 / (1 + u^6)^2 du = (pi/9) / (2 pi) = 1/18
double noise_scale(double noise_sigma_m, double point_spacing_m) {
  return noise_sigma_m * std::sqrt(point_spacing_m / 18.0);
}

double lambda_of(double length_m) { return std::pow(length_m / (2.0 * std::numbers::pi), 6); }

// Third derivative of a window: 3! times the divided difference over its four points.
struct Window {
  std::array<double, kOrder + 1> coefficient{};
  double length_third = 0.0;  // c_j: the window's length / 3
};

std::vector<Window> windows_of(const std::vector<double>& s) {
  std::vector<Window> windows(s.size() - kOrder);
  for (std::size_t j = 0; j < windows.size(); ++j) {
    for (std::size_t k = 0; k <= kOrder; ++k) {
      double product = 1.0;
      for (std::size_t m = 0; m <= kOrder; ++m)
        if (m != k) product *= s[j + k] - s[j + m];
      windows[j].coefficient[k] = 6.0 / product;
    }
    windows[j].length_third = (s[j + kOrder] - s[j]) / 3.0;
  }
  return windows;
}

}  // namespace

AdaptivelySmoothedPoints smooth_adaptively(const std::vector<double>& y, const std::vector<double>& z, double length_m,
                                           double noise_sigma_m) {
  const std::size_t n = y.size();
  if (n < 8 || z.size() != n || !(length_m > 0.0) || !(noise_sigma_m > 0.0))
    throw std::invalid_argument("smooth_adaptively: needs 8 points, a length and a noise above 0");
  std::vector<double> s, w;
  summed_chord_arc_length(y, z, s, w);
  const std::vector<Window> windows = windows_of(s);
  const double lambda = lambda_of(length_m);
  const double tau =
      kAdaptiveHuberThreshold *
      adaptive_curvature_slope_noise_per_m2(noise_sigma_m, s.back() / static_cast<double>(n - 1), length_m);
  std::vector<double> rho(windows.size(), 1.0);
  Eigen::VectorXd wy(static_cast<Eigen::Index>(n)), wz(static_cast<Eigen::Index>(n)), fy, fz;
  for (std::size_t i = 0; i < n; ++i) {
    wy(static_cast<Eigen::Index>(i)) = w[i] * y[i];
    wz(static_cast<Eigen::Index>(i)) = w[i] * z[i];
  }
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(n + windows.size() * (kOrder + 1) * (kOrder + 1));
  Eigen::SparseMatrix<double> system(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  for (int iteration = 0;; ++iteration) {
    // (W + lambda D^T diag(rho c) D) f = W x for both coordinates
    entries.clear();
    for (std::size_t i = 0; i < n; ++i)
      entries.emplace_back(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i), w[i]);
    for (std::size_t j = 0; j < windows.size(); ++j) {
      const double factor = lambda * rho[j] * windows[j].length_third;
      for (std::size_t a = 0; a <= kOrder; ++a)
        for (std::size_t b = 0; b <= kOrder; ++b)
          entries.emplace_back(static_cast<Eigen::Index>(j + a), static_cast<Eigen::Index>(j + b),
                               factor * windows[j].coefficient[a] * windows[j].coefficient[b]);
    }
    system.setFromTriplets(entries.begin(), entries.end());
    if (iteration == 0) solver.analyzePattern(system);
    solver.factorize(system);
    fy = solver.solve(wy);
    fz = solver.solve(wz);
    if (iteration == kAdaptiveIterations) break;
    // Huber weights from dkappa/ds = N . f''' (the tangent from the window's middle chord)
    for (std::size_t j = 0; j < windows.size(); ++j) {
      double ty = 0.0, tz = 0.0;
      for (std::size_t k = 0; k <= kOrder; ++k) {
        ty += windows[j].coefficient[k] * fy(static_cast<Eigen::Index>(j + k));
        tz += windows[j].coefficient[k] * fz(static_cast<Eigen::Index>(j + k));
      }
      const auto middle = static_cast<Eigen::Index>(j + 1);
      const double ey = fy(middle + 1) - fy(middle), ez = fz(middle + 1) - fz(middle);
      const double slope = std::abs(ey * tz - ez * ty) / std::hypot(ey, ez);
      rho[j] = slope > tau ? tau / slope : 1.0;
    }
  }
  AdaptivelySmoothedPoints out;
  out.y_m.assign(fy.data(), fy.data() + fy.size());
  out.z_m.assign(fz.data(), fz.data() + fz.size());
  out.shortest_length_m = length_m * std::pow(*std::min_element(rho.begin(), rho.end()), 1.0 / 6.0);
  return out;
}

double adaptive_curvature_noise_per_m(double noise_sigma_m, double point_spacing_m, double smoothing_length_m) {
  return noise_scale(noise_sigma_m, point_spacing_m) * std::pow(lambda_of(smoothing_length_m), -5.0 / 12.0);
}

double adaptive_length_for_curvature_noise_m(double noise_sigma_m, double point_spacing_m,
                                             double curvature_noise_per_m) {
  const double lambda = std::pow(noise_scale(noise_sigma_m, point_spacing_m) / curvature_noise_per_m, 12.0 / 5.0);
  return 2.0 * std::numbers::pi * std::pow(lambda, 1.0 / 6.0);
}

double adaptive_curvature_slope_noise_per_m2(double noise_sigma_m, double point_spacing_m, double smoothing_length_m) {
  return noise_scale(noise_sigma_m, point_spacing_m) * std::pow(lambda_of(smoothing_length_m), -7.0 / 12.0);
}

}  // namespace ctab::gen
