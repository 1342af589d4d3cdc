// SPDX-License-Identifier: Apache-2.0
// `ctab bench lookup FILE`: time per query of one wheel (all slots, all quantities) over random points, with and
// without the prelookup reused for both wheels; median, p99.99, max per repetition; memory per table; the
// largest difference of single-precision storage against double.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bench_progress.hpp"
#include "commands.hpp"
#include "creep_bench.hpp"
#include "ctab/core/error.hpp"
#include "ctab/lookup/hdf5_table.hpp"
#include "isolated_read.hpp"
#include "load_errors.hpp"

namespace ctab::cli {

namespace {

using Clock = std::chrono::steady_clock;

struct Points {
  std::vector<double> dy, second;
};

Points random_points(const lookup::Table& table, std::size_t n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> dy(table.dy_min(), table.dy_max());
  std::uniform_real_distribution<double> second(table.second_axis().front(), table.second_axis().back());
  Points p;
  p.dy.resize(n);
  p.second.resize(n);
  for (std::size_t i = 0; i < n; ++i) p.dy[i] = dy(random), p.second[i] = second(random);
  return p;
}

double ns_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::nano>(b - a).count();
}

//! Median cost of reading the clock twice [ns], subtracted from every single-query time.
double timer_overhead_ns() {
  std::vector<double> t(100000);
  for (double& v : t) {
    const auto a = Clock::now();
    v = ns_between(a, Clock::now());
  }
  std::nth_element(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(t.size() / 2), t.end());
  return t[t.size() / 2];
}

struct Figures {
  double median_ns, p9999_ns, max_ns, mean_batch_ns;
};

double quantile(std::vector<double>& t, double q) {
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(t.size() - 1));
  std::nth_element(t.begin(), t.begin() + k, t.end());
  return t[static_cast<std::size_t>(k)];
}

//! One repetition: per-query times (one wheel, or per wheel with a shared prelookup) and the batch mean.
Figures measure(const lookup::Table& table, const Points& p, bool shared_prelookup, double overhead_ns, double& sink) {
  const std::size_t n = p.dy.size();
  std::vector<double> times(n);
  ctab_result r;
  std::memset(&r, 0, sizeof r);
  ctab_location where;
  for (std::size_t i = 0; i < n; ++i) {
    const auto start = Clock::now();
    table.prelookup(p.dy[i], p.second[i], where);
    table.query(where, static_cast<std::int32_t>(i & 1u), r);
    if (shared_prelookup) table.query(where, static_cast<std::int32_t>(1u - (i & 1u)), r);
    const auto stop = Clock::now();
    sink += r.patch[0].q[CTAB_NORMAL_FORCE_N];
    times[i] = std::max(0.0, ns_between(start, stop) - overhead_ns) / (shared_prelookup ? 2.0 : 1.0);
  }
  const auto start = Clock::now();
  for (std::size_t i = 0; i < n; ++i) {
    table.prelookup(p.dy[i], p.second[i], where);
    table.query(where, static_cast<std::int32_t>(i & 1u), r);
    if (shared_prelookup) table.query(where, static_cast<std::int32_t>(1u - (i & 1u)), r);
    sink += r.patch[0].q[CTAB_NORMAL_FORCE_N];
  }
  const double batch = ns_between(start, Clock::now()) / static_cast<double>(n) / (shared_prelookup ? 2.0 : 1.0);
  Figures f{quantile(times, 0.5), quantile(times, 0.9999), *std::max_element(times.begin(), times.end()), batch};
  return f;
}

void report(const char* label, std::vector<Figures>& runs) {
  const auto stat = [&](double Figures::*field, bool median) {
    std::vector<double> v;
    for (const Figures& f : runs) v.push_back(f.*field);
    std::sort(v.begin(), v.end());
    return median ? v[v.size() / 2] : v.front();
  };
  std::printf(
      "  %-34s median %6.1f (%6.1f) ns  p99.99 %7.1f (%7.1f) ns  max %8.1f (%8.1f) ns  batch mean %6.1f (%6.1f) ns\n",
      label, stat(&Figures::median_ns, false), stat(&Figures::median_ns, true), stat(&Figures::p9999_ns, false),
      stat(&Figures::p9999_ns, true), stat(&Figures::max_ns, false), stat(&Figures::max_ns, true),
      stat(&Figures::mean_batch_ns, false), stat(&Figures::mean_batch_ns, true));
}

//! Largest difference of single-precision storage against double over the points: relative to each quantity's
//! largest magnitude, and relative to the value itself where it exceeds 1e-3 of that magnitude.
void compare_single(const lookup::Table& full, const lookup::Table& single, const Points& p) {
  double scale[CTAB_QUANTITIES] = {}, worst_scaled = 0.0, worst_relative = 0.0;
  std::vector<std::array<double, CTAB_QUANTITIES>> a, b;
  ctab_location where;
  ctab_result ra, rb;
  for (std::size_t i = 0; i < p.dy.size(); ++i) {
    full.prelookup(p.dy[i], p.second[i], where);
    for (std::int32_t wheel = 0; wheel < 2; ++wheel) {
      full.query(where, wheel, ra);
      single.query(where, wheel, rb);
      for (std::int32_t s = 0; s < ra.n_slots; ++s) {
        std::array<double, CTAB_QUANTITIES> va{}, vb{};
        std::copy(std::begin(ra.patch[s].q), std::end(ra.patch[s].q), va.begin());
        std::copy(std::begin(rb.patch[s].q), std::end(rb.patch[s].q), vb.begin());
        for (std::size_t q = 0; q < CTAB_QUANTITIES; ++q) scale[q] = std::max(scale[q], std::fabs(va[q]));
        a.push_back(va);
        b.push_back(vb);
      }
    }
  }
  for (std::size_t k = 0; k < a.size(); ++k)
    for (std::size_t q = 0; q < CTAB_QUANTITIES; ++q) {
      if (scale[q] == 0.0) continue;
      const double d = std::fabs(a[k][q] - b[k][q]);
      worst_scaled = std::max(worst_scaled, d / scale[q]);
      if (std::fabs(a[k][q]) > 1e-3 * scale[q]) worst_relative = std::max(worst_relative, d / std::fabs(a[k][q]));
    }
  std::printf("single vs double precision over %zu points: max |diff| / max|quantity| %.2e, max relative diff %.2e\n",
              p.dy.size(), worst_scaled, worst_relative);
}

int bench_table(const std::string& path, std::size_t queries, int repetitions, bool progress, IsolatedChild& child) {
  lookup::TableData data;
  bool single_blob = false;
  child.reading(path);
  throw_if_failed(lookup::read_any(path, data, single_blob));
  child.trusted_from_here();
  struct Variant {
    const char* label;
    lookup::LoadOptions options;
  };
  const Variant variants[] = {{"linear, double", {CTAB_LINEAR, false}},
                              {"linear, single", {CTAB_LINEAR, true}},
                              {"pchip, double", {CTAB_PCHIP, false}}};
  std::printf("Lookup: %s, %zu x %zu cases x 2 wheels x %zu slots; %zu random queries, %d repetitions\n", path.c_str(),
              data.n_dy(), data.n_second(), data.n_slots, queries, repetitions);
  std::printf("time per wheel query (all slots, all quantities): min over repetitions (median of repetitions)\n");
  const double overhead = timer_overhead_ns();
  double sink = 0.0;
  lookup::Table tables[3];
  BenchProgress runs_done(progress, 3 * 2 * repetitions);
  for (std::size_t v = 0; v < 3; ++v) {
    const lookup::LoadResult loaded = tables[v].load(data, variants[v].options);
    if (!loaded.ok()) throw gen::Error(path + ": " + loaded.message);
    const Points points = random_points(tables[v], queries, 1234);
    for (const bool shared : {false, true}) {
      std::vector<Figures> runs;
      const std::string label = std::string(variants[v].label) + (shared ? ", prelookup for 2 wheels" : ", 1 wheel");
      for (int r = 0; r < repetitions; ++r) {
        runs_done.step(label.c_str());
        runs.push_back(measure(tables[v], points, shared, overhead, sink));
      }
      report(label.c_str(), runs);
    }
    std::printf("  %-34s memory %.1f kB\n", variants[v].label, static_cast<double>(tables[v].memory_bytes()) / 1024.0);
  }
  std::printf("(clock overhead %.1f ns subtracted from single-query times; checksum %g)\n", overhead, sink);
  compare_single(tables[0], tables[1], random_points(tables[0], std::min<std::size_t>(queries, 200000), 99));
  bench_creep(tables[0], std::min<std::size_t>(queries, 100000), overhead);
  return 0;
}

// In a child process (isolated_read.hpp): the file may be an HDF5 table from anywhere.
int run_bench_lookup(const std::string& path, std::size_t queries, int repetitions, bool progress) {
  return run_isolated([&](IsolatedChild& child) { return bench_table(path, queries, repetitions, progress, child); })
      .exit_code;
}

}  // namespace

Command add_bench_lookup_subcommand(CLI::App& bench) {
  auto path = std::make_shared<std::string>();
  auto queries = std::make_shared<std::size_t>(1000000);
  auto repetitions = std::make_shared<int>(5);
  CLI::App* app =
      bench.add_subcommand("lookup", "Time per lookup query (median, p99.99, max), memory, single vs double");
  app->add_option("file", *path, "table (.h5 or blob)")->required();
  app->add_option("--queries", *queries, "random queries per repetition (default 1e6)");
  app->add_option("--repetitions", *repetitions, "repetitions (default 5)");
  auto progress = std::make_shared<bool>(false);
  app->add_flag("--progress", *progress, "a progress line on stderr also when it is not a terminal");
  return {app, [path, queries, repetitions, progress] {
            return run_bench_lookup(*path, *queries, *repetitions, *progress);
          }};
}

}  // namespace ctab::cli
