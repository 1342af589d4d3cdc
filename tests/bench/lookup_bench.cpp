// SPDX-License-Identifier: Apache-2.0
// Google Benchmark of the lookup query: one wheel (all slots, all quantities) with its prelookup, and two wheels
// sharing one prelookup, linear / PCHIP, double / single precision. The table: CTAB_LOOKUP_BLOB (a blob file,
// e.g. `ctab export build/default_table.h5 -o build/default_table.blob`), else a synthetic table of the default
// table's shape (241 lateral shifts, 3 slots). The *_adaptive cases: the synthetic table on an adaptive axis of 593
// nodes spaced 1 um .. 0.5 mm (test::adaptive_options). Random query points, cycled; time per query of one wheel.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "ctab/lookup/open.hpp"
#include "synthetic_table.hpp"

namespace {

using ctab::lookup::LoadOptions;
using ctab::lookup::Table;

Table load(const LoadOptions& options, bool adaptive = false) {
  Table table;
  const char* blob = std::getenv("CTAB_LOOKUP_BLOB");
  const ctab::lookup::LoadResult result =
      blob && !adaptive ? ctab::lookup::open_blob_file(blob, options, table)
      : adaptive        ? table.load(ctab::lookup::test::make_synthetic(ctab::lookup::test::adaptive_options()), options)
                        : table.load(ctab::lookup::test::make_synthetic({.dy_step_m = 0.1e-3, .strip_samples = 32}), options);
  if (!result.ok()) std::abort();
  return table;
}

//! Random points over the whole dy range (cold: most records come from L2/L3), or within +-0.5 mm of the centre
//! (hot: a few cells, as a wheel in a simulation that moves a little per step).
std::vector<double> random_dy(const Table& table, bool hot = false) {
  std::mt19937_64 random(42);
  const double centre = 0.5 * (table.dy_min() + table.dy_max());
  std::uniform_real_distribution<double> uniform(hot ? centre - 0.5e-3 : table.dy_min(),
                                                 hot ? centre + 0.5e-3 : table.dy_max());
  std::vector<double> dy(1 << 16);
  for (double& v : dy) v = uniform(random);
  return dy;
}

void query_one_wheel(benchmark::State& state, LoadOptions options, bool hot, bool adaptive = false) {
  const Table table = load(options, adaptive);
  const std::vector<double> dy = random_dy(table, hot);
  const double second = table.second_axis().front();
  ctab_result r;
  std::memset(&r, 0, sizeof r);
  ctab_location where;
  std::size_t i = 0;
  for (auto _ : state) {
    table.prelookup(dy[i & 0xffff], second, where);
    table.query(where, static_cast<std::int32_t>(i & 1u), r);
    benchmark::DoNotOptimize(r);
    ++i;
  }
  state.counters["memory_kB"] = static_cast<double>(table.memory_bytes()) / 1024.0;
}

void query_two_wheels(benchmark::State& state, LoadOptions options) {
  const Table table = load(options);
  const std::vector<double> dy = random_dy(table);
  const double second = table.second_axis().front();
  ctab_result right, left;
  std::memset(&right, 0, sizeof right);
  std::memset(&left, 0, sizeof left);
  ctab_location where;
  std::size_t i = 0;
  for (auto _ : state) {
    table.prelookup(dy[i & 0xffff], second, where);
    table.query(where, CTAB_WHEEL_RIGHT, right);
    table.query(where, CTAB_WHEEL_LEFT, left);
    benchmark::DoNotOptimize(right);
    benchmark::DoNotOptimize(left);
    ++i;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 2);  // wheel queries
}

BENCHMARK_CAPTURE(query_one_wheel, linear_double, LoadOptions{CTAB_LINEAR, false}, false);
BENCHMARK_CAPTURE(query_one_wheel, linear_single, LoadOptions{CTAB_LINEAR, true}, false);
BENCHMARK_CAPTURE(query_one_wheel, pchip_double, LoadOptions{CTAB_PCHIP, false}, false);
BENCHMARK_CAPTURE(query_one_wheel, linear_double_hot, LoadOptions{CTAB_LINEAR, false}, true);
BENCHMARK_CAPTURE(query_one_wheel, pchip_double_hot, LoadOptions{CTAB_PCHIP, false}, true);
BENCHMARK_CAPTURE(query_one_wheel, linear_double_adaptive, LoadOptions{CTAB_LINEAR, false}, false, true);
BENCHMARK_CAPTURE(query_one_wheel, linear_single_adaptive, LoadOptions{CTAB_LINEAR, true}, false, true);
BENCHMARK_CAPTURE(query_one_wheel, pchip_double_adaptive, LoadOptions{CTAB_PCHIP, false}, false, true);
BENCHMARK_CAPTURE(query_two_wheels, linear_double, LoadOptions{CTAB_LINEAR, false});
BENCHMARK_CAPTURE(query_two_wheels, pchip_double, LoadOptions{CTAB_PCHIP, false});

}  // namespace

BENCHMARK_MAIN();
