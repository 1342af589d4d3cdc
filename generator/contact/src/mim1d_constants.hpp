// SPDX-License-Identifier: Apache-2.0
#pragma once
// Numerical settings of the MIM-1D solver (mim1d.hpp), shared by its source files; private to the contact library.
#include <chrono>
#include <cstdint>
#include <numbers>

namespace ctab::gen::mim1d_detail {

inline constexpr double kPi = std::numbers::pi;
// Relative step and residual below which strips outside the set are checked for interpenetration (Eq. 4): early
// enough that admissions do not wait for full convergence, late enough that the deformation is nearly right.
inline constexpr double kAdmissionCheckLevel = 1.0e-3;
// Admitted strip's starting load (admit_strip): a quarter of its neighbour's, at least 1e-12 N, refined by
// kAdmissionNewtonSteps Newton steps on its own self term, each step kept within [1/20, 4] x the load so that a
// step on the curved self term cannot overshoot to a non-positive or runaway load.
inline constexpr double kAdmissionStartFraction = 0.25;
inline constexpr double kAdmissionMinimumLoad_N = 1e-12;
inline constexpr int kAdmissionNewtonSteps = 8;
inline constexpr double kAdmissionStepFloor = 0.05;
inline constexpr double kAdmissionStepCeiling = 4.0;
// CONTACT's limit R_y <= 20 R_x: the Hertz start uses B >= A/20 (README, "bottleneck cure").
inline constexpr double kCurvatureRatioLimit = 20.0;
// Start approach beyond first contact when Hertz fails at the deepest strip [m]: 1 um, a shallow interpenetration
// from which the outer iteration grows the approach.
inline constexpr double kFallbackStartApproach_m = 1e-6;
// Outer iteration without contact: the approach beyond first contact doubles, plus 1 nm so that it leaves 0.
inline constexpr double kNoContactGrowth = 2.0;
inline constexpr double kNoContactNudge_m = 1e-9;
// Warm start along dN/d(delta): a strip predicted non-positive keeps half its load.
inline constexpr double kWarmStartShrink = 0.5;
// Stall detection (track_progress): a step counts as progress when it lowers the best residual on the current set
// by kProgressFactor; after kStallSteps steps without progress the step is scaled by kDampingFactor, at most down to
// kMinimumDamping (a Newton 2-cycle is caught within 4 steps; 1/16 still converges well inside the iteration
// limit). Full steps return below kFullStepLevel, where Newton is in its quadratic range.
inline constexpr double kProgressFactor = 0.9;
inline constexpr int kStallSteps = 4;
inline constexpr double kDampingFactor = 0.5;
inline constexpr double kMinimumDamping = 1.0 / 16.0;
inline constexpr double kFullStepLevel = 1.0e-6;
// Forward-difference step of the compliances' approach derivative, relative to the depth (fill_approach_column):
// well inside the smooth range of the weights, with a round-off error of ~1e-10 in the rate.
inline constexpr double kComplianceApproachStep = 1.0e-6;
// FNV-1a 64-bit constants (Fowler, Noll, Vo), for the active-set signatures of the cycle detection.
inline constexpr std::uint64_t kFnvOffset = 14695981039346656037ull;
inline constexpr std::uint64_t kFnvPrime = 1099511628211ull;

}  // namespace ctab::gen::mim1d_detail
