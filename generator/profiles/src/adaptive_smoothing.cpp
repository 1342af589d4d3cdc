// SPDX-License-Identifier: Apache-2.0
#include "ctab/profiles/adaptive_smoothing.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "ctab/profiles/arc_length.hpp"
#include "ctab/profiles/quadratic_segmentation.hpp"

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

// Iteratively reweighted penalised least squares of both coordinates: Huber's weights rho_j on the windows' penalty,
// 0 throughout on the `freed` windows. Penalty::Coordinates penalises the windows' third derivatives f_j'''.
// Penalty::Circle penalises their departure from a circle's, f_j''' + kappa_j^2 T_j (a circle at unit speed has
// f''' = -kappa^2 T), with kappa_j and T_j from the last pass (the first from `start`), so that an arc of any radius
// passes untouched while a change of its curvature is penalised as before.
enum class Penalty { Coordinates, Circle };

struct ReweightedFit {
  Eigen::VectorXd fy, fz;
  std::vector<double> rho;
};

// The unit tangent of window j's middle chord and the window's curvature, the mean of the two Menger curvatures
// (4 area / product of sides) of its point triples [1/m].
struct WindowShape {
  double tangent_y = 0.0, tangent_z = 0.0, curvature = 0.0;
};

WindowShape window_shape(std::size_t j, const ReweightedFit& fit) {
  auto menger = [&](std::size_t first) {
    const auto i = static_cast<Eigen::Index>(first);
    const double uy = fit.fy(i + 1) - fit.fy(i), uz = fit.fz(i + 1) - fit.fz(i);
    const double vy = fit.fy(i + 2) - fit.fy(i + 1), vz = fit.fz(i + 2) - fit.fz(i + 1);
    const double wy = fit.fy(i + 2) - fit.fy(i), wz = fit.fz(i + 2) - fit.fz(i);
    return 2.0 * (uy * vz - uz * vy) / (std::hypot(uy, uz) * std::hypot(vy, vz) * std::hypot(wy, wz));
  };
  const auto middle = static_cast<Eigen::Index>(j + 1);
  const double ey = fit.fy(middle + 1) - fit.fy(middle), ez = fit.fz(middle + 1) - fit.fz(middle);
  const double chord = std::hypot(ey, ez);
  return {ey / chord, ez / chord, 0.5 * (menger(j) + menger(j + 1))};
}

ReweightedFit reweighted_fit(const std::vector<double>& y, const std::vector<double>& z, const std::vector<double>& w,
                             const std::vector<Window>& windows, double lambda, double tau,
                             const std::vector<bool>& freed, Penalty penalty, const ReweightedFit* start = nullptr) {
  const std::size_t n = y.size();
  ReweightedFit fit;
  if (start) fit = *start;
  fit.rho.assign(windows.size(), 1.0);
  for (std::size_t j = 0; j < windows.size(); ++j)
    if (freed[j]) fit.rho[j] = 0.0;
  Eigen::VectorXd wy(static_cast<Eigen::Index>(n)), wz(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    wy(static_cast<Eigen::Index>(i)) = w[i] * y[i];
    wz(static_cast<Eigen::Index>(i)) = w[i] * z[i];
  }
  Eigen::VectorXd right_y = wy, right_z = wz;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(n + windows.size() * (kOrder + 1) * (kOrder + 1));
  Eigen::SparseMatrix<double> system(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  for (int iteration = 0;; ++iteration) {
    // (W + lambda D^T diag(rho c) D) f = W x + lambda D^T diag(rho c) b for both coordinates, b = 0 or, for
    // Penalty::Circle, each window's -kappa^2 T
    entries.clear();
    for (std::size_t i = 0; i < n; ++i)
      entries.emplace_back(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i), w[i]);
    if (penalty == Penalty::Circle) {
      right_y = wy;
      right_z = wz;
    }
    for (std::size_t j = 0; j < windows.size(); ++j) {
      const double factor = lambda * fit.rho[j] * windows[j].length_third;
      for (std::size_t a = 0; a <= kOrder; ++a)
        for (std::size_t b = 0; b <= kOrder; ++b)
          entries.emplace_back(static_cast<Eigen::Index>(j + a), static_cast<Eigen::Index>(j + b),
                               factor * windows[j].coefficient[a] * windows[j].coefficient[b]);
      if (penalty != Penalty::Circle || factor == 0.0) continue;
      const WindowShape shape = window_shape(j, fit);
      const double offset = -factor * shape.curvature * shape.curvature;
      for (std::size_t a = 0; a <= kOrder; ++a) {
        right_y(static_cast<Eigen::Index>(j + a)) += offset * windows[j].coefficient[a] * shape.tangent_y;
        right_z(static_cast<Eigen::Index>(j + a)) += offset * windows[j].coefficient[a] * shape.tangent_z;
      }
    }
    system.setFromTriplets(entries.begin(), entries.end());
    if (iteration == 0) solver.analyzePattern(system);
    solver.factorize(system);
    fit.fy = solver.solve(right_y);
    fit.fz = solver.solve(right_z);
    if (iteration == kAdaptiveIterations) break;
    // Huber weights from dkappa/ds = N . f''' (the tangent from the window's middle chord)
    for (std::size_t j = 0; j < windows.size(); ++j) {
      if (freed[j]) continue;
      double ty = 0.0, tz = 0.0;
      for (std::size_t k = 0; k <= kOrder; ++k) {
        ty += windows[j].coefficient[k] * fit.fy(static_cast<Eigen::Index>(j + k));
        tz += windows[j].coefficient[k] * fit.fz(static_cast<Eigen::Index>(j + k));
      }
      const auto middle = static_cast<Eigen::Index>(j + 1);
      const double ey = fit.fy(middle + 1) - fit.fy(middle), ez = fit.fz(middle + 1) - fit.fz(middle);
      const double slope = std::abs(ey * tz - ez * ty) / std::hypot(ey, ez);
      fit.rho[j] = slope > tau ? tau / slope : 1.0;
    }
  }
  return fit;
}

// The arcs prior's junctions: along an arc the curvature, f's plus e'' to first order (e the points' offsets from the
// smooth fit f along its normal), is constant, so e + K (K'' = f's curvature) is quadratic in s; the optimal partition
// into quadratic pieces at kArcJunctionPenalty noise variances per piece places the junctions. Returns the windows that
// straddle one (a window spans points j..j+3; a junction lies between a piece's first point and the one before).
std::vector<bool> arc_junction_windows(const std::vector<double>& y, const std::vector<double>& z,
                                       const std::vector<double>& s, const ReweightedFit& smooth, double noise_sigma_m,
                                       std::size_t window_count) {
  const std::size_t n = y.size();
  std::vector<double> angle(n), curvature(n), g(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto before = static_cast<Eigen::Index>(i == 0 ? 0 : i - 1);
    const auto after = static_cast<Eigen::Index>(std::min(i + 1, n - 1));
    angle[i] = std::atan2(smooth.fz(after) - smooth.fz(before), smooth.fy(after) - smooth.fy(before));
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = i == 0 ? 0 : i - 1, after = std::min(i + 1, n - 1);
    curvature[i] = (angle[after] - angle[before]) / (s[after] - s[before]);
  }
  double slope = 0.0, offset = 0.0;  // K' and K
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) {
      const double ds = s[i] - s[i - 1];
      const double next_slope = slope + 0.5 * (curvature[i - 1] + curvature[i]) * ds;
      offset += 0.5 * (slope + next_slope) * ds;
      slope = next_slope;
    }
    const auto k = static_cast<Eigen::Index>(i);
    g[i] = -(y[i] - smooth.fy(k)) * std::sin(angle[i]) + (z[i] - smooth.fz(k)) * std::cos(angle[i]) + offset;
  }
  // The partition places each junction to within a few points (its pieces need not join); the fit across the two
  // pieces around it with value and slope continuous places it to about 0.1 mm (60E1 with 5 um noise).
  const std::vector<std::size_t> pieces =
      quadratic_segmentation(s, g, kArcJunctionPenalty * noise_sigma_m * noise_sigma_m, kArcMinPoints);
  std::vector<bool> freed(window_count, false);
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const std::size_t begin = k == 0 ? 0 : pieces[k - 1], end = k + 1 == pieces.size() ? n : pieces[k + 1];
    const std::size_t first = refine_curvature_jump(s, g, begin, end, kArcMinPoints / 2);
    freed[first - 2] = true;  // points first-2 .. first+1: the jump between first-1 and first in the middle
  }
  return freed;
}

}  // namespace

AdaptivelySmoothedPoints smooth_adaptively(const std::vector<double>& y, const std::vector<double>& z, double length_m,
                                           double noise_sigma_m, CurvaturePrior prior) {
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
  std::vector<bool> freed(windows.size(), false);
  ReweightedFit fit = reweighted_fit(y, z, w, windows, lambda, tau, freed, Penalty::Coordinates);
  AdaptivelySmoothedPoints out;
  out.length_m = length_m;
  if (prior == CurvaturePrior::Arcs) {
    // The junctions from the smooth fit, then the arcs between them with the circle's penalty, which leaves an arc
    // untouched, and a longer length (tau scales as the smoothed noise's dkappa/ds, L^-3.5). Both in arc length along
    // the smooth fit: the points' own summed chords grow with their noise along the profile (by delta^2 / 2h a step:
    // 4 % at 0.025 mm spacing with 5 um noise where the profile is steep), which bends arcs in s; at that spacing 60E1
    // gained a junction inside each R13 arc, and its contacts read area and max pressure 25 and 41 % off (1.4 and
    // 2.1 % along the fit).
    std::vector<double> smooth_y(fit.fy.data(), fit.fy.data() + n), smooth_z(fit.fz.data(), fit.fz.data() + n);
    std::vector<double> smooth_s, smooth_weights;
    summed_chord_arc_length(smooth_y, smooth_z, smooth_s, smooth_weights);
    freed = arc_junction_windows(y, z, smooth_s, fit, noise_sigma_m, windows.size());
    out.length_m = kArcLengthFactor * length_m;
    fit = reweighted_fit(y, z, smooth_weights, windows_of(smooth_s), lambda_of(out.length_m),
                         tau * std::pow(kArcLengthFactor, -3.5), freed, Penalty::Circle, &fit);
    for (std::size_t j = 0; j < windows.size(); ++j)
      if (freed[j])
        out.junction_y_m.push_back(
            0.5 * (fit.fy(static_cast<Eigen::Index>(j + 1)) + fit.fy(static_cast<Eigen::Index>(j + 2))));
  }
  out.y_m.assign(fit.fy.data(), fit.fy.data() + fit.fy.size());
  out.z_m.assign(fit.fz.data(), fit.fz.data() + fit.fz.size());
  double shortest_rho = 1.0;
  for (std::size_t j = 0; j < windows.size(); ++j)
    if (!freed[j]) shortest_rho = std::min(shortest_rho, fit.rho[j]);
  out.shortest_length_m = out.length_m * std::pow(shortest_rho, 1.0 / 6.0);
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
