// SPDX-License-Identifier: Apache-2.0
// Hertz coefficients against the check table of facts/methods_and_tables.md 1.1.2 (AGM-derived) and exact
// relations for the sphere and for elongated ellipses (where a modulus/parameter mix-up shows).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ctab/contact/elliptic.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/contact/material.hpp"

using namespace ctab::gen;

struct TableRow {
  double ratio, m, n, r;  // B/A and the coefficients
};

TEST(Hertz, CoefficientTable) {
  const TableRow rows[] = {{1, 1.0, 1.0, 1.0},           {1.5, 1.1498, 0.8776, 0.9910}, {2, 1.2758, 0.8045, 0.9741},
                           {3, 1.4858, 0.7171, 0.9376},  {5, 1.8129, 0.6273, 0.8757},   {10, 2.3905, 0.5313, 0.7761},
                           {20, 3.1570, 0.4556, 0.6723}, {50, 4.5443, 0.3765, 0.5439},  {100, 5.9607, 0.3277, 0.4581}};
  for (const TableRow& row : rows) {
    HertzCoefficients c;
    ASSERT_TRUE(hertz_coefficients(1.0, row.ratio, c));
    EXPECT_NEAR(c.m, row.m, 6e-5 * row.m) << "B/A = " << row.ratio;
    EXPECT_NEAR(c.n, row.n, 6e-5 * row.n + 1e-4) << "B/A = " << row.ratio;
    EXPECT_NEAR(c.r, row.r, 6e-5 * row.r + 1e-4) << "B/A = " << row.ratio;
  }
}

TEST(Hertz, AxesFollowTheSmallerCurvature) {
  HertzCoefficients along_x, along_y;
  ASSERT_TRUE(hertz_coefficients(1.0, 3.0, along_x));
  ASSERT_TRUE(hertz_coefficients(3.0, 1.0, along_y));
  EXPECT_DOUBLE_EQ(along_x.m, along_y.n);
  EXPECT_DOUBLE_EQ(along_x.n, along_y.m);
  EXPECT_GT(along_x.m, along_x.n);
}

TEST(Hertz, SphereOnFlat) {
  const double E_star = effective_modulus(kSteel, kSteel);
  EXPECT_NEAR(E_star, 208e9 / (2 * (1 - 0.09)), 1e-3);
  const double R = 0.040, A = 1 / (2 * R);
  const HertzContact c = hertz_from_approach(A, A, E_star, 1e-3);
  ASSERT_EQ(c.status, SolveStatus::Converged);
  EXPECT_NEAR(c.normal_force_N, 4.0 / 3.0 * E_star * std::sqrt(R) * std::pow(1e-3, 1.5), 1e-6);
  EXPECT_NEAR(c.normal_force_N, 963.74e3, 0.01e3);
  EXPECT_NEAR(c.semi_axis_x_m, std::sqrt(R * 1e-3), 1e-12);
  EXPECT_NEAR(c.area_m2, 125.66e-6, 0.01e-6);
}

TEST(Hertz, ElongatedEllipseSatisfiesTheExactRelations) {
  // For a >= b: p0 = (A + B) E* b / E(e) and delta = b p0 K(e) / E*, with m_e = 1 - (b/a)^2 (parameter).
  const double E_star = 114.3e9;
  for (const double ratio : {0.01, 0.05, 20.0, 100.0}) {
    const double A = 2.0, B = 2.0 * ratio;
    const HertzContact c = hertz_from_load(A, B, E_star, 50e3);
    ASSERT_EQ(c.status, SolveStatus::Converged);
    const double major = std::max(c.semi_axis_x_m, c.semi_axis_y_m), minor = std::min(c.semi_axis_x_m, c.semi_axis_y_m);
    const double m = 1.0 - (minor / major) * (minor / major);
    EXPECT_NEAR(c.max_pressure_Pa, (A + B) * E_star * minor / elliptic_e(m), 1e-9 * c.max_pressure_Pa);
    EXPECT_NEAR(c.approach_m, minor * c.max_pressure_Pa * elliptic_k(m) / E_star, 1e-9 * c.approach_m);
    EXPECT_NEAR(c.normal_force_N, 2.0 / 3.0 * std::numbers::pi * major * minor * c.max_pressure_Pa, 1e-6);
    const HertzContact back = hertz_from_approach(A, B, E_star, c.approach_m);
    EXPECT_NEAR(back.normal_force_N, 50e3, 1e-8 * 50e3);
  }
}

TEST(Hertz, StripCompliancePaperEq25) {
  // a_i = pi m^2 n p0_i / (2 E* (A + B)) reproduces the Hertz semi-axis at the centre.
  const double E_star = 114.3e9, A = 1.25, B = 12.5;
  const HertzContact c = hertz_from_load(A, B, E_star, 1e6);
  EXPECT_NEAR(strip_length_compliance(A, B, E_star) * c.max_pressure_Pa, c.semi_axis_x_m, 1e-12 * c.semi_axis_x_m);
}

TEST(Hertz, InvalidInputIsAStatus) {
  HertzCoefficients c;
  EXPECT_FALSE(hertz_coefficients(-1.0, 1.0, c));
  EXPECT_FALSE(hertz_coefficients(1.0, 0.0, c));
  EXPECT_FALSE(hertz_coefficients(NAN, 1.0, c));
  EXPECT_EQ(hertz_from_load(1.0, 1.0, 1e11, NAN).status, SolveStatus::InvalidInput);
  EXPECT_EQ(hertz_from_load(1.0, 1.0, 1e11, 0.0).status, SolveStatus::NoContact);
  EXPECT_THROW((void)effective_modulus({-1.0, 0.3}, kSteel), std::exception);
  EXPECT_THROW((void)effective_modulus({1e9, 0.5}, kSteel), std::exception);
}
