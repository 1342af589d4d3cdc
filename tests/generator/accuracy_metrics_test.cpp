// SPDX-License-Identifier: Apache-2.0
// Accuracy measures of `ctab bench accuracy` (accuracy_metrics.hpp): summaries of solutions and their errors.
#include "ctab/validation/accuracy_metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace ctab::gen;

PatchSolution patch(double y0, double force_N, double area_m2, std::initializer_list<double> p0) {
  PatchSolution p;
  p.normal_force_N = force_N;
  p.area_m2 = area_m2;
  double y = y0;
  for (const double v : p0) {
    p.strips.push_back({y, 1e-3, v, 0.0});
    p.max_pressure_Pa = std::max(p.max_pressure_Pa, v);
    y += 1e-3;
  }
  p.centre_of_pressure_y_m = y0 + 1e-3;
  return p;
}

TEST(AccuracyMetrics, SummaryAddsPatchesAndWeighsTheCentreOfPressureByLoad) {
  NormalSolution s;
  s.patches = {patch(0.0, 1000.0, 2e-6, {1e8, 3e8, 1e8}), patch(0.010, 3000.0, 1e-6, {2e8, 4e8, 2e8})};
  const ContactSummary summary = summarise(s);
  EXPECT_DOUBLE_EQ(summary.area_m2, 3e-6);
  EXPECT_DOUBLE_EQ(summary.max_pressure_Pa, 4e8);
  EXPECT_DOUBLE_EQ(summary.normal_force_N, 4000.0);
  EXPECT_NEAR(summary.centre_of_pressure_m, (1000.0 * 1e-3 + 3000.0 * 11e-3) / 4000.0, 1e-15);
  EXPECT_NEAR(profile_pressure_at(summary, 0.5e-3), 2e8, 1.0);   // between the first two strips
  EXPECT_NEAR(profile_pressure_at(summary, 11e-3), 4e8, 1.0);    // at a strip of the second patch
  EXPECT_DOUBLE_EQ(profile_pressure_at(summary, 5e-3), 0.0);     // between the patches
  EXPECT_DOUBLE_EQ(profile_pressure_at(summary, -0.4e-3), 1e8);  // outer half of the first strip
  EXPECT_DOUBLE_EQ(profile_pressure_at(summary, 12.4e-3), 2e8);  // outer half of the last strip
  EXPECT_DOUBLE_EQ(profile_pressure_at(summary, -0.6e-3), 0.0);  // outside
}

TEST(AccuracyMetrics, ErrorsAgainstAReference) {
  NormalSolution reference, candidate;
  reference.patches = {patch(0.0, 1000.0, 2e-6, {1e8, 2e8, 1e8})};
  candidate.patches = {patch(1e-3, 1000.0, 2.2e-6, {1e8, 3e8, 1e8})};  // shifted by one strip, 10 % larger
  const AccuracyErrors same = accuracy_errors(summarise(reference), summarise(reference));
  EXPECT_EQ(same.area_rel, 0.0);
  EXPECT_EQ(same.p0_profile_rms_rel, 0.0);
  const AccuracyErrors e = accuracy_errors(summarise(candidate), summarise(reference));
  EXPECT_NEAR(e.area_rel, 0.1, 1e-12);
  EXPECT_NEAR(e.max_pressure_rel, 0.5, 1e-12);
  EXPECT_NEAR(e.contact_point_m, 1e-3, 1e-15);
  // at the reference strips y = 0, 1, 2 mm the candidate has 0, 1e8, 3e8 against 1e8, 2e8, 1e8
  EXPECT_NEAR(e.p0_profile_rms_rel, std::sqrt((1.0 + 1.0 + 4.0) / (1.0 + 4.0 + 1.0)), 1e-12);
  // no contact at all: 100 % off in area, pressure and profile
  const AccuracyErrors none = accuracy_errors(summarise(NormalSolution{}), summarise(reference));
  EXPECT_DOUBLE_EQ(none.area_rel, 1.0);
  EXPECT_DOUBLE_EQ(none.p0_profile_rms_rel, 1.0);
}

}  // namespace
