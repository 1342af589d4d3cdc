// SPDX-License-Identifier: Apache-2.0
// The closed-form strip kernel against independent quadrature: h(t) by graded Gauss-Legendre, and the full
// influence coefficient by the paper's own route (Eq. 11: regular part by Gauss quadrature, singular part by
// Love's closed form, Eq. 12).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>

#include "ctab/contact/strip_kernel.hpp"

using ctab::gen::StripKernel;

namespace {

constexpr std::array<double, 10> kNodes = {-0.9739065285171717, -0.8650633666889845, -0.6794095682990244,
                                           -0.4333953941292472, -0.1488743389816312, 0.1488743389816312,
                                           0.4333953941292472,  0.6794095682990244,  0.8650633666889845,
                                           0.9739065285171717};
constexpr std::array<double, 10> kWeights = {0.0666713443086881, 0.1494513491505806, 0.2190863625159820,
                                             0.2692667193099963, 0.2955242247147529, 0.2955242247147529,
                                             0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                             0.0666713443086881};

double gauss(const std::function<double(double)>& f, double lo, double hi, int panels) {
  double sum = 0.0;
  const double width = (hi - lo) / panels;
  for (int p = 0; p < panels; ++p)
    for (std::size_t g = 0; g < kNodes.size(); ++g)
      sum += 0.5 * width * kWeights[g] * f(lo + width * (p + 0.5 * (1.0 + kNodes[g])));
  return sum;
}

// Geometrically graded panels towards lo (log-singular integrands at lo).
double gauss_graded(const std::function<double(double)>& f, double lo, double hi) {
  double sum = 0.0, upper = hi;
  for (int k = 0; k < 80; ++k) {
    const double lower = lo + 0.5 * (upper - lo);
    sum += gauss(f, lower, upper, 1);
    upper = lower;
  }
  return sum;
}

// h(t) = int_0^1 sqrt(1 - u^2) asinh(t/u) du with u = sin(theta).
double h_by_quadrature(double t) {
  return gauss_graded([t](double th) { return std::cos(th) * std::cos(th) * std::asinh(t / std::sin(th)); }, 0.0,
                      std::numbers::pi / 2);
}

}  // namespace

TEST(StripKernel, ValueMatchesQuadrature) {
  const StripKernel& kernel = StripKernel::instance();
  for (double t : {1e-9, 1e-6, 1e-3, 0.05, 0.3, 1.0, 2.7, 10.0, 123.0, 1e4, 1e7}) {
    const double reference = h_by_quadrature(t);
    EXPECT_NEAR(kernel.value(t), reference, 2e-11 + 1e-10 * std::abs(reference)) << "t = " << t;
    EXPECT_NEAR(kernel.value(-t), -reference, 2e-11 + 1e-10 * std::abs(reference)) << "odd in t";
  }
}

TEST(StripKernel, AsymptotesAndSlope) {
  const StripKernel& kernel = StripKernel::instance();
  const double t = 1e12;  // beyond the table: large-argument form; continuity across the table end
  EXPECT_NEAR(kernel.value(std::nextafter(StripKernel::kTableMax, 0.0)), kernel.value(StripKernel::kTableMax), 1e-9);
  EXPECT_NEAR(kernel.value(t) - std::numbers::pi / 4 * std::asinh(t),
              std::numbers::pi / 8 + std::numbers::pi / 4 * std::log(2.0), 1e-9);
  double h = 0, t_dh = 0;
  for (double x : {1e-4, 0.2, 3.0, 500.0}) {
    kernel.value_and_scaled_slope(x, h, t_dh);
    EXPECT_NEAR(t_dh, x * StripKernel::exact_slope(x), 1e-8 * std::abs(t_dh)) << "t = " << x;
  }
}

// Paper Eqs. 11-12, for a strip of half-length a, half-width b, observed at lateral distance d (E* scaled out):
// returns a [h((d+b)/a) - h((d-b)/a)] computed the paper's way.
double paper_coefficient(double a, double b, double d) {
  // Regular part: int_{-b}^{b} int_0^a (sqrt(1 - xi^2/a^2) - 1) / sqrt(xi^2 + (d - eta)^2) dxi deta, xi = a sin(th).
  auto inner = [a, d](double eta) {
    const double s = d - eta;
    return gauss(
        [a, s](double th) {
          const double xi = a * std::sin(th);
          return (std::cos(th) - 1.0) * a * std::cos(th) / std::sqrt(xi * xi + s * s);
        },
        0.0, std::numbers::pi / 2, 24);
  };
  double regular = 0.0;
  if (std::abs(d) < b) {
    regular = gauss(inner, -b, d, 24) + gauss(inner, d, b, 24);
  } else {
    regular = gauss(inner, -b, b, 24);
  }
  // Love's closed form (Eq. 12) gives twice the uniform-pressure integral.
  const double yp = d + b, ym = d - b;
  const double rp = std::sqrt(yp * yp + a * a), rm = std::sqrt(ym * ym + a * a);
  const double love = yp * std::log((a + rp) / (-a + rp)) + (ym == 0.0 ? 0.0 : ym * std::log((-a + rm) / (a + rm))) +
                      2.0 * a * std::log((yp + rp) / (ym + rm));
  return regular + 0.5 * love;
}

TEST(StripKernel, InfluenceCoefficientMatchesPaperEquations11And12) {
  const StripKernel& kernel = StripKernel::instance();
  const double b = 1.0;
  struct Case {
    double a;
    int k;
  };
  for (const Case c :
       {Case{0.5, 0}, Case{5.0, 0}, Case{100.0, 0}, Case{5.0, 1}, Case{60.0, 3}, Case{0.2, 10}, Case{300.0, 50}}) {
    const double d = 2.0 * b * c.k;
    const double closed = c.a * (kernel.value((d + b) / c.a) - kernel.value((d - b) / c.a));
    const double paper = paper_coefficient(c.a, b, d);
    EXPECT_NEAR(closed, paper, 1e-7 * std::abs(paper)) << "a/b = " << c.a << ", k = " << c.k;
  }
}
