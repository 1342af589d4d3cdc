// SPDX-License-Identifier: Apache-2.0
// Noise-aware smoothing of point profiles (issue 8, "No lost patches"): the noise estimate of point_noise.hpp on
// synthetic noise of known sigma, the automatic choice (smoothing_spline.hpp), the adaptive smoother
// (adaptive_smoothing.hpp) and their effect on the contact: S1002 and UIC60 1:40 sampled every 0.1 mm along the
// profile, Gaussian noise in z (fixed seeds), single wheel at 78.5 kN, 0.2 mm strips, dy -6 ... +8 mm. Set
// CTAB_NOISE_REPORT=1 to print the table of the README (CTAB_NOISE_SIGMAS_UM=2,5 and CTAB_NOISE_LENGTHS_MM=3.5,8 choose
// the rows, CTAB_NOISE_SEEDS=10 the seeds 1..10, CTAB_NOISE_DETAIL=1 prints every case).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_run.hpp"
#include "ctab/core/error.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/profiles/adaptive_smoothing.hpp"
#include "ctab/profiles/builtin_profiles.hpp"
#include "ctab/profiles/point_noise.hpp"
#include "ctab/profiles/sampled_points.hpp"
#include "ctab/profiles/smoothing_spline.hpp"
#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "ctab/wheelrail/wheelrail_geometry.hpp"
#include "test_support.hpp"

namespace ctab::gen {
namespace {

constexpr double kPointStep_m = 0.1e-3;  // profilometer point spacing [m]
constexpr double kForce_N = 78.5e3;      // single wheel, normal force
constexpr double kStripWidth_m = 0.2e-3;

ProfileTable exact_wheel() { return ProfileTable(*s1002_curve(), kProfileTableStep_m, "S1002"); }
ProfileTable exact_rail() { return ProfileTable(*uic60_inclined_curve(1.0 / 40.0), kProfileTableStep_m, "UIC60"); }

SampledPoints noisy_points(const ProfileTable& exact, double sigma_m, unsigned seed, double step_m = kPointStep_m) {
  SeededNoise noise(SeededNoise::Shape::Gaussian, sigma_m, seed);
  return sample_points(exact, step_m, PointSpacing::ArcLength,
                       [&](double y) { return sigma_m > 0.0 ? noise(y) : 0.0; });
}

// The profile table of points smoothed by the cubic spline of length L [m], or the automatic choice with `prior` for
// L < 0 (`shortest_m`: the shortest local length it used).
ProfileTable smoothed(const SampledPoints& points, double smoothing_length_m, SmoothingChoice* chosen = nullptr,
                      double* shortest_m = nullptr, CurvaturePrior prior = CurvaturePrior::Smooth) {
  SmoothingChoice choice{smoothing_length_m, 0.0, false};
  if (smoothing_length_m < 0.0) choice = choose_smoothing(points.y_m, points.z_m);
  choice.prior = prior;
  if (chosen) *chosen = choice;
  const SmoothedPointCurve smoothed = smooth_point_profile(points.y_m, points.z_m, choice);
  if (shortest_m) *shortest_m = smoothed.shortest_length_m;
  if (chosen) chosen->length_m = smoothed.length_m;  // the length used
  return ProfileTable(*smoothed.curve, kProfileTableStep_m, "points");
}

struct Result {
  bool usable = false;  // a success status: converged or under-resolved (usable, flagged)
  SolveStatus status = SolveStatus::InvalidInput;
  int patches = 0;
  double area_m2 = 0.0, max_pressure_Pa = 0.0;
};

Result solve(const ProfileTable& wheel, const ProfileTable& rail, double dy_m) {
  const SideGeometry side(wheel, rail, TrackSetup{});
  WheelRailOptions options;
  options.mim1d.strip_width_m = kStripWidth_m;
  const WheelContact c =
      solve_wheel_contact(side, dy_m, 0.0, effective_modulus(kSteel, kSteel), LoadKind::NormalForce, kForce_N, options);
  Result r;
  r.usable = is_success(c.status);
  r.status = c.status;
  for (const ContactPatch& p : c.patches) {
    if (!(p.normal_force_N > 0.0)) continue;
    ++r.patches;
    r.area_m2 += p.area_m2;
    r.max_pressure_Pa = std::max(r.max_pressure_Pa, p.max_pressure_Pa);
  }
  return r;
}

std::vector<double> shifts_m() {
  std::vector<double> dy;
  for (int k = -6; k <= 8; ++k) dy.push_back(k * 1e-3);
  return dy;
}

// Worst deviations of a noisy profile's results from the clean profile's over the shifts.
struct Deviation {
  int patch_mismatches = 0, failures = 0;
  double area = 0.0, pressure = 0.0;  // worst relative |noisy/clean - 1|
  double length_m = 0.0, shortest_length_m = 0.0, sigma_m = 0.0;
};

enum class Body { Wheel, Rail };

Deviation deviation(Body body, double sigma_m, unsigned seed, double smoothing_length_m,
                    const std::vector<Result>& clean, CurvaturePrior prior = CurvaturePrior::Smooth) {
  const ProfileTable wheel = exact_wheel(), rail = exact_rail();
  const ProfileTable& noisy_source = body == Body::Wheel ? wheel : rail;
  SmoothingChoice choice;
  double shortest_m = 0.0;
  const ProfileTable noisy =
      smoothed(noisy_points(noisy_source, sigma_m, seed), smoothing_length_m, &choice, &shortest_m, prior);
  const ProfileTable clean_other = smoothed(noisy_points(body == Body::Wheel ? rail : wheel, 0.0, 0), 1e-3);
  Deviation d;
  d.length_m = choice.length_m;
  d.shortest_length_m = shortest_m;
  d.sigma_m = choice.noise_sigma_m;
  const auto dy = shifts_m();
  for (std::size_t k = 0; k < dy.size(); ++k) {
    const Result r = body == Body::Wheel ? solve(noisy, clean_other, dy[k]) : solve(clean_other, noisy, dy[k]);
    if (std::getenv("CTAB_NOISE_DETAIL"))
      std::printf("  dy %+5.1f mm L %.2f mm: %s/%s patches %d/%d area %+6.1f %% pmax %+6.1f %%\n", dy[k] * 1e3,
                  choice.length_m * 1e3, status_name(r.status), status_name(clean[k].status), r.patches,
                  clean[k].patches, 100 * (r.area_m2 / clean[k].area_m2 - 1),
                  100 * (r.max_pressure_Pa / clean[k].max_pressure_Pa - 1));
    if (!r.usable) ++d.failures;
    if (r.patches != clean[k].patches) ++d.patch_mismatches;
    d.area = std::max(d.area, std::abs(r.area_m2 / clean[k].area_m2 - 1.0));
    d.pressure = std::max(d.pressure, std::abs(r.max_pressure_Pa / clean[k].max_pressure_Pa - 1.0));
  }
  return d;
}

// The clean sampled profiles (both smoothed as today, L = 1 mm) over the shifts.
std::vector<Result> clean_results() {
  const ProfileTable wheel = smoothed(noisy_points(exact_wheel(), 0.0, 0), 1e-3);
  const ProfileTable rail = smoothed(noisy_points(exact_rail(), 0.0, 0), 1e-3);
  std::vector<Result> results;
  for (const double dy : shifts_m()) results.push_back(solve(wheel, rail, dy));
  return results;
}

// ---- the noise estimate ----

TEST(PointNoise, EstimatesKnownGaussianNoiseOnWheelAndRail) {
  for (const auto& exact : {exact_wheel(), exact_rail()})
    // at 0.5 mm the profile's own curvature changes start to count (third differences grow as h^3)
    for (const auto& [step, tolerance] : {std::pair{0.1e-3, 0.12}, std::pair{0.5e-3, 0.25}})
      for (const double sigma : {1e-6, 2e-6, 5e-6, 10e-6})
        for (const unsigned seed : {1u, 2u, 3u}) {
          const SampledPoints p = noisy_points(exact, sigma, seed, step);
          // normal noise on the running surface: z-noise times the cosine of the slope, about 1
          EXPECT_NEAR(estimate_point_noise_m(p.y_m, p.z_m), sigma, tolerance * sigma)
              << exact.name() << " step " << step << " sigma " << sigma << " seed " << seed;
        }
}

TEST(PointNoise, ExactDataGiveNoNoise) {
  for (const auto& exact : {exact_wheel(), exact_rail()})
    for (const double step : {0.1e-3, 0.5e-3}) {
      const SampledPoints p = noisy_points(exact, 0.0, 0, step);
      EXPECT_LT(estimate_point_noise_m(p.y_m, p.z_m), 0.05e-6) << exact.name() << " step " << step;
    }
}

TEST(PointNoise, RejectsTooFewPoints) {
  EXPECT_THROW((void)estimate_point_noise_m({0.0, 1.0, 2.0}, {0.0, 0.0, 0.0}), std::invalid_argument);
}

// ---- the automatic smoothing length ----

TEST(AutoSmoothing, CleanProfilesKeepTheDefaultExactly) {
  for (const auto& exact : {exact_wheel(), exact_rail()}) {
    const SampledPoints p = noisy_points(exact, 0.0, 0);
    const SmoothingChoice choice = choose_smoothing(p.y_m, p.z_m);
    EXPECT_EQ(choice.length_m, kDefaultSmoothingLength_m) << exact.name();
    EXPECT_EQ(smoothed(p, -1.0).z_samples(), smoothed(p, kDefaultSmoothingLength_m).z_samples()) << exact.name();
  }
}

TEST(AdaptiveSmoothing, CurvatureNoiseMatchesMonteCarlo) {
  // Pure noise on a straight line: the smoothed curve's second derivative is the noise's curvature; Huber's
  // threshold (10 standard deviations) leaves the penalty whole.
  constexpr double sigma = 5e-6, h = 0.1e-3;
  for (const double length : {4e-3, 8e-3}) {
    double sum2 = 0.0;
    int count = 0;
    for (const unsigned seed : {1u, 2u, 3u, 4u}) {
      SeededNoise noise(SeededNoise::Shape::Gaussian, sigma, seed);
      std::vector<double> y, z;
      for (int i = 0; i < 4000; ++i) {
        y.push_back(i * h);
        z.push_back(noise(0.0));
      }
      const AdaptivelySmoothedPoints points = smooth_adaptively(y, z, length, sigma);
      EXPECT_GT(points.shortest_length_m, 0.9 * length);
      const SmoothingSplineCurve curve(points.y_m, points.z_m, 0.0);
      for (double t = 0.1 * curve.t_end(); t < 0.9 * curve.t_end(); t += h) {
        sum2 += std::pow(curve.at(t).d2z, 2);
        ++count;
      }
    }
    const double predicted = adaptive_curvature_noise_per_m(sigma, h, length);
    EXPECT_NEAR(std::sqrt(sum2 / count), predicted, 0.1 * predicted) << length;
    EXPECT_NEAR(adaptive_length_for_curvature_noise_m(sigma, h, predicted), length, 1e-12);
  }
}

TEST(AdaptiveSmoothing, RejectsWhatItCannotSmooth) {
  const std::vector<double> few(5, 0.0);
  EXPECT_THROW((void)smooth_adaptively(few, few, 1e-3, 1e-6), std::invalid_argument);
  const SampledPoints p = noisy_points(exact_rail(), 0.0, 0u);
  EXPECT_THROW((void)smooth_adaptively(p.y_m, p.z_m, 0.0, 1e-6), std::invalid_argument);
  EXPECT_THROW((void)smooth_adaptively(p.y_m, p.z_m, 1e-3, 0.0), std::invalid_argument);
}

TEST(AutoSmoothing, LengthGrowsWithTheNoise) {
  double previous = kDefaultSmoothingLength_m;
  for (const double sigma : {2e-6, 5e-6, 10e-6}) {
    const SampledPoints p = noisy_points(exact_wheel(), sigma, 3u);
    const SmoothingChoice choice = choose_smoothing(p.y_m, p.z_m);
    EXPECT_TRUE(choice.adaptive) << sigma;
    EXPECT_GT(choice.length_m, previous) << sigma;
    previous = choice.length_m;
    if (sigma == 5e-6) {
      EXPECT_NEAR(choice.length_m, 10.6e-3, 0.4e-3);
    }
    if (sigma == 10e-6) {
      EXPECT_EQ(choice.length_m, kMaxAutoSmoothingLength_m);
    }
  }
  const SampledPoints clean = noisy_points(exact_wheel(), 0.0, 0u);
  EXPECT_FALSE(choose_smoothing(clean.y_m, clean.z_m).adaptive);
}

// The largest curvature error [1/m] of a smoothed rail against 60E1's over the running surface (rail y -30 ... +15
// mm), away (1 mm) from the jumps of its curvature (the R300/R80 junctions).
double crown_curvature_error(const ProfileTable& smoothed_rail) {
  constexpr double away = 1e-3;
  const ProfileTable exact = exact_rail();
  double worst = 0.0;
  for (double y = -30e-3; y <= 15e-3; y += 0.1e-3) {
    const double kappa = exact.at(y).curvature();
    if (std::abs(exact.at(y - away).curvature() - kappa) > 0.01 ||
        std::abs(exact.at(y + away).curvature() - kappa) > 0.01)
      continue;
    worst = std::max(worst, std::abs(smoothed_rail.at(y).curvature() - kappa));
  }
  return worst;
}

// The rail's head is arcs (R300 on the crown, R80, R13). Where its curvature jumps, the adaptive penalty gives way:
// 1 mm from the R300/R80 junctions the arcs keep their curvature within 0.9 1/m on clean points and 1.0-1.3 1/m
// with 5 um noise, where the cubic spline of the same length spreads the jump over its length (2.7-2.9 1/m) and the
// cubic spline of 3 mm (the earlier automatic choice's length near jumps) keeps the noise (7.0-8.3 1/m).
TEST(AdaptiveSmoothing, KeepsTheRailsArcsNearTheirJunctions) {
  const SampledPoints clean = noisy_points(exact_rail(), 0.0, 0u);
  const double length = adaptive_length_for_curvature_noise_m(5e-6, kPointStep_m, kCurvatureNoise_per_m);
  const AdaptivelySmoothedPoints adaptive = smooth_adaptively(clean.y_m, clean.z_m, length, 5e-6);
  const double adaptive_error = crown_curvature_error(
      ProfileTable(SmoothingSplineCurve(adaptive.y_m, adaptive.z_m, 0.0), kProfileTableStep_m, "adaptive"));
  const double cubic_error = crown_curvature_error(smoothed(clean, length));
  EXPECT_LT(adaptive_error, 1.0);
  EXPECT_GT(cubic_error, 2.5 * adaptive_error);
  for (const unsigned seed : {1u, 2u, 3u}) {
    const SampledPoints noisy = noisy_points(exact_rail(), 5e-6, seed);
    const double noisy_error = crown_curvature_error(smoothed(noisy, -1.0));
    EXPECT_LT(noisy_error, 1.5) << seed;
    EXPECT_GT(crown_curvature_error(smoothed(noisy, length)), 2.0 * noisy_error) << seed;
    EXPECT_GT(crown_curvature_error(smoothed(noisy, 3e-3)), 4.0 * noisy_error) << seed;
  }
}

// 60E1 1:40's head: R300 on the crown, R80, R13 and the 1:20 flanks; the rail frame's junctions (rotated and
// re-origined as uic60_inclined_curve, from EN 13674-1's half-widths 10.228 and 26.027 mm) [m].
const std::vector<double> kRailJunctions_m{-43.129e-3, -33.458e-3, -17.718e-3, 2.732e-3, 18.578e-3, 28.848e-3};

// The arcs prior finds 60E1's six junctions and no others on points with 2-10 um noise, each within 0.1 mm at 2 and 5
// um (seeds 1-3: 0.08 mm at worst) and 0.25 mm at 10 um (0.18 mm); the smooth prior places none.
TEST(AdaptiveSmoothing, ArcsPriorFindsTheRailsJunctions) {
  for (const double sigma : {2e-6, 5e-6, 10e-6})
    for (const unsigned seed : {1u, 2u, 3u}) {
      const SampledPoints noisy = noisy_points(exact_rail(), sigma, seed);
      const SmoothingChoice choice = choose_smoothing(noisy.y_m, noisy.z_m);
      const AdaptivelySmoothedPoints arcs =
          smooth_adaptively(noisy.y_m, noisy.z_m, choice.length_m, choice.noise_sigma_m, CurvaturePrior::Arcs);
      ASSERT_EQ(arcs.junction_y_m.size(), kRailJunctions_m.size()) << sigma << " seed " << seed;
      for (std::size_t k = 0; k < kRailJunctions_m.size(); ++k)
        EXPECT_NEAR(arcs.junction_y_m[k], kRailJunctions_m[k], sigma > 5e-6 ? 0.25e-3 : 0.1e-3)
            << sigma << " seed " << seed << " #" << k;
      EXPECT_TRUE(smooth_adaptively(noisy.y_m, noisy.z_m, choice.length_m, choice.noise_sigma_m).junction_y_m.empty());
    }
}

// The same six at 5 um on points every 0.025, 0.05 and 0.2 mm, within 0.15 mm (seeds 1-3: 0.101 mm at worst). In the
// points' own summed chords the densest sampling found a seventh and eighth junction inside the R13 arcs (the chords
// grow with the noise where the profile is steep); the partition runs in arc length along the smooth fit.
TEST(AdaptiveSmoothing, ArcsPriorFindsTheRailsJunctionsAtAnySpacing) {
  for (const double step : {0.025e-3, 0.05e-3, 0.2e-3})
    for (const unsigned seed : {1u, 2u, 3u}) {
      const SampledPoints noisy = noisy_points(exact_rail(), 5e-6, seed, step);
      const SmoothingChoice choice = choose_smoothing(noisy.y_m, noisy.z_m);
      const AdaptivelySmoothedPoints arcs =
          smooth_adaptively(noisy.y_m, noisy.z_m, choice.length_m, choice.noise_sigma_m, CurvaturePrior::Arcs);
      ASSERT_EQ(arcs.junction_y_m.size(), kRailJunctions_m.size()) << step << " seed " << seed;
      for (std::size_t k = 0; k < kRailJunctions_m.size(); ++k)
        EXPECT_NEAR(arcs.junction_y_m[k], kRailJunctions_m[k], 0.15e-3) << step << " seed " << seed << " #" << k;
    }
}

// With the junctions free and the arcs' own penalty the crown keeps its curvature 1 mm from the R300/R80 junctions
// within 0.35 1/m (5 um, seeds 1-3: 0.24-0.28 1/m), against 1.0-1.3 1/m with the smooth prior.
TEST(AdaptiveSmoothing, ArcsPriorKeepsTheCrownsCurvature) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    const SampledPoints noisy = noisy_points(exact_rail(), 5e-6, seed);
    const double arcs = crown_curvature_error(smoothed(noisy, -1.0, nullptr, nullptr, CurvaturePrior::Arcs));
    const double smooth = crown_curvature_error(smoothed(noisy, -1.0));
    std::printf("seed %u: crown curvature error arcs %.2f 1/m, smooth %.2f 1/m\n", seed, arcs, smooth);
    EXPECT_LT(arcs, 0.35) << seed;
    EXPECT_LT(arcs, 0.5 * smooth) << seed;
  }
}

TEST(AutoSmoothing, ManchesterFilesAreCleanAndKeepTheDefault) {
  CTAB_REQUIRE_SHARED();
  for (const auto& [file, role] : {std::pair{"profiles/MBench_S1002_v3.prw", ProfileRole::Wheel},
                                   std::pair{"profiles/MBench_UIC60_v3.prr", ProfileRole::Rail},
                                   std::pair{"profiles/MBench_UIC60_v3.ban", ProfileRole::Rail}}) {
    ProfileReadOptions options;
    options.inclination = 0.0;
    const ProfilePoints p = read_profile_points(test::shared_path(file), role, options);
    const SmoothingChoice choice = choose_smoothing(p.y_m, p.z_m);
    std::printf("%s: %zu points, noise %.3g um, L %.3g mm\n", file, p.y_m.size(), choice.noise_sigma_m * 1e6,
                choice.length_m * 1e3);
    EXPECT_EQ(choice.length_m, kDefaultSmoothingLength_m) << file;
  }
}

// ---- the contact on noisy profiles ----

// Numbers [mm or um] of an environment variable, "2,4,8", scaled by `unit`, after `first`.
std::vector<double> env_list(const char* name, std::vector<double> first, double unit) {
  std::vector<double> lengths = std::move(first);
  if (const char* extra = std::getenv(name)) {
    std::string text = extra;
    for (std::size_t at = 0; at < text.size();) {
      const std::size_t comma = std::min(text.find(',', at), text.size());
      lengths.push_back(std::stod(text.substr(at, comma - at)) * unit);
      at = comma + 1;
    }
  }
  return lengths;
}

constexpr double kAuto = -1.0, kAutoArcs = -2.0;  // the report's rows besides lengths

void print_report() {
  const auto clean = clean_results();
  std::printf("| body | noise | smoothing | L [mm] (shortest) | sigma est. [um] | patch-count mismatches | failures | "
              "worst area | worst pmax |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const Body body : {Body::Wheel, Body::Rail})
    for (const double sigma : std::getenv("CTAB_NOISE_SIGMAS_UM") ? env_list("CTAB_NOISE_SIGMAS_UM", {}, 1e-6)
                                                                  : std::vector<double>{2e-6, 5e-6, 10e-6})
      for (const double setting : env_list("CTAB_NOISE_LENGTHS_MM", {1e-3, kAuto, kAutoArcs}, 1e-3)) {
        const double length = setting < 0.0 ? -1.0 : setting;
        const CurvaturePrior prior = setting == kAutoArcs ? CurvaturePrior::Arcs : CurvaturePrior::Smooth;
        Deviation worst;
        double l_min = 1e9, l_max = 0.0, j_min = 1e9, j_max = 0.0, s_min = 1e9, s_max = 0.0;
        int cases = 0;
        const auto seeds =
            static_cast<unsigned>(std::getenv("CTAB_NOISE_SEEDS") ? std::atoi(std::getenv("CTAB_NOISE_SEEDS")) : 3);
        for (unsigned seed = 1; seed <= seeds; ++seed) {
          const Deviation d = deviation(body, sigma, seed, length, clean, prior);
          worst.patch_mismatches += d.patch_mismatches;
          worst.failures += d.failures;
          worst.area = std::max(worst.area, d.area);
          worst.pressure = std::max(worst.pressure, d.pressure);
          l_min = std::min(l_min, d.length_m), l_max = std::max(l_max, d.length_m);
          j_min = std::min(j_min, d.shortest_length_m), j_max = std::max(j_max, d.shortest_length_m);
          s_min = std::min(s_min, d.sigma_m), s_max = std::max(s_max, d.sigma_m);
          cases += static_cast<int>(shifts_m().size());
        }
        std::printf(
            "| %s | %g um | %s | %.1f-%.1f (%.1f-%.1f) | %s | %d/%d | %d | %.1f %% | %.1f %% |\n",
            body == Body::Wheel ? "wheel" : "rail", sigma * 1e6,
            length < 0 ? (prior == CurvaturePrior::Arcs ? "auto-arcs" : "auto")
                       : ("L = " + std::to_string(length * 1e3).substr(0, 4) + " mm").c_str(),
            l_min * 1e3, l_max * 1e3, j_min * 1e3, j_max * 1e3,
            length < 0
                ? (std::to_string(s_min * 1e6).substr(0, 4) + "-" + std::to_string(s_max * 1e6).substr(0, 4)).c_str()
                : "-",
            worst.patch_mismatches, cases, worst.failures, 100 * worst.area, 100 * worst.pressure);
        std::fflush(stdout);
      }
}

// Issue 8: 5 um noise gives the clean profile's patch count, area within 5 % and max pressure within 5 %, with the
// smoothing docs/method.md "Curvature and smoothing" gives for the profile: `auto` for S1002 (3 seeds: 2.8 % and 3.1 %),
// `auto-arcs` for 60E1, drawn as arcs (1.3 % and 2.6 %). With `auto` the rail's contacts that straddle the crown's
// R300/R80 junction (dy 0 ... +1 mm) read max pressure within 16 % (14.5 %: the smooth prior spreads that 9.2 1/m
// jump over several millimetres); with `auto-arcs` S1002's polynomial tread is read as arcs (max pressure 30.2 %).
TEST(NoisyContact, FiveMicronsKeepThePatchesAreaAndPressure) {
  const auto clean = clean_results();
  for (const Body body : {Body::Wheel, Body::Rail})
    for (const unsigned seed : {1u, 2u, 3u}) {
      const char* name = body == Body::Wheel ? "wheel" : "rail";
      const CurvaturePrior advised = body == Body::Wheel ? CurvaturePrior::Smooth : CurvaturePrior::Arcs;
      const Deviation d = deviation(body, 5e-6, seed, -1.0, clean, advised);
      EXPECT_EQ(d.patch_mismatches, 0) << name << " seed " << seed;
      EXPECT_EQ(d.failures, 0) << name << " seed " << seed;
      EXPECT_LT(d.area, 0.05) << name << " seed " << seed;
      EXPECT_LT(d.pressure, 0.05) << name << " seed " << seed;
      // the default length alone splits the patches
      EXPECT_GT(deviation(body, 5e-6, seed, kDefaultSmoothingLength_m, clean).patch_mismatches, 5) << name;
    }
  for (const unsigned seed : {1u, 2u, 3u}) {
    const Deviation rail_auto = deviation(Body::Rail, 5e-6, seed, -1.0, clean);
    EXPECT_EQ(rail_auto.patch_mismatches, 0) << seed;
    EXPECT_LT(rail_auto.area, 0.05) << seed;
    EXPECT_LT(rail_auto.pressure, 0.16) << seed;
  }
  // the wrong prior for the profile: S1002's polynomial tread read as arcs, the noise decides where their junctions
  // lie (seeds 1-3: max pressure 30.2 % at worst)
  double wheel_as_arcs = 0.0;
  for (const unsigned seed : {1u, 2u, 3u})
    wheel_as_arcs =
        std::max(wheel_as_arcs, deviation(Body::Wheel, 5e-6, seed, -1.0, clean, CurvaturePrior::Arcs).pressure);
  EXPECT_GT(wheel_as_arcs, 0.15);
}

// ---- the option: config, tables, solve --json ----

std::string config_error(const std::string& text) {
  try {
    (void)parse_table_config(text, "c.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kSmallAxes =
    "[solver]\nmode = \"wheel\"\n[axes]\nlateral_displacement_m = { start = -1e-3, stop = 1e-3, step = 1e-3 }\n"
    "vertical_load_N = 78.5e3\n";

TEST(SmoothingOption, ConfigTakesAutoAutoArcsOrALength) {
  const SmoothingSetting automatic{true, CurvaturePrior::Smooth, kDefaultSmoothingLength_m};
  const SmoothingSetting arcs{true, CurvaturePrior::Arcs, kDefaultSmoothingLength_m};
  const TableConfig defaults = parse_table_config(kSmallAxes, "c.toml");
  EXPECT_EQ(defaults.wheel_smoothing, automatic);
  EXPECT_EQ(defaults.rail_smoothing, automatic);
  const TableConfig both = parse_table_config("[profiles]\nsmoothing_m = \"auto-arcs\"\n" + kSmallAxes, "c.toml");
  EXPECT_EQ(both.wheel_smoothing, arcs);
  EXPECT_EQ(both.rail_smoothing, arcs);
  const TableConfig fixed = parse_table_config("[profiles]\nsmoothing_m = 2e-3\n" + kSmallAxes, "c.toml");
  EXPECT_EQ(fixed.wheel_smoothing, (SmoothingSetting{false, CurvaturePrior::Smooth, 2e-3}));
  EXPECT_EQ(fixed.rail_smoothing, fixed.wheel_smoothing);
  // one body's key overrides smoothing_m for that body, wherever it stands
  const TableConfig rail_arcs =
      parse_table_config("[profiles]\nrail_smoothing_m = \"auto-arcs\"\nsmoothing_m = 3e-3\n" + kSmallAxes, "c.toml");
  EXPECT_EQ(rail_arcs.rail_smoothing, arcs);
  EXPECT_EQ(rail_arcs.wheel_smoothing, (SmoothingSetting{false, CurvaturePrior::Smooth, 3e-3}));
  const TableConfig wheel_fixed = parse_table_config("[profiles]\nwheel_smoothing_m = 0.5e-3\n" + kSmallAxes, "c.toml");
  EXPECT_EQ(wheel_fixed.wheel_smoothing, (SmoothingSetting{false, CurvaturePrior::Smooth, 0.5e-3}));
  EXPECT_EQ(wheel_fixed.rail_smoothing, automatic);
  const std::string expected = "expected \"auto\", \"auto-arcs\" or a smoothing length in [0, 0.1] m";
  EXPECT_EQ(config_error("[profiles]\nsmoothing_m = \"soft\"\n" + kSmallAxes),
            "c.toml:2: 'profiles.smoothing_m': " + expected);
  EXPECT_EQ(config_error("[profiles]\nsmoothing_m = 1\n" + kSmallAxes),
            "c.toml:2: 'profiles.smoothing_m': " + expected);
  EXPECT_EQ(config_error("[profiles]\nwheel = \"S1002\"\nrail_smoothing_m = \"arcs\"\n" + kSmallAxes),
            "c.toml:3: 'profiles.rail_smoothing_m': " + expected);
}

// An exact profile with 5 um noise as a 2-column file (mm).
std::string noisy_profile_file(const ProfileTable& exact, const std::string& name) {
  const SampledPoints p = noisy_points(exact, 5e-6, 11u);
  std::ostringstream text;
  text.precision(10);
  for (std::size_t i = 0; i < p.y_m.size(); ++i) text << p.y_m[i] * 1e3 << ' ' << p.z_m[i] * 1e3 << '\n';
  return test::write_temp(name, text.str());
}
std::string noisy_wheel_file() { return noisy_profile_file(exact_wheel(), "noisy_s1002.txt"); }
std::string noisy_rail_file() { return noisy_profile_file(exact_rail(), "noisy_60e1.txt"); }  // inclined already

TEST(SmoothingOption, TablesRecordTheChosenLengthAndNoise) {
  const std::string file = noisy_wheel_file();
  const TableConfig c = parse_table_config("[profiles]\nwheel = \"" + file + "\"\n" + kSmallAxes, "c.toml");
  const tables::Table t = generate_table(c, GeneratorInfo{});
  EXPECT_EQ(t.text_attributes.at("smoothing"), "auto");
  ASSERT_TRUE(t.number_attributes.count("wheel_smoothing_m"));
  EXPECT_NEAR(t.number_attributes.at("wheel_smoothing_m"), 10.6e-3, 0.4e-3);
  // the shortest local length: at S1002's flange-root jumps the adaptive penalty gives way
  EXPECT_NEAR(t.number_attributes.at("wheel_smoothing_near_jumps_m"), 4.6e-3, 0.3e-3);
  EXPECT_NEAR(t.number_attributes.at("wheel_noise_sigma_m"), 5e-6, 0.6e-6);
  EXPECT_FALSE(t.number_attributes.count("rail_smoothing_m"));  // built-in UIC60: analytic, not smoothed
  const TableConfig fixed =
      parse_table_config("[profiles]\nwheel = \"" + file + "\"\nsmoothing_m = 1e-3\n" + kSmallAxes, "c.toml");
  const tables::Table f = generate_table(fixed, GeneratorInfo{});
  EXPECT_EQ(f.text_attributes.at("smoothing"), "0.001 m");
  EXPECT_EQ(f.number_attributes.at("wheel_smoothing_m"), 1e-3);
  EXPECT_EQ(f.number_attributes.at("wheel_smoothing_near_jumps_m"), 1e-3);
  EXPECT_EQ(f.number_attributes.at("wheel_noise_sigma_m"), t.number_attributes.at("wheel_noise_sigma_m"));
  EXPECT_FALSE(f.number_attributes.count("wheel_arc_junctions"));  // the arcs prior only
}

TEST(SmoothingOption, TablesRecordEachBodysSettingAndTheArcJunctions) {
  const std::string wheel = noisy_wheel_file(), rail = noisy_rail_file();
  const TableConfig c =
      parse_table_config("[profiles]\nwheel = \"" + wheel + "\"\nrail = \"" + rail +
                             "\"\ninclination = \"0\"\nrail_smoothing_m = \"auto-arcs\"\n" + kSmallAxes,
                         "c.toml");
  const tables::Table t = generate_table(c, GeneratorInfo{});
  EXPECT_EQ(t.text_attributes.at("smoothing"), "wheel auto, rail auto-arcs");
  EXPECT_EQ(t.number_attributes.at("rail_arc_junctions"), 6.0);
  EXPECT_FALSE(t.number_attributes.count("wheel_arc_junctions"));
  // between the junctions the arcs prior smooths with 1.5 times auto's length (kArcLengthFactor)
  EXPECT_NEAR(t.number_attributes.at("rail_smoothing_m"), kArcLengthFactor * 10.6e-3, 0.6e-3);
}

TEST(SmoothingOption, SolveJsonReportsTheSmoothing) {
  const std::string file = noisy_wheel_file();
  const std::string solve = "solve --mode wheel --dy 0 --vertical-load 78500 --json --wheel " + file;
  const test::CtabRun automatic = test::run_ctab(solve);
  ASSERT_EQ(automatic.exit_code, 0) << automatic.err;
  const auto json = nlohmann::json::parse(automatic.out);
  EXPECT_TRUE(json.at("wheel_profile_smoothing").at("automatic").get<bool>());
  EXPECT_NEAR(json.at("wheel_profile_smoothing").at("length_m").get<double>(), 10.6e-3, 0.4e-3);
  EXPECT_NEAR(json.at("wheel_profile_smoothing").at("length_near_jumps_m").get<double>(), 4.6e-3, 0.3e-3);
  EXPECT_FALSE(json.contains("rail_profile_smoothing"));
  const test::CtabRun fixed = test::run_ctab(solve + " --smoothing 0.002");
  ASSERT_EQ(fixed.exit_code, 0) << fixed.err;
  EXPECT_EQ(nlohmann::json::parse(fixed.out).at("wheel_profile_smoothing").at("length_m").get<double>(), 2e-3);
  const test::CtabRun bad = test::run_ctab(solve + " --smoothing soft");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find(
                "--smoothing: expected \"auto\", \"auto-arcs\" or a smoothing length in [0, 0.05] m, got soft"),
            std::string::npos)
      << bad.err;
  // per body, after --smoothing whatever the order on the command line
  const std::string both = solve + " --rail " + noisy_rail_file() + " --inclination 0";
  const test::CtabRun arcs = test::run_ctab(both + " --rail-smoothing auto-arcs --smoothing 0.002");
  ASSERT_EQ(arcs.exit_code, 0) << arcs.err;
  const auto arcs_json = nlohmann::json::parse(arcs.out);
  EXPECT_EQ(arcs_json.at("rail_profile_smoothing").at("arc_junctions").get<int>(), 6);
  EXPECT_TRUE(arcs_json.at("rail_profile_smoothing").at("automatic").get<bool>());
  EXPECT_EQ(arcs_json.at("wheel_profile_smoothing").at("length_m").get<double>(), 2e-3);
  EXPECT_FALSE(arcs_json.at("wheel_profile_smoothing").contains("arc_junctions"));
  const test::CtabRun wheel_bad = test::run_ctab(solve + " --wheel-smoothing arcs");
  EXPECT_EQ(wheel_bad.exit_code, 2);
  EXPECT_NE(wheel_bad.err.find("--wheel-smoothing: expected"), std::string::npos) << wheel_bad.err;
}

TEST(NoisyContact, Report) {
  if (!std::getenv("CTAB_NOISE_REPORT")) GTEST_SKIP() << "set CTAB_NOISE_REPORT=1 for the README table";
  print_report();
}

}  // namespace
}  // namespace ctab::gen
