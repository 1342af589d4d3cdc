// SPDX-License-Identifier: Apache-2.0
// make_uniform_axis: the validated uniform-axis builder shared by table configs and `ctab geometry`.
#include <gtest/gtest.h>

#include <limits>

#include "ctab/wheelrail/axis_range.hpp"

using namespace ctab::gen;

TEST(AxisRange, BuildsTheDefaultAxisExactlyAntisymmetric) {
  const UniformAxis axis = make_uniform_axis(-12e-3, 12e-3, 0.1e-3);
  ASSERT_TRUE(axis.ok());
  ASSERT_EQ(axis.values.size(), 241u);
  EXPECT_EQ(axis.values[120], 0.0);
  for (std::size_t i = 0; i < 241; ++i) EXPECT_EQ(axis.values[240 - i], -axis.values[i]);
  EXPECT_EQ(make_uniform_axis(1.0, 1.0, 0.5).values, std::vector<double>{1.0});
  EXPECT_EQ(make_uniform_axis(0.0, 1.0, 0.25).values, (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
}

TEST(AxisRange, RejectsEveryBadRangeWithoutAllocating) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  struct Bad {
    double start, stop, step;
    AxisProblem problem;
    const char* part;
  };
  for (const Bad& b :
       {Bad{nan, 1, 1, AxisProblem::NonFinite, "start"}, Bad{0, inf, 1, AxisProblem::NonFinite, "stop"},
        Bad{0, 1, nan, AxisProblem::NonFinite, "step"}, Bad{0, 1, 0, AxisProblem::NonPositiveStep, "step"},
        Bad{0, 1, -1, AxisProblem::NonPositiveStep, "step"}, Bad{1, 0, 0.1, AxisProblem::StopBelowStart, "stop"},
        Bad{-12e-3, 12e-3, 1e-21, AxisProblem::TooManyPoints, ""},
        Bad{-1e308, 1e308, 1.0, AxisProblem::TooManyPoints, ""}, Bad{0.0, 1e-3, 1e-15, AxisProblem::TooManyPoints, ""},
        Bad{1.0, 1.0 + 1e-15, 1e-16, AxisProblem::StepTooSmall, "step"}}) {
    const UniformAxis axis = make_uniform_axis(b.start, b.stop, b.step);
    EXPECT_EQ(axis.problem, b.problem) << b.start << " " << b.stop << " " << b.step;
    EXPECT_EQ(axis.part, b.part);
    EXPECT_TRUE(axis.values.empty());
    EXPECT_FALSE(axis.message.empty());
  }
  EXPECT_EQ(make_uniform_axis(0, 10, 1, 10).problem, AxisProblem::TooManyPoints);  // 11 points, limit 10
  EXPECT_TRUE(make_uniform_axis(0, 9, 1, 10).ok());
}
