// SPDX-License-Identifier: Apache-2.0
#include "ctab/profiles/quadratic_segmentation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace ctab::gen {

namespace {

// Least squares of g ~ c0 + c1 u + c2 u^2, one point at a time: R (upper triangular) and Q^T g of the points so far,
// and the residual sum of squares (Givens rotations; Golub & Van Loan 5.1.8).
class IncrementalQuadraticFit {
 public:
  static constexpr std::size_t N = 3;
  void add(double u, double g) {
    std::array<double, N> row{1.0, u, u * u};
    double value = g;
    for (std::size_t k = 0; k < N; ++k) {
      if (row[k] == 0.0) continue;
      const double radius = std::hypot(r_[k][k], row[k]);
      const double c = r_[k][k] / radius, s = row[k] / radius;
      for (std::size_t j = k; j < N; ++j) {
        const double upper = r_[k][j];
        r_[k][j] = c * upper + s * row[j];
        row[j] = c * row[j] - s * upper;
      }
      const double upper = rhs_[k];
      rhs_[k] = c * upper + s * value;
      value = c * value - s * upper;
    }
    residual_ += value * value;
  }
  [[nodiscard]] double residual() const { return residual_; }

 private:
  std::array<std::array<double, N>, N> r_{};
  std::array<double, N> rhs_{};
  double residual_ = 0.0;
};

}  // namespace

std::vector<std::size_t> quadratic_segmentation(const std::vector<double>& t, const std::vector<double>& g,
                                                double penalty, std::size_t min_points) {
  const std::size_t n = t.size();
  if (g.size() != n || min_points < 3 || !(penalty >= 0.0))
    throw std::invalid_argument("quadratic_segmentation: t and g of one size, min_points >= 3, penalty >= 0");
  if (n < 2 * min_points) return {};
  // best[b]: the least cost of points [0, b); start[b]: where its last piece starts
  std::vector<double> best(n + 1, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> start(n + 1, 0);
  best[0] = 0.0;
  const double scale = (t.back() - t.front()) / static_cast<double>(n - 1);  // u in point spacings: R well scaled
  // The pieces that may still end a best partition, each fitted from its first point to the last seen, with its
  // residuals of the last min_points + 1 ends. Pruning (PELT; Killick, Fearnhead & Eckley 2012): a residual sum only
  // grows when a piece is split no more, so a start a whose best[a] + residual(a, b) exceeds best[b] can no longer
  // win once a piece from b may follow, i.e. for ends from b + min_points on; it is dropped then, at b + min_points.
  // The partition is the one of the search over all pieces, ties included (starts kept in order, drops strict).
  struct Candidate {
    std::size_t first = 0;
    IncrementalQuadraticFit fit;
    std::vector<double> residuals;  // residual(first, end) at end % residuals.size()
  };
  const std::size_t history = min_points + 1;
  std::vector<Candidate> live;
  for (std::size_t end = 1; end <= n; ++end) {
    const std::size_t point = end - 1;
    if (std::isfinite(best[point]) && point + min_points <= n)
      live.push_back({point, IncrementalQuadraticFit{}, std::vector<double>(history, 0.0)});
    for (Candidate& c : live) {
      const double u = (t[point] - t[c.first]) / scale;
      c.fit.add(u, g[point]);
      c.residuals[end % history] = c.fit.residual();
    }
    if (end >= n || n - end >= min_points)
      for (const Candidate& c : live) {
        if (end - c.first < min_points) break;  // starts ascend: the later ones are shorter still
        const double cost = best[c.first] + c.fit.residual() + penalty;
        if (cost < best[end]) {
          best[end] = cost;
          start[end] = c.first;
        }
      }
    if (end < min_points) continue;
    const std::size_t then = end - min_points;
    if (!std::isfinite(best[then])) continue;
    std::erase_if(live, [&](const Candidate& c) {
      return c.first < then && best[c.first] + c.residuals[then % history] > best[then];
    });
  }
  std::vector<std::size_t> boundaries;
  for (std::size_t end = n; start[end] > 0; end = start[end]) boundaries.push_back(start[end]);
  return {boundaries.rbegin(), boundaries.rend()};
}

std::size_t refine_curvature_jump(const std::vector<double>& t, const std::vector<double>& g, std::size_t begin,
                                  std::size_t end, std::size_t margin) {
  if (g.size() != t.size() || end > t.size() || begin + 2 * margin + 1 > end || margin < 2)
    throw std::invalid_argument("refine_curvature_jump: a range [begin, end) of t of more than 2 margin points");
  const std::size_t count = end - begin;
  const double origin = 0.5 * (t[begin] + t[end - 1]);
  const double scale = (t[end - 1] - t[begin]) / 2.0;  // u in [-1, 1]
  std::vector<double> u(count);
  for (std::size_t i = 0; i < count; ++i) u[i] = (t[begin + i] - origin) / scale;
  // An orthonormal basis Q of {1, u, u^2} over the range (modified Gram-Schmidt, twice) and g's residual r off it.
  std::array<std::vector<double>, 3> q;
  for (std::size_t k = 0; k < 3; ++k) {
    q[k].resize(count);
    for (std::size_t i = 0; i < count; ++i) q[k][i] = std::pow(u[i], static_cast<double>(k));
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t l = 0; l < k; ++l) {
        double projection = 0.0;
        for (std::size_t i = 0; i < count; ++i) projection += q[l][i] * q[k][i];
        for (std::size_t i = 0; i < count; ++i) q[k][i] -= projection * q[l][i];
      }
    double norm = 0.0;
    for (const double v : q[k]) norm += v * v;
    for (double& v : q[k]) v /= std::sqrt(norm);
  }
  std::vector<double> r(g.begin() + static_cast<std::ptrdiff_t>(begin), g.begin() + static_cast<std::ptrdiff_t>(end));
  for (int pass = 0; pass < 2; ++pass)
    for (std::size_t k = 0; k < 3; ++k) {
      double projection = 0.0;
      for (std::size_t i = 0; i < count; ++i) projection += q[k][i] * r[i];
      for (std::size_t i = 0; i < count; ++i) r[i] -= projection * q[k][i];
    }
  // The jump's column x = max(u - u_j, 0)^2 lowers the residual sum by (x.r)^2 / (|x|^2 - |Q^T x|^2) (r is
  // orthogonal to Q): the best jump lowers it most. x vanishes before the jump, so the sums run over the points after.
  double most = -1.0;
  std::size_t best = begin + margin;
  for (std::size_t first = begin + margin; first + margin <= end; ++first) {
    const double jump_u = (0.5 * (t[first - 1] + t[first]) - origin) / scale;
    double xr = 0.0, xx = 0.0;
    std::array<double, 3> qx{};
    for (std::size_t i = first - begin; i < count; ++i) {
      const double beyond = u[i] - jump_u, x = beyond * beyond;
      xr += x * r[i];
      xx += x * x;
      for (std::size_t k = 0; k < 3; ++k) qx[k] += q[k][i] * x;
    }
    const double independent = xx - (qx[0] * qx[0] + qx[1] * qx[1] + qx[2] * qx[2]);
    const double lowered = independent > 0.0 ? xr * xr / independent : 0.0;
    if (lowered > most) {
      most = lowered;
      best = first;
    }
  }
  return best;
}

}  // namespace ctab::gen
