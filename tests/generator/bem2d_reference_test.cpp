// SPDX-License-Identifier: Apache-2.0
// bem2d at fine meshes against Hertz, and against CONTACT (../shared/reference/contact, the same discretisation:
// piecewise-constant elements, Love's coefficients). Label "slow" (about a minute); the CONTACT tests skip when
// ../shared is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "ctab/contact/bem2d.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/fixtures/paper_cases.hpp"
#include "ctab/validation/reference_csv.hpp"
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

double relative(double value, double reference) { return value / reference - 1.0; }

bool have_reference() { return std::filesystem::exists(ctab::test::shared_path("reference/contact/README.md")); }

// One row of a CONTACT summary file by its `case` name, as column -> number.
std::map<std::string, double> reference_row(const std::string& file, const std::string& case_name) {
  const auto table = ctab::gen::read_csv(ctab::test::shared_path("reference/contact/" + file));
  const std::size_t name = table.column("case");
  std::map<std::string, double> out;
  for (const auto& row : table.rows)
    if (row[name] == case_name)
      for (std::size_t c = 0; c < table.header.size() && c < row.size(); ++c) try {
          out[table.header[c]] = std::stod(row[c]);
        } catch (const std::exception&) {
        }
  if (out.empty()) ADD_FAILURE() << "no case " << case_name << " in " << file;
  return out;
}

}  // namespace

// The fine-mesh bar: sphere R = 40 mm at 0.04 mm elements (158 per contact radius, 450 x 450 grid), prescribed
// approach 1 mm and prescribed load 963 kN: area within 0.2 %, max pressure within 0.5 %, force-approach relation.
TEST(Bem2dFineMesh, SphereWithinHertzTolerances) {
  const double A = 1.0 / (2 * paper::kSphereRadius_m);
  const HertzContact by_approach = hertz_from_approach(A, A, kEStar, 1e-3);
  const NormalSolution s = solve_bem2d_for_approach(paper::hertz_sphere_gap(), kEStar, square_grid(0.04e-3), 1e-3);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  EXPECT_NEAR(relative(s.patches[0].area_m2, by_approach.area_m2), 0.0, 0.002);
  EXPECT_NEAR(relative(s.patches[0].max_pressure_Pa, by_approach.max_pressure_Pa), 0.0, 0.005);
  EXPECT_NEAR(relative(s.normal_load_N, by_approach.normal_force_N), 0.0, 1e-4);
  const HertzContact by_load = hertz_from_load(A, A, kEStar, 963e3);
  const NormalSolution l = solve_bem2d_for_load(paper::hertz_sphere_gap(), kEStar, square_grid(0.04e-3), 963e3);
  ASSERT_EQ(l.status, SolveStatus::Converged);
  EXPECT_NEAR(relative(l.patches[0].area_m2, by_load.area_m2), 0.0, 0.002);
  EXPECT_NEAR(relative(l.patches[0].max_pressure_Pa, by_load.max_pressure_Pa), 0.0, 0.005);
  EXPECT_NEAR(relative(l.approach_m, by_load.approach_m), 0.0, 1e-4);
  std::cout << "sphere 0.04 mm: approach " << s.solve_time_s << " s, " << s.iterations << " it, area "
            << 100 * relative(s.patches[0].area_m2, by_approach.area_m2) << " %; load " << l.solve_time_s << " s, "
            << l.iterations << " it, area " << 100 * relative(l.patches[0].area_m2, by_load.area_m2) << " %\n";
}

// Ellipsoid B/A = 10 (a/b = 4.5), 160 elements per semi-axis (dx = a/160, dy = b/160).
TEST(Bem2dFineMesh, EllipsoidWithinHertzTolerances) {
  const double A = 2.5, B = 25.0, approach = 0.05e-3;
  const GapProfile gap = sample_gap(
      -5e-3, 5e-3, 0.01e-3, [&](double y) { return B * y * y; }, [&](double) { return A; }, [&](double) { return B; },
      "ellipsoid");
  const HertzContact h = hertz_from_approach(A, B, kEStar, approach);
  Bem2dGrid grid;
  grid.dx_m = h.semi_axis_x_m / 160;
  grid.dy_m = h.semi_axis_y_m / 160;
  const NormalSolution s = solve_bem2d_for_approach(gap, kEStar, grid, approach);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  EXPECT_NEAR(relative(s.patches[0].area_m2, h.area_m2), 0.0, 0.002);
  EXPECT_NEAR(relative(s.patches[0].max_pressure_Pa, h.max_pressure_Pa), 0.0, 0.005);
  EXPECT_NEAR(relative(s.normal_load_N, h.normal_force_N), 0.0, 1e-4);
}

// CONTACT's Hertz sphere rows (0.2, 0.08 and 0.04 mm, force 963 kN and approach 1 mm): the same discretisation,
// so area and max pressure within 1 % (measured: equal to CONTACT's printed digits).
TEST(Bem2dContact, HertzSphereRows) {
  if (!have_reference()) GTEST_SKIP() << "../shared/reference/contact is absent";
  for (const std::string name : {"hertz_F_dx0p2", "hertz_P_dx0p2", "hertz_F_dx0p08", "hertz_F_dx0p04"}) {
    const auto ref = reference_row("hertz_sphere.csv", name);
    const Bem2dGrid grid = square_grid(ref.at("dx_mm") * 1e-3);
    const bool force = name[6] == 'F';
    const NormalSolution s = force ? solve_bem2d_for_load(paper::hertz_sphere_gap(), kEStar, grid, ref.at("FN_N"))
                                   : solve_bem2d_for_approach(paper::hertz_sphere_gap(), kEStar, grid, 1e-3);
    ASSERT_EQ(s.status, SolveStatus::Converged) << name;
    EXPECT_NEAR(relative(s.patches[0].area_m2 * 1e6, ref.at("area_mm2")), 0.0, 0.01) << name;
    EXPECT_NEAR(relative(s.patches[0].max_pressure_Pa * 1e-6, ref.at("pmax_MPa")), 0.0, 0.01) << name;
    EXPECT_NEAR(relative(s.approach_m * 1e3, ref.at("approach_mm")), 0.0, 1e-4) << name;
    std::cout << name << ": area " << 100 * relative(s.patches[0].area_m2 * 1e6, ref.at("area_mm2")) << " %, pmax "
              << 100 * relative(s.patches[0].max_pressure_Pa * 1e-6, ref.at("pmax_MPa")) << " %, " << s.solve_time_s
              << " s\n";
  }
}

// The paper's non-Hertzian body (R_roll 400 mm, lateral 40 / 500 mm) at 0.2 mm: totals and every strip.
class Bem2dNonHertz : public ::testing::TestWithParam<bool> {};

TEST_P(Bem2dNonHertz, MatchesContact) {
  if (!have_reference()) GTEST_SKIP() << "../shared/reference/contact is absent";
  const bool force = GetParam();
  const auto ref = reference_row("nonhertz_r40_r500.csv", force ? "nonhz_F_dx0p2" : "nonhz_P_dx0p2");
  const NormalSolution s = force ? solve_bem2d_for_load(paper::nonhertz_gap(), kEStar, square_grid(0.2e-3), 2645e3)
                                 : solve_bem2d_for_approach(paper::nonhertz_gap(), kEStar, square_grid(0.2e-3), 1e-3);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  ASSERT_EQ(s.patches.size(), 1u);
  const PatchSolution& p = s.patches[0];
  EXPECT_NEAR(relative(p.area_m2 * 1e6, ref.at("area_mm2")), 0.0, 0.01);
  EXPECT_NEAR(relative(p.max_pressure_Pa * 1e-6, ref.at("pmax_MPa")), 0.0, 0.01);
  EXPECT_NEAR(relative(s.normal_load_N, ref.at("FN_N")), 0.0, 1e-4);
  EXPECT_NEAR(relative(s.approach_m * 1e3, ref.at("approach_mm")), 0.0, 1e-4);
  EXPECT_NEAR(p.centre_of_pressure_y_m * 1e3, ref.at("y_cop_mm"), 0.01);
  EXPECT_NEAR(p.y_min_m * 1e3, ref.at("y_min_mm"), 1e-9);
  EXPECT_NEAR(p.y_max_m * 1e3, ref.at("y_max_mm"), 1e-9);
  // Per strip (row): half the loaded x-extent exactly, row max pressure and row load within 0.1 %.
  const auto strips = ctab::gen::read_csv(ctab::test::shared_path(
      std::string("reference/contact/nonhertz_r40_r500_strips_") + (force ? "force2645kN" : "approach1mm") + ".csv"));
  const auto y = strips.numbers("y_mm"), a = strips.numbers("a_count_mm"), p0 = strips.numbers("p0_i_MPa"),
             q = strips.numbers("q_i_N_per_mm");
  ASSERT_EQ(p.strips.size(), y.size());
  for (std::size_t k = 0; k < y.size(); ++k) {
    const StripSolution& mine = p.strips[k];
    EXPECT_NEAR(mine.y_m * 1e3, y[k], 1e-9);
    EXPECT_NEAR(mine.half_length_m * 1e3, a[k], 1e-9) << y[k];
    EXPECT_NEAR(relative(mine.p0_Pa * 1e-6, p0[k]), 0.0, 1e-3) << y[k];
    EXPECT_NEAR(relative(mine.load_N / 0.2, q[k]), 0.0, 1e-3) << y[k];  // N per mm of width
  }
  std::cout << (force ? "force" : "approach") << ": area " << 100 * relative(p.area_m2 * 1e6, ref.at("area_mm2"))
            << " %, pmax " << 100 * relative(p.max_pressure_Pa * 1e-6, ref.at("pmax_MPa")) << " %, " << s.solve_time_s
            << " s, " << s.iterations << " it\n";
}

INSTANTIATE_TEST_SUITE_P(BothLoadings, Bem2dNonHertz, ::testing::Values(false, true), [](const auto& param_info) {
  return param_info.param ? std::string("Force") : std::string("Approach");
});
