// SPDX-License-Identifier: Apache-2.0
// Google Benchmark: time per case of each rung of the method ladder through solve_normal_contact (strip grid set-up
// included: what one table case costs), on the paper's Hertz sphere (963 kN prescribed) and non-Hertzian case
// (approach 1 mm and 2645 kN prescribed), strips 0.2 mm. Run with --benchmark_repetitions=N for min/median.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "ctab/contact/material.hpp"
#include "ctab/contact/normal_contact.hpp"
#include "ctab/fixtures/paper_cases.hpp"

namespace {

using namespace ctab::gen;

enum Scene { kSphereForce = 0, kNonHertzApproach = 1, kNonHertzForce = 2 };

void BM_MethodLadder(benchmark::State& state) {
  MethodOptions options;
  options.method = static_cast<ContactMethod>(state.range(0));
  options.E_star_Pa = effective_modulus(kSteel, kSteel);
  options.strip_width_m = 0.2e-3;
  const auto scene = static_cast<Scene>(state.range(1));
  const GapProfile gap = scene == kSphereForce ? paper::hertz_sphere_gap() : paper::nonhertz_gap();
  const Loading loading = scene == kSphereForce        ? Loading::normal_force(963e3)
                          : scene == kNonHertzApproach ? Loading::approach(1e-3)
                                                       : Loading::normal_force(2645e3);
  (void)solve_normal_contact(gap, options, loading);  // process-wide tables (Hertz coefficients, strip kernel)
  for (auto _ : state) benchmark::DoNotOptimize(solve_normal_contact(gap, options, loading).normal_load_N);
  state.SetLabel(std::string(method_name(options.method)) + (scene == kSphereForce        ? " sphere F"
                                                             : scene == kNonHertzApproach ? " nonhertz delta"
                                                                                          : " nonhertz F"));
}

double minimum(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

}  // namespace

BENCHMARK(BM_MethodLadder)
    ->ArgsProduct({{static_cast<long>(ContactMethod::Hertz), static_cast<long>(ContactMethod::Kp),
                    static_cast<long>(ContactMethod::Analyn), static_cast<long>(ContactMethod::Mim1d)},
                   {kSphereForce, kNonHertzApproach, kNonHertzForce}})
    ->ComputeStatistics("min", minimum)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
