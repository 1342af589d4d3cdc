// bem2d, the 2-D boundary-element reference: influence coefficients, FFT product, statuses, Hertz, and CONTACT
// (../shared/reference/contact; those tests skip when ../shared is absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

#include "ctab/contact/bem2d.hpp"
#include "ctab/contact/bem2d_convolution.hpp"
#include "ctab/contact/bem2d_influence.hpp"
#include "ctab/contact/error.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/fixtures/paper_cases.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

const double kEStar = effective_modulus(kSteel, kSteel);

Bem2dGrid square_grid(double size_m) {
  Bem2dGrid g;
  g.dx_m = size_m;
  g.dy_m = size_m;
  return g;
}

}  // namespace

TEST(Bem2dInfluence, SelfCoefficientOfASquare) {
  const double h = 0.2e-3;
  const double expected = 4.0 * h * std::log(1.0 + std::sqrt(2.0)) / (std::numbers::pi * kEStar);
  EXPECT_NEAR(love_influence_m_per_Pa(0, 0, h, h, kEStar) / expected, 1.0, 1e-13);
}

TEST(Bem2dInfluence, FarFieldIsAPointLoad) {
  // Boussinesq: u = P / (pi E* r) with P = dx dy.
  const double dx = 0.2e-3, dy = 0.1e-3, x = 30e-3, y = -40e-3;
  const double point = dx * dy / (std::numbers::pi * kEStar * std::hypot(x, y));
  EXPECT_NEAR(love_influence_m_per_Pa(x, y, dx, dy, kEStar) / point, 1.0, 1e-5);
}

TEST(Bem2dConvolution, MatchesTheDirectSum) {
  for (const auto& [nx, ny] : {std::pair<std::size_t, std::size_t>{7, 5}, {13, 1}, {1, 9}, {33, 17}}) {
    const double dx = 0.3e-3, dy = 0.2e-3;
    InfluenceConvolution A(nx, ny, dx, dy, kEStar);
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> pressure(0.0, 1e9);
    std::vector<double> p(nx * ny), u;
    for (double& v : p) v = pressure(rng);
    A.apply(p, u);
    ASSERT_EQ(u.size(), nx * ny);
    double worst = 0.0, largest = 0.0;
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        double direct = 0.0;
        for (std::size_t l = 0; l < ny; ++l)
          for (std::size_t k = 0; k < nx; ++k)
            direct += p[l * nx + k] * love_influence_m_per_Pa((double(i) - double(k)) * dx, (double(j) - double(l)) * dy,
                                                              dx, dy, kEStar);
        worst = std::max(worst, std::abs(u[j * nx + i] - direct));
        largest = std::max(largest, std::abs(direct));
      }
    EXPECT_LT(worst / largest, 1e-12) << nx << " x " << ny;
    EXPECT_NEAR(A.self_coefficient() / love_influence_m_per_Pa(0, 0, dx, dy, kEStar), 1.0, 1e-14);
  }
}

TEST(Bem2dConvolution, RejectsBadSizes) {
  EXPECT_THROW((void)InfluenceConvolution(0, 3, 1e-4, 1e-4, kEStar), InputError);
  EXPECT_THROW((void)InfluenceConvolution(3, kBem2dMaxElementsPerSide + 1, 1e-4, 1e-4, kEStar), InputError);
  EXPECT_THROW((void)InfluenceConvolution(3, 3, -1e-4, 1e-4, kEStar), InputError);
  EXPECT_THROW((void)InfluenceConvolution(3, 3, 1e-4, 1e-4, std::nan("")), InputError);
}

TEST(Bem2dHertz, SphereCoarse) {
  const GapProfile gap = paper::hertz_sphere_gap();
  const double A = 1.0 / (2 * paper::kSphereRadius_m);
  const NormalSolution s = solve_bem2d_for_approach(gap, kEStar, square_grid(0.2e-3), 1e-3);
  const HertzContact h = hertz_from_approach(A, A, kEStar, 1e-3);
  ASSERT_EQ(s.status, SolveStatus::Converged) << status_name(s.status);
  ASSERT_EQ(s.patches.size(), 1u);
  std::cout << "iterations " << s.iterations << " time " << s.solve_time_s << " area " << s.patches[0].area_m2 / h.area_m2 - 1
            << " pmax " << s.patches[0].max_pressure_Pa / h.max_pressure_Pa - 1 << " N " << s.normal_load_N / h.normal_force_N - 1
            << '\n';
}
