#include "ctab/profiles/quadratic_segmentation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ctab::gen {

namespace {

// Linear least squares with N unknowns, one row at a time: R (upper triangular) and Q^T g of the rows so far, and the
// residual sum of squares (Givens rotations; Golub & Van Loan 5.1.8).
template <std::size_t N>
class IncrementalFit {
 public:
  void add(std::array<double, N> row, double g) {
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
  for (std::size_t a = 0; a + min_points <= n; ++a) {
    if (!std::isfinite(best[a])) continue;
    IncrementalFit<3> fit;
    for (std::size_t b = a; b < n; ++b) {
      const double u = (t[b] - t[a]) / scale;
      fit.add({1.0, u, u * u}, g[b]);
      const std::size_t end = b + 1;
      if (end - a < min_points || (end < n && n - end < min_points)) continue;
      const double cost = best[a] + fit.residual() + penalty;
      if (cost < best[end]) {
        best[end] = cost;
        start[end] = a;
      }
    }
  }
  std::vector<std::size_t> boundaries;
  for (std::size_t end = n; start[end] > 0; end = start[end]) boundaries.push_back(start[end]);
  return {boundaries.rbegin(), boundaries.rend()};
}

std::size_t refine_curvature_jump(const std::vector<double>& t, const std::vector<double>& g, std::size_t begin,
                                  std::size_t end, std::size_t margin) {
  if (g.size() != t.size() || end > t.size() || begin + 2 * margin + 1 > end || margin < 2)
    throw std::invalid_argument("refine_curvature_jump: a range [begin, end) of t of more than 2 margin points");
  const double origin = 0.5 * (t[begin] + t[end - 1]);
  const double scale = (t[end - 1] - t[begin]) / 2.0;  // u in [-1, 1]
  double least = std::numeric_limits<double>::infinity();
  std::size_t best = begin + margin;
  for (std::size_t first = begin + margin; first + margin <= end; ++first) {
    const double jump_u = (0.5 * (t[first - 1] + t[first]) - origin) / scale;
    IncrementalFit<4> fit;
    for (std::size_t i = begin; i < end; ++i) {
      const double u = (t[i] - origin) / scale, beyond = std::max(u - jump_u, 0.0);
      fit.add({1.0, u, u * u, beyond * beyond}, g[i]);
    }
    if (fit.residual() < least) {
      least = fit.residual();
      best = first;
    }
  }
  return best;
}

}  // namespace ctab::gen
