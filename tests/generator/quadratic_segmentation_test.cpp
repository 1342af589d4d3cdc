// SPDX-License-Identifier: Apache-2.0
// Optimal partitioning into quadratic pieces and the C1 refinement of a curvature jump (quadratic_segmentation.hpp),
// the arcs prior's junction finder: against data whose pieces are known.
#include "ctab/profiles/quadratic_segmentation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace ctab::gen {
namespace {

constexpr double kStep = 0.1e-3;  // t spacing [m]

// g = curvature_k t^2 / 2 on piece k, value and slope continuous at the joins, plus Gaussian noise.
struct Signal {
  std::vector<double> t, g;
};

Signal joined_parabolas(const std::vector<std::size_t>& joins, const std::vector<double>& curvatures,
                        std::size_t points, double sigma, unsigned seed) {
  Signal out;
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  double value = 0.0, slope = 0.0;
  std::size_t piece = 0;
  for (std::size_t i = 0; i < points; ++i) {
    if (piece < joins.size() && i == joins[piece]) ++piece;
    if (i > 0) {  // exact integration of a piecewise constant second derivative
      const double c = curvatures[piece];
      value += slope * kStep + 0.5 * c * kStep * kStep;
      slope += c * kStep;
    }
    out.t.push_back(static_cast<double>(i) * kStep);
    out.g.push_back(value + (sigma > 0.0 ? noise(random) : 0.0));
  }
  return out;
}

TEST(QuadraticSegmentation, OneParabolaIsOnePiece) {
  for (const unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    const Signal s = joined_parabolas({}, {12.5}, 600, 5e-6, seed);
    EXPECT_TRUE(quadratic_segmentation(s.t, s.g, 30.0 * 25e-12, 10).empty()) << seed;
  }
}

TEST(QuadraticSegmentation, FindsJoinsNearWhereTheCurvatureJumps) {
  // 60E1-like: 3.33, 12.5 and 76.9 1/m (R300, R80, R13), 5 um noise
  const std::vector<std::size_t> joins{200, 360};
  for (const unsigned seed : {1u, 2u, 3u}) {
    const Signal s = joined_parabolas(joins, {3.33, 12.5, 76.9}, 500, 5e-6, seed);
    const std::vector<std::size_t> found = quadratic_segmentation(s.t, s.g, 30.0 * 25e-12, 10);
    ASSERT_EQ(found.size(), joins.size()) << seed;
    // the pieces need not join, so the partition alone places a join only to several points
    for (std::size_t k = 0; k < joins.size(); ++k) {
      EXPECT_NEAR(static_cast<double>(found[k]), static_cast<double>(joins[k]), 15.0) << seed << " #" << k;
      // the refinement across the two pieces, value and slope continuous: to a point or two
      const std::size_t begin = k == 0 ? 0 : found[k - 1], end = k + 1 == found.size() ? s.t.size() : found[k + 1];
      EXPECT_NEAR(static_cast<double>(refine_curvature_jump(s.t, s.g, begin, end, 5)), static_cast<double>(joins[k]),
                  2.0)
          << seed << " #" << k;
    }
  }
}

// The residual sum of a quadratic fitted to g over [a, b) by the normal equations, u centred and scaled.
double quadratic_residual(const Signal& s, std::size_t a, std::size_t b) {
  const double mid = 0.5 * (s.t[a] + s.t[b - 1]), half = 0.5 * (s.t[b - 1] - s.t[a]);
  double m[3][4] = {};
  for (std::size_t i = a; i < b; ++i) {
    const double u = (s.t[i] - mid) / half, row[3] = {1.0, u, u * u};
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[r][c] += row[r] * row[c];
      m[r][3] += row[r] * s.g[i];
    }
  }
  for (int k = 0; k < 3; ++k)  // Gauss-Jordan, SPD: no pivoting
    for (int r = 0; r < 3; ++r) {
      if (r == k) continue;
      const double f = m[r][k] / m[k][k];
      for (int c = k; c < 4; ++c) m[r][c] -= f * m[k][c];
    }
  double rss = 0.0;
  for (std::size_t i = a; i < b; ++i) {
    const double u = (s.t[i] - mid) / half;
    const double e = s.g[i] - (m[0][3] / m[0][0] + u * m[1][3] / m[1][1] + u * u * m[2][3] / m[2][2]);
    rss += e * e;
  }
  return rss;
}

// The pruned search (PELT) gives the partition of the search over every piece (here by brute force).
TEST(QuadraticSegmentation, PrunedSearchMatchesTheFullSearch) {
  constexpr std::size_t kMin = 8;
  for (const unsigned seed : {1u, 2u, 3u, 4u}) {
    const Signal s = joined_parabolas({40, 95, 120, 170}, {3.0, 40.0, -20.0, 5.0, 60.0}, 220, 5e-6, seed);
    const double penalty = 30.0 * 25e-12;
    const std::size_t n = s.t.size();
    std::vector<double> best{0.0};  // the least cost of points [0, b)
    best.resize(n + 1, 1e300);
    std::vector<std::size_t> start(n + 1, 0);
    for (std::size_t a = 0; a + kMin <= n; ++a) {
      if (best[a] >= 1e300) continue;
      for (std::size_t b = a + kMin; b <= n; ++b) {
        if (b < n && n - b < kMin) continue;
        const double cost = best[a] + quadratic_residual(s, a, b) + penalty;
        if (cost < best[b]) best[b] = cost, start[b] = a;
      }
    }
    std::vector<std::size_t> expected;
    for (std::size_t end = n; start[end] > 0; end = start[end]) expected.push_back(start[end]);
    std::reverse(expected.begin(), expected.end());
    EXPECT_EQ(quadratic_segmentation(s.t, s.g, penalty, kMin), expected) << seed;
    EXPECT_GE(expected.size(), 3u) << seed;  // the data do have pieces
  }
}

TEST(QuadraticSegmentation, RefinementIsExactWithoutNoise) {
  const Signal s = joined_parabolas({137}, {3.33, 12.5}, 300, 0.0, 0u);
  EXPECT_EQ(refine_curvature_jump(s.t, s.g, 0, s.t.size(), 5), 137u);
}

TEST(QuadraticSegmentation, PiecesRespectTheirFewestPoints) {
  // a jump 6 points from the end cannot make a piece of 10
  const Signal s = joined_parabolas({294}, {3.33, 200.0}, 300, 0.0, 0u);
  for (const std::size_t first : quadratic_segmentation(s.t, s.g, 1e-18, 10)) {
    EXPECT_GE(first, 10u);
    EXPECT_LE(first, 290u);
  }
}

TEST(QuadraticSegmentation, RejectsBadArguments) {
  const std::vector<double> t{0.0, 1.0, 2.0}, g{0.0, 1.0};
  EXPECT_THROW((void)quadratic_segmentation(t, g, 1.0, 3), std::invalid_argument);
  EXPECT_THROW((void)quadratic_segmentation(t, t, -1.0, 3), std::invalid_argument);
  EXPECT_THROW((void)quadratic_segmentation(t, t, 1.0, 2), std::invalid_argument);
  EXPECT_THROW((void)refine_curvature_jump(t, t, 0, 3, 2), std::invalid_argument);
}

}  // namespace
}  // namespace ctab::gen
