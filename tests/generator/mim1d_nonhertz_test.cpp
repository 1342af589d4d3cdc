// SPDX-License-Identifier: Apache-2.0
// MIM-1D on the paper's non-Hertzian case (3.1.2) against CONTACT (../shared/reference/contact):
// rolling radius 400 mm, lateral radius 40 mm (y < 0) / 500 mm (y >= 0), on a flat, steel, strips 0.2 mm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/fixtures/paper_cases.hpp"
#include "ctab/validation/reference_csv.hpp"
#include "test_support.hpp"

using namespace ctab::gen;

namespace {

const double kEStar = effective_modulus(kSteel, kSteel);

struct StripErrors {
  double half_length_rms = 0.0;  // RMS of (a_i - a_ell) over max a_ell
  double p0_rms = 0.0;           // RMS of (p0_i - row max) over max row max
  std::size_t matched = 0;
};

// Compares per strip with CONTACT's rows (same strip centres: edges at multiples of 0.2 mm). A CONTACT row
// without a MIM-1D strip counts with MIM-1D's value 0, and vice versa.
StripErrors compare_strips(const NormalSolution& s, const std::string& file) {
  const auto table = ctab::gen::read_csv(ctab::test::shared_path("reference/contact/" + file));
  const auto y = table.numbers("y_mm"), a = table.numbers("a_ell_mm"), p = table.numbers("p0_i_MPa");
  std::map<long, std::pair<double, double>> mim;  // key: strip centre in 0.1 mm units
  for (const auto& patch : s.patches)
    for (const auto& strip : patch.strips)
      mim[std::lround(strip.y_m * 1e4)] = {strip.half_length_m * 1e3, strip.p0_Pa * 1e-6};
  std::map<long, std::pair<double, double>> ref;
  for (std::size_t i = 0; i < y.size(); ++i) ref[std::lround(y[i] * 10)] = {a[i], p[i]};
  double sa = 0, sp = 0;
  std::size_t count = 0;
  StripErrors e;
  for (const auto& [key, value] : ref) {
    const auto found = mim.find(key);
    const auto mine = found == mim.end() ? std::pair<double, double>{0, 0} : found->second;
    if (found != mim.end()) ++e.matched;
    sa += std::pow(mine.first - value.first, 2);
    sp += std::pow(mine.second - value.second, 2);
    ++count;
  }
  for (const auto& [key, value] : mim)
    if (!ref.count(key)) {
      sa += value.first * value.first;
      sp += value.second * value.second;
      ++count;
    }
  e.half_length_rms = std::sqrt(sa / static_cast<double>(count)) / *std::max_element(a.begin(), a.end());
  e.p0_rms = std::sqrt(sp / static_cast<double>(count)) / *std::max_element(p.begin(), p.end());
  return e;
}

double reference_value(const std::string& case_name, const std::string& column) {
  const auto table = ctab::gen::read_csv(ctab::test::shared_path("reference/contact/nonhertz_r40_r500.csv"));
  const std::size_t c = table.column(column), name = table.column("case");
  for (const auto& row : table.rows)
    if (row[name] == case_name) return std::stod(row[c]);
  ADD_FAILURE() << "no case " << case_name;
  return 0.0;
}

}  // namespace

TEST(Mim1dNonHertz, PrescribedApproachMatchesContact) {
  CTAB_REQUIRE_SHARED();
  Mim1dSolver solver(paper::nonhertz_gap(), kEStar, {});
  const NormalSolution s = solver.solve_for_approach(1e-3);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  ASSERT_EQ(s.patches.size(), 1u);
  const double force = reference_value("nonhz_P_dx0p2", "FN_N"), area = reference_value("nonhz_P_dx0p2", "area_mm2");
  EXPECT_NEAR(force, 2645.5e3, 1e3);
  EXPECT_NEAR(s.normal_load_N / force - 1.0, 0.0, 0.01);
  EXPECT_NEAR(s.patches[0].area_m2 * 1e6 / area - 1.0, 0.0, 0.01);
  const StripErrors e = compare_strips(s, "nonhertz_r40_r500_strips_approach1mm.csv");
  EXPECT_GE(e.matched, 138u);
  EXPECT_LT(e.p0_rms, 0.02);
  EXPECT_LT(e.half_length_rms, 0.05);
  // Centre of pressure (CONTACT: 5.5835 mm) to 0.2 mm.
  EXPECT_NEAR(s.patches[0].centre_of_pressure_y_m * 1e3, reference_value("nonhz_P_dx0p2", "y_cop_mm"), 0.2);
}

TEST(Mim1dNonHertz, PrescribedLoadMatchesContact) {
  CTAB_REQUIRE_SHARED();
  Mim1dSolver solver(paper::nonhertz_gap(), kEStar, {});
  const NormalSolution s = solver.solve_for_load(2645e3);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  EXPECT_NEAR(s.normal_load_N, 2645e3, 1e-6 * 2645e3);
  EXPECT_NEAR(s.approach_m * 1e3, reference_value("nonhz_F_dx0p2", "approach_mm"), 0.01 * 1.0);
  EXPECT_NEAR(s.patches[0].area_m2 * 1e6 / reference_value("nonhz_F_dx0p2", "area_mm2") - 1.0, 0.0, 0.01);
  const StripErrors e = compare_strips(s, "nonhertz_r40_r500_strips_force2645kN.csv");
  EXPECT_LT(e.p0_rms, 0.02);
  EXPECT_LT(e.half_length_rms, 0.05);
}

TEST(Mim1dNonHertz, PointwiseCurvatureShowsThePapersBottleneck) {
  CTAB_REQUIRE_SHARED();
  // The paper's Eq. 26 with local curvature: a_i jumps at y = 0 (~17 -> ~29 mm), CONTACT stays near 21.5 mm.
  Mim1dOptions options;
  options.curvature.treatment = CurvatureTreatment::Pointwise;
  Mim1dSolver solver(paper::nonhertz_gap(), kEStar, options);
  const NormalSolution s = solver.solve_for_approach(1e-3);
  ASSERT_EQ(s.status, SolveStatus::Converged);
  double left = 0, right = 0;
  for (const auto& strip : s.patches[0].strips) {
    if (std::abs(strip.y_m + 0.1e-3) < 1e-9) left = strip.half_length_m;
    if (std::abs(strip.y_m - 0.1e-3) < 1e-9) right = strip.half_length_m;
  }
  EXPECT_GT(right / left, 1.5);
  EXPECT_GT(compare_strips(s, "nonhertz_r40_r500_strips_approach1mm.csv").half_length_rms, 0.07);
}
