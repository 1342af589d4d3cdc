// SPDX-License-Identifier: Apache-2.0
// Google Benchmark: bem2d solve time against grid size, the whole solve (grid, coefficient FFT, constrained CG,
// result) timed. Hertz sphere R = 40 mm, prescribed load 963 kN, elements 0.2 ... 0.04 mm (argument in um), and
// the FFT product alone. Run with --benchmark_repetitions=5 for min/median.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "ctab/contact/bem2d.hpp"
#include "ctab/contact/bem2d_convolution.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/fixtures/paper_cases.hpp"

namespace {

const double kEStar = ctab::gen::effective_modulus(ctab::gen::kSteel, ctab::gen::kSteel);

void BM_Bem2dHertzPrescribedLoad(benchmark::State& state) {
  ctab::gen::Bem2dGrid grid;
  grid.dx_m = grid.dy_m = static_cast<double>(state.range(0)) * 1e-6;
  const auto gap = ctab::gen::paper::hertz_sphere_gap();
  ctab::gen::Bem2dPressureField field;
  int iterations = 0;
  for (auto _ : state) {
    const auto solution = ctab::gen::solve_bem2d_for_load(gap, kEStar, grid, 963e3, &field);
    iterations = solution.iterations;
    benchmark::DoNotOptimize(solution.approach_m);
  }
  state.counters["cg_iterations"] = iterations;
  state.counters["elements"] = static_cast<double>(field.nx * field.ny);
}

void BM_Bem2dFftProduct(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  ctab::gen::InfluenceConvolution product(n, n, 1e-4, 1e-4, kEStar);
  std::vector<double> p(n * n, 1e9), u;
  for (auto _ : state) {
    product.apply(p, u);
    benchmark::DoNotOptimize(u.data());
  }
}

double minimum(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

}  // namespace

BENCHMARK(BM_Bem2dHertzPrescribedLoad)
    ->Arg(200)
    ->Arg(100)
    ->Arg(80)
    ->Arg(40)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min", minimum);
BENCHMARK(BM_Bem2dFftProduct)
    ->Arg(64)
    ->Arg(128)
    ->Arg(256)
    ->Arg(512)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("min", minimum);
BENCHMARK_MAIN();
