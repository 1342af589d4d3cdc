// SPDX-License-Identifier: Apache-2.0
// Google Benchmark: MIM-1D on the paper's Hertz case with prescribed load (963 kN) at strip widths
// 0.2, 0.08 and 0.04 mm (paper Table 1). Setup (strip grid, kernel table) stays outside the timed loop.
#include <benchmark/benchmark.h>

#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/fixtures/paper_cases.hpp"

namespace {

void BM_Mim1dHertzPrescribedLoad(benchmark::State& state) {
  ctab::gen::Mim1dOptions options;
  options.strip_width_m = static_cast<double>(state.range(0)) * 1e-6;
  ctab::gen::Mim1dSolver solver(ctab::gen::paper::hertz_sphere_gap(),
                                ctab::gen::effective_modulus(ctab::gen::kSteel, ctab::gen::kSteel), options);
  int iterations = 0;
  for (auto _ : state) {
    const auto solution = solver.solve_for_load(963e3);
    iterations = solution.iterations;
    benchmark::DoNotOptimize(solution.approach_m);
  }
  state.counters["newton_iterations"] = iterations;
}

void BM_Mim1dNonHertzPrescribedApproach(benchmark::State& state) {
  ctab::gen::Mim1dSolver solver(ctab::gen::paper::nonhertz_gap(),
                                ctab::gen::effective_modulus(ctab::gen::kSteel, ctab::gen::kSteel), {});
  for (auto _ : state) benchmark::DoNotOptimize(solver.solve_for_approach(1e-3).normal_load_N);
}

}  // namespace

BENCHMARK(BM_Mim1dHertzPrescribedLoad)->Arg(200)->Arg(80)->Arg(40)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Mim1dNonHertzPrescribedApproach)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
