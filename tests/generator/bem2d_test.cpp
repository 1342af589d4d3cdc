// SPDX-License-Identifier: Apache-2.0
// bem2d, the 2-D boundary-element reference: influence coefficients, FFT product, statuses, Hertz, and CONTACT
// (../shared/reference/contact; those tests skip when ../shared is absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "ctab/contact/bem2d.hpp"
#include "ctab/contact/bem2d_convolution.hpp"
#include "ctab/contact/bem2d_influence.hpp"
#include "ctab/core/error.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/fixtures/paper_cases.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

const double kEStar = effective_modulus(kSteel, kSteel);

Bem2dGrid grid_of(double dx_m, double dy_m) {
  Bem2dGrid g;
  g.dx_m = dx_m;
  g.dy_m = dy_m;
  return g;
}

// Ellipsoid on a flat: h = A x^2 + B y^2 with B/A = 10 (Hertz a/b = 4.5).
constexpr double kEllipsoidA = 2.5, kEllipsoidB = 25.0;  // [1/m]
GapProfile ellipsoid_gap() {
  return sample_gap(
      -5e-3, 5e-3, 0.01e-3, [](double y) { return kEllipsoidB * y * y; }, [](double) { return kEllipsoidA; },
      [](double) { return kEllipsoidB; }, "ellipsoid");
}

double relative(double value, double reference) { return value / reference - 1.0; }

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
            direct += p[l * nx + k] * love_influence_m_per_Pa((double(i) - double(k)) * dx,
                                                              (double(j) - double(l)) * dy, dx, dy, kEStar);
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

// Sphere R = 40 mm at 0.2 mm elements: the same numbers as CONTACT's run on that mesh (hertz_sphere.csv, row
// hertz_P_dx0p2: area +0.841 %, pmax -0.018 %, force +0.006 % against Hertz): area converges from above.
TEST(Bem2dHertz, SphereAtCoarseMeshPrescribedApproach) {
  const double A = 1.0 / (2 * paper::kSphereRadius_m);
  const HertzContact h = hertz_from_approach(A, A, kEStar, 1e-3);
  Bem2dPressureField field;
  const NormalSolution s =
      solve_bem2d_for_approach(paper::hertz_sphere_gap(), kEStar, grid_of(0.2e-3, 0.2e-3), 1e-3, &field);
  ASSERT_EQ(s.status, SolveStatus::Converged) << status_name(s.status);
  EXPECT_EQ(s.method, "bem2d");
  ASSERT_EQ(s.patches.size(), 1u);
  const PatchSolution& p = s.patches[0];
  EXPECT_NEAR(relative(p.area_m2, h.area_m2), 0.0084, 0.0002);
  EXPECT_NEAR(relative(p.max_pressure_Pa, h.max_pressure_Pa), 0.0, 5e-4);
  EXPECT_NEAR(relative(s.normal_load_N, h.normal_force_N), 0.0, 5e-4);
  EXPECT_DOUBLE_EQ(s.approach_m, 1e-3);
  EXPECT_NEAR(p.centre_of_pressure_y_m, 0.0, 1e-9);
  // 64 rows of 0.2 mm over the diameter 12.65 mm; symmetric about y = 0 (an element edge).
  ASSERT_EQ(p.strips.size(), 64u);
  EXPECT_NEAR(p.y_min_m, -6.4e-3, 1e-12);
  EXPECT_NEAR(p.y_max_m, 6.4e-3, 1e-12);
  for (std::size_t k = 0; k < p.strips.size(); ++k) {
    const StripSolution& a = p.strips[k];
    const StripSolution& b = p.strips[p.strips.size() - 1 - k];
    EXPECT_NEAR(a.load_N, b.load_N, 1e-6 * p.normal_force_N);
    EXPECT_NEAR(a.half_length_m, b.half_length_m, 1e-12);
    // Half-length of the row within one element of Hertz's chord over the row's width.
    const auto chord = [&](double y) {
      return h.semi_axis_x_m * std::sqrt(std::max(0.0, 1.0 - std::pow(y / h.semi_axis_y_m, 2)));
    };
    EXPECT_LE(a.half_length_m, chord(std::abs(a.y_m) - 0.1e-3) + 0.2e-3) << a.y_m;
    EXPECT_GE(a.half_length_m, chord(std::abs(a.y_m) + 0.1e-3) - 0.2e-3) << a.y_m;
  }
  // The field: its sum is the load, its maximum the peak pressure, symmetric in x.
  double sum = 0.0, peak = 0.0;
  for (const double v : field.pressure_Pa) {
    sum += v * field.dx_m * field.dy_m;
    peak = std::max(peak, v);
  }
  EXPECT_NEAR(sum, s.normal_load_N, 1e-9 * s.normal_load_N);
  EXPECT_EQ(peak, p.max_pressure_Pa);
  for (std::size_t j = 0; j < field.ny; ++j)
    for (std::size_t i = 0; i < field.nx; ++i) EXPECT_NEAR(field.at(i, j), field.at(field.nx - 1 - i, j), 1e-6 * peak);
  EXPECT_NEAR(field.x0_m + 0.5 * static_cast<double>(field.nx - 1) * field.dx_m, 0.0, 1e-12);
}

TEST(Bem2dHertz, SphereAtCoarseMeshPrescribedLoad) {
  const double A = 1.0 / (2 * paper::kSphereRadius_m), force = 963e3;
  const HertzContact h = hertz_from_load(A, A, kEStar, force);
  const NormalSolution s = solve_bem2d_for_load(paper::hertz_sphere_gap(), kEStar, grid_of(0.2e-3, 0.2e-3), force);
  ASSERT_EQ(s.status, SolveStatus::Converged) << status_name(s.status);
  ASSERT_EQ(s.patches.size(), 1u);
  EXPECT_NEAR(s.normal_load_N, force, 1e-9 * force);
  EXPECT_NEAR(relative(s.approach_m, h.approach_m), 0.0, 2e-4);  // force-approach relation
  EXPECT_NEAR(relative(s.patches[0].area_m2, h.area_m2), 0.0089, 0.0002);
  EXPECT_NEAR(relative(s.patches[0].max_pressure_Pa, h.max_pressure_Pa), 0.0, 5e-4);
  EXPECT_GE(s.outer_iterations, 1);
}

// Refinement: the area error against Hertz falls from 1.5 % (20 elements per semi-axis) to 0.6 % (40);
// rectangular elements dx != dy.
TEST(Bem2dHertz, EllipsoidConvergesWithTheMesh) {
  const double approach = 0.05e-3;
  const HertzContact h = hertz_from_approach(kEllipsoidA, kEllipsoidB, kEStar, approach);
  double previous = 1.0;
  for (const double per_semi_axis : {20.0, 40.0}) {
    const NormalSolution s =
        solve_bem2d_for_approach(ellipsoid_gap(), kEStar,
                                 grid_of(h.semi_axis_x_m / per_semi_axis, h.semi_axis_y_m / per_semi_axis), approach);
    ASSERT_EQ(s.status, SolveStatus::Converged);
    const double area_error = relative(s.patches[0].area_m2, h.area_m2);
    EXPECT_GT(area_error, 0.0);
    EXPECT_LT(area_error, 0.6 * previous);
    EXPECT_NEAR(relative(s.patches[0].max_pressure_Pa, h.max_pressure_Pa), 0.0, 1e-3);
    EXPECT_NEAR(relative(s.normal_load_N, h.normal_force_N), 0.0, 5e-4);
    previous = area_error;
  }
  EXPECT_LT(previous, 0.007);
}

TEST(Bem2dPatches, TwoSeparateContactsGiveTwoPatches) {
  // Two spherical bumps (R = 40 mm) centred at y = -/+4 mm.
  const double R = 0.04, c = 4e-3;
  const GapProfile gap = sample_gap(
      -10e-3, 10e-3, 0.05e-3, [&](double y) { return std::pow(std::abs(y) - c, 2) / (2 * R); },
      [&](double) { return 1 / (2 * R); }, [&](double) { return 1 / (2 * R); }, "two bumps");
  const NormalSolution s = solve_bem2d_for_approach(gap, kEStar, grid_of(0.2e-3, 0.2e-3), 0.05e-3);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_NEAR(s.patches[0].centre_of_pressure_y_m, -c, 0.05e-3);
  EXPECT_NEAR(s.patches[1].centre_of_pressure_y_m, c, 0.05e-3);
  EXPECT_NEAR(s.patches[0].normal_force_N, s.patches[1].normal_force_N, 1e-4 * s.normal_load_N);
  EXPECT_NEAR(s.patches[0].normal_force_N + s.patches[1].normal_force_N, s.normal_load_N, 1e-9 * s.normal_load_N);
}

TEST(Bem2dStatus, BadInputIsInvalidInput) {
  const GapProfile gap = paper::hertz_sphere_gap();
  const Bem2dGrid good = grid_of(0.2e-3, 0.2e-3);
  for (const Bem2dGrid& bad : {grid_of(0.0, 0.2e-3), grid_of(0.2e-3, -1.0), grid_of(std::nan(""), 0.2e-3),
                               grid_of(std::numeric_limits<double>::infinity(), 0.2e-3)}) {
    EXPECT_EQ(solve_bem2d_for_approach(gap, kEStar, bad, 1e-3).status, SolveStatus::InvalidInput);
    EXPECT_EQ(solve_bem2d_for_load(gap, kEStar, bad, 1e3).status, SolveStatus::InvalidInput);
  }
  Bem2dGrid no_tolerance = good;
  no_tolerance.tolerance = 0.0;
  EXPECT_EQ(solve_bem2d_for_approach(gap, kEStar, no_tolerance, 1e-3).status, SolveStatus::InvalidInput);
  Bem2dGrid no_iterations = good;
  no_iterations.max_iterations = 0;
  EXPECT_EQ(solve_bem2d_for_approach(gap, kEStar, no_iterations, 1e-3).status, SolveStatus::InvalidInput);
  EXPECT_EQ(solve_bem2d_for_approach(gap, -1.0, good, 1e-3).status, SolveStatus::InvalidInput);
  EXPECT_EQ(solve_bem2d_for_approach(gap, kEStar, good, std::nan("")).status, SolveStatus::InvalidInput);
  EXPECT_EQ(solve_bem2d_for_load(gap, kEStar, good, -1.0).status, SolveStatus::InvalidInput);
  EXPECT_EQ(solve_bem2d_for_load(gap, kEStar, good, std::numeric_limits<double>::infinity()).status,
            SolveStatus::InvalidInput);
  GapProfile broken = gap;
  broken.A_per_m[3] = -1.0;
  EXPECT_EQ(solve_bem2d_for_approach(broken, kEStar, good, 1e-3).status, SolveStatus::InvalidInput);
  // A grid over kBem2dMaxElementsPerSide is refused before anything is allocated.
  const NormalSolution tiny = solve_bem2d_for_approach(gap, kEStar, grid_of(1e-6, 1e-6), 1e-3);
  EXPECT_EQ(tiny.status, SolveStatus::InvalidInput);
  EXPECT_EQ(tiny.method, "bem2d");
  EXPECT_TRUE(tiny.patches.empty());
}

TEST(Bem2dStatus, NoContact) {
  const GapProfile gap = paper::hertz_sphere_gap();
  const NormalSolution apart = solve_bem2d_for_approach(gap, kEStar, grid_of(0.2e-3, 0.2e-3), -1e-6);
  EXPECT_EQ(apart.status, SolveStatus::NoContact);
  EXPECT_EQ(apart.normal_load_N, 0.0);
  EXPECT_TRUE(apart.patches.empty());
  const NormalSolution unloaded = solve_bem2d_for_load(gap, kEStar, grid_of(0.2e-3, 0.2e-3), 0.0);
  EXPECT_EQ(unloaded.status, SolveStatus::NoContact);
  EXPECT_TRUE(unloaded.patches.empty());
}

TEST(Bem2dStatus, ContactReachingTheEndOfTheGapIsTruncated) {
  // Sphere data only on |y| <= 3 mm, contact half-width 6.3 mm.
  const GapProfile gap = sphere_on_flat_gap(paper::kSphereRadius_m, 3e-3, 0.05e-3);
  const NormalSolution s = solve_bem2d_for_approach(gap, kEStar, grid_of(0.2e-3, 0.2e-3), 1e-3);
  EXPECT_EQ(s.status, SolveStatus::ZoneTruncated);
  const NormalSolution l = solve_bem2d_for_load(gap, kEStar, grid_of(0.2e-3, 0.2e-3), 963e3);
  EXPECT_EQ(l.status, SolveStatus::ZoneTruncated);
  EXPECT_TRUE(std::isfinite(l.approach_m));
}

TEST(Bem2dStatus, IterationCapGivesMaxIterations) {
  Bem2dGrid capped = grid_of(0.2e-3, 0.2e-3);
  capped.max_iterations = 3;
  const NormalSolution s = solve_bem2d_for_approach(paper::hertz_sphere_gap(), kEStar, capped, 1e-3);
  EXPECT_EQ(s.status, SolveStatus::MaxIterations);
  EXPECT_EQ(s.iterations, 3);
  EXPECT_TRUE(std::isfinite(s.normal_load_N));
}

TEST(Bem2dStatus, TinyLoadStillTouches) {
  // 1 mN on the sphere: the Hertz radius (~2 um) is far below one element; one element carries it.
  const NormalSolution s = solve_bem2d_for_load(paper::hertz_sphere_gap(), kEStar, grid_of(0.2e-3, 0.2e-3), 1e-3);
  ASSERT_EQ(s.status, SolveStatus::Converged) << status_name(s.status);
  EXPECT_NEAR(s.normal_load_N, 1e-3, 1e-12);
  ASSERT_EQ(s.patches.size(), 1u);
  EXPECT_GT(s.approach_m, 0.0);
  EXPECT_TRUE(std::isfinite(s.patches[0].max_pressure_Pa));
}
