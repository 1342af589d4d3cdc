// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The wheel-rail solve's tuning constants (internal to ctab::wheelrail), one line of reason each. The measurements
//! behind the chosen values are in docs/design/wheelrail-solve.md.
#include <cstddef>

namespace ctab::gen::tuning {

// Patch window (docs/method.md "Contact search"): h is sampled while h < kWindowFactor x the expected approach, at
// least kMinimumWindowDepth_m, so that close minima (tread and flange root at dy = 5 mm) share a patch as CONTACT
// combines them. A contact that reaches the window's end multiplies the depth by kWindowGrowth, at most
// kWindowAttempts times.
inline constexpr double kWindowFactor = 2.0;
inline constexpr double kMinimumWindowDepth_m = 50e-6;
inline constexpr double kWindowGrowth = 2.0;
inline constexpr int kWindowAttempts = 4;
inline constexpr int kMaxSamplesPerSide = 4000;     // 0.4 m at the 0.1 mm sample step: beyond any profile
inline constexpr std::size_t kMinPatchSamples = 8;  // a window with fewer samples cannot hold 3 strips

// Newton on the wheel parameter S and on the normal-line intersections: quadratic, 3-5 steps in practice.
inline constexpr int kWheelPointSteps = 20;
inline constexpr double kWheelPointTolerance_m = 1e-13;
inline constexpr int kIntersectionSteps = 30;
inline constexpr double kIntersectionTolerance_m = 1e-14;

// Conformal surface: corrector passes put a surface point midway between rail and wheel on its averaged normal until
// a pass moves it by less than kSurfaceMove_m and turns the normal by less than kSurfaceTurn_rad (round-off of the
// intersections, 1e-14 m), at most kSurfacePasses (the turns contract quadratically: 7e-3, 5e-8, 2e-13 rad).
inline constexpr int kSurfacePasses = 4;
inline constexpr double kSurfaceMove_m = 1e-13;
inline constexpr double kSurfaceTurn_rad = 1e-12;
// Below this last turn the intersections follow the turn to first order instead of a re-intersection along the final
// normal: the second order, n (t theta)^2, stays below 1e-16 m.
inline constexpr double kFirstOrderTurn_rad = 1e-5;
// A pass whose turn would move the point by less than kSurfaceMove_m / kNextMoveMargin on the next pass (first order)
// is the last; the margin covers slopes taken where the last Newton steps evaluated them.
inline constexpr double kNextMoveMargin = 10.0;

// Window sizing only: Hertz at the gap minimum with B >= A / kCurvatureRatioLimit (CONTACT's R_y <= 20 R_x) and a
// cosine floor for steep flanks (cos 87 deg); kFallbackApproach_m when Hertz fails.
inline constexpr double kCurvatureRatioLimit = 20.0;
inline constexpr double kCosineFloor = 0.05;
inline constexpr double kFallbackApproach_m = 1e-4;

// Several patches: their shared vertical approach by the Illinois root finder, to a force tolerance of
// kSharedForceToleranceFactor x the strip solver's.
inline constexpr double kSharedApproachTolerance_m = 1e-15;
inline constexpr double kSharedForceToleranceFactor = 10.0;
inline constexpr int kSharedApproachIterations = 100;

// CONTACT's reference point (interpenetration_centre.hpp): at least kCentreSamples samples over the region (the
// centre moves < 0.1 um from 64 to 1000 samples), refined down to kFinestCentreStep_m; the main patch is re-solved
// until the point moves less than kRecentreTolerance_m, at most kRecentrePasses times (2 in practice).
inline constexpr int kCentreSamples = 64;
inline constexpr double kFinestCentreStep_m = 1e-6;
inline constexpr double kRecentreTolerance_m = 1e-6;
inline constexpr int kRecentrePasses = 4;
// Secant steps on the centre: a measured slope above this is taken as this (a slope near +1 makes the step unbounded).
inline constexpr double kMaxCentreSlope = 0.5;
// The gap passes follow the centre for at most this many passes, then the plane stays (where one region spans tread
// and flange root, following alternates; planar cases settle in 2-4 passes).
inline constexpr int kCentreFollowingPasses = 6;
// A conformal grid that follows the centre moves a pass's warm start to first order while the move stays below this
// share of a strip (the strips keep their index up to half a strip).
inline constexpr double kPredictedGridMove = 0.5;

// Prescribed load (gap_passes.hpp): the gap is re-sampled at the solved vertical approach until it moves by less
// than kGapApproachTolerance_m (1e-5 of a typical 0.1 mm approach) and the vertical load balances to
// kVerticalBalance (warm-started strip solves scatter by about 2e-11), at most kGapPasses passes.
inline constexpr double kGapApproachTolerance_m = 1e-9;
inline constexpr double kVerticalBalance = 1e-10;
inline constexpr int kGapPasses = 60;
// Settled x and the vertical load within this share of its value: x is held and the force alone balanced at that gap
// (x's 1 nm settling puts up to 1e-5 of the load of noise on the conformal flank's vertical load).
inline constexpr double kHoldSamplingWindow = 1e-4;
// A first pass from the Hertz estimate only predicts the next x, so it is solved to this looser relative tolerance:
// the approach to ~1e-11 m, 1 % of kGapApproachTolerance_m, and warm and cold starts still agree to 1e-8.
inline constexpr double kPredictorTolerance = 1e-7;
// A later pass stops at kPredictorTolerance while its approach lies more than this many kGapApproachTolerance_m off
// its sampling approach (it cannot settle there).
inline constexpr double kEarlyStopWindow = 2.0;
// Factor on the sampling approach where the secant step predicts x <= 0: halving.
inline constexpr double kSamplingApproachCut = 0.5;
// Failed strip solves after a successful pass, each retried halfway back towards it.
inline constexpr int kStripSolveRetries = 4;
// Slope d dz / d x of the solved approach on the sampling approach, clamped to [kMinGapSlope, kMaxGapSlope] (beyond
// them it is noise; -2 is measured where a plane on the flank lies over the flange root).
inline constexpr double kMinGapSlope = -20.0;
inline constexpr double kMaxGapSlope = 0.8;

}  // namespace ctab::gen::tuning
