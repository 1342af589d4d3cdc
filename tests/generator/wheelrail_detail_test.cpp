// SPDX-License-Identifier: Apache-2.0
// Per-case failure reasons (WheelContact::detail, WheelsetPose::detail), the strip cap per patch, and the Hertz
// path that needs no MIM-1D solver. Built-in S1002 on UIC60 1:40, single wheel.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "ctab/core/error.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/contact/strip_grid.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/wheelrail/contact_geometry_sweep.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

using namespace ctab::gen;

namespace {

class WheelRailDetail : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    ProfileReadOptions o;
    o.inclination = 1.0 / 40.0;
    wheel_ = new ProfileTable(load_profile("S1002", ProfileRole::Wheel, o));
    rail_ = new ProfileTable(load_profile("UIC60", ProfileRole::Rail, o));
    side_ = new SideGeometry(*wheel_, *rail_, TrackSetup{});
  }
  static void TearDownTestSuite() {
    delete side_;
    delete rail_;
    delete wheel_;
  }
  static WheelContact solve(double dy_m, LoadKind load, double value, const WheelRailOptions& options = {}) {
    return solve_wheel_contact(*side_, dy_m, 0.0, effective_modulus(kSteel, kSteel), load, value, options);
  }
  static ProfileTable* wheel_;
  static ProfileTable* rail_;
  static SideGeometry* side_;
};
ProfileTable* WheelRailDetail::wheel_ = nullptr;
ProfileTable* WheelRailDetail::rail_ = nullptr;
SideGeometry* WheelRailDetail::side_ = nullptr;

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

}  // namespace

TEST_F(WheelRailDetail, SuccessHasNoDetail) {
  const WheelContact c = solve(2e-3, LoadKind::NormalForce, 78.5e3);
  EXPECT_EQ(c.status, SolveStatus::Converged);
  EXPECT_TRUE(c.detail.empty());
  const WheelContact none = solve(2e-3, LoadKind::NormalForce, 0.0);
  EXPECT_EQ(none.status, SolveStatus::NoContact);
  EXPECT_TRUE(none.detail.empty());
}

TEST_F(WheelRailDetail, InvalidInputSaysWhy) {
  const WheelContact negative = solve(2e-3, LoadKind::Approach, -1e-5);
  EXPECT_EQ(negative.status, SolveStatus::InvalidInput);
  EXPECT_EQ(negative.detail, "negative approach");
  EXPECT_EQ(solve(2e-3, LoadKind::VerticalForce, -1.0).detail, "negative load");
  EXPECT_EQ(solve(std::numeric_limits<double>::quiet_NaN(), LoadKind::NormalForce, 1e3).detail,
            "lateral shift dy is not finite");
  EXPECT_EQ(solve(2e-3, LoadKind::NormalForce, std::numeric_limits<double>::infinity()).detail, "load is not finite");
  const WheelContact off = solve(1.0, LoadKind::NormalForce, 78.5e3);
  EXPECT_EQ(off.status, SolveStatus::InvalidInput);
  EXPECT_TRUE(starts_with(off.detail, "the wheel does not reach the rail at dy = 1 m")) << off.detail;
  EXPECT_NE(off.detail.find("(lateral shift beyond the profiles)"), std::string::npos);
}

TEST_F(WheelRailDetail, StripCapRefusesThePatchBeforeAllocating) {
  WheelRailOptions options;
  options.mim1d.strip_width_m = 1e-6;  // took minutes and 10 GB before the cap
  const WheelContact c = solve(2e-3, LoadKind::NormalForce, 78.5e3, options);
  EXPECT_EQ(c.status, SolveStatus::InvalidInput);
  EXPECT_TRUE(starts_with(c.detail, "patch needs ")) << c.detail;
  EXPECT_NE(c.detail.find(" strips (max 4000): strip width too small"), std::string::npos) << c.detail;
  EXPECT_LT(c.solve_time_s, 1.0);
  EXPECT_TRUE(c.patches.empty());
}

TEST_F(WheelRailDetail, HertzPathBuildsNoStripSolver) {
  // At a strip width MIM-1D refuses (the cap), Hertz solves: it never sets up a MIM-1D solver.
  WheelRailOptions options;
  options.method = NormalMethod::Hertz;
  options.mim1d.strip_width_m = 1e-6;
  const WheelContact thin = solve(2e-3, LoadKind::NormalForce, 78.5e3, options);
  ASSERT_EQ(thin.status, SolveStatus::Converged) << thin.detail;
  EXPECT_TRUE(thin.detail.empty());
  options.mim1d.strip_width_m = 0.2e-3;
  const WheelContact normal = solve(2e-3, LoadKind::NormalForce, 78.5e3, options);
  ASSERT_EQ(normal.status, SolveStatus::Converged);
  EXPECT_EQ(thin.normal_force_N, normal.normal_force_N);
  EXPECT_EQ(thin.patches.at(0).area_m2, normal.patches.at(0).area_m2);
}

TEST_F(WheelRailDetail, NonConvergenceNamesIterationsAndPatch) {
  WheelRailOptions options;
  options.mim1d.max_iterations = 1;
  options.mim1d.max_outer_iterations = 1;
  const WheelContact c = solve(2e-3, LoadKind::NormalForce, 78.5e3, options);
  EXPECT_EQ(c.status, SolveStatus::MaxIterations);
  EXPECT_TRUE(starts_with(c.detail, "MIM-1D did not converge in ")) << c.detail;
  EXPECT_NE(c.detail.find(" iterations at patch 1"), std::string::npos) << c.detail;
}

TEST_F(WheelRailDetail, StripGridCapThrowsAtSetUp) {
  GapProfile gap;
  gap.source = "wide.csv";
  for (int i = 0; i <= 100; ++i) {
    const double y = -0.05 + 1e-3 * i;
    gap.y_m.push_back(y);
    gap.h_m.push_back(y * y);
    gap.A_per_m.push_back(1.0);
    gap.B_per_m.push_back(1.0);
  }
  EXPECT_DOUBLE_EQ(strip_count(gap, 1e-3), 100.0);
  EXPECT_GT(strip_count(gap, 1e-9), 1e7);  // counted in double: no overflow, no allocation
  Mim1dOptions options;
  options.strip_width_m = 0.1e-3 / 5.0;  // 5000 strips
  try {
    Mim1dSolver solver(gap, effective_modulus(kSteel, kSteel), options);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_TRUE(starts_with(e.what(), "--strip-width: the gap needs 5000 strips of width ")) << e.what();
    EXPECT_NE(std::string(e.what()).find("(max 4000): increase the strip width"), std::string::npos);
  }
  options.strip_width_m = 0.1e-3 / 4.0;  // 4000 strips: allowed
  EXPECT_NO_THROW(Mim1dSolver(gap, effective_modulus(kSteel, kSteel), options));
}

TEST_F(WheelRailDetail, WheelsetRollFailureSaysWhere) {
  const WheelsetPose ok = rigid_wheelset_pose(*side_, *side_, 5e-3);
  EXPECT_TRUE(ok.converged);
  EXPECT_TRUE(ok.detail.empty());
  const WheelsetPose off = rigid_wheelset_pose(*side_, *side_, 0.5);
  EXPECT_FALSE(off.converged);
  EXPECT_EQ(off.detail,
            "wheelset roll: a wheel does not reach its rail at dy = 0.5 m (lateral shift beyond the profiles)");
  const RigidContactRow row = rigid_contact(*side_, *side_, 0.5, ContactMode::Wheelset);
  EXPECT_FALSE(row.converged);
  EXPECT_EQ(row.detail, off.detail);
  const RigidContactRow single = rigid_contact(*side_, *side_, 0.5, ContactMode::SingleWheel);
  EXPECT_FALSE(single.converged);
  EXPECT_TRUE(starts_with(single.detail, "the right wheel does not reach its rail at dy = 0.5")) << single.detail;
}
