// SPDX-License-Identifier: Apache-2.0
#include "creep_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "ctab/lookup/creep.hpp"

namespace ctab::cli {

namespace {

using Clock = std::chrono::steady_clock;

double ns_since(Clock::time_point start) { return std::chrono::duration<double, std::nano>(Clock::now() - start).count(); }

double at(std::vector<double>& t, double q) {
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(t.size() - 1));
  std::nth_element(t.begin(), t.begin() + k, t.end());
  return t[static_cast<std::size_t>(k)];
}

// A patch's strips, fetched once so that only the creep call is timed.
struct Sample {
  double s[lookup::kMaxCreepStrips], a[lookup::kMaxCreepStrips], p0[lookup::kMaxCreepStrips];
  std::uint32_t n = 0;
  double force = 0.0, plane = 0.0;
};

std::vector<Sample> patches(const lookup::Table& table, std::size_t count) {
  std::mt19937_64 random(4321);
  std::uniform_real_distribution<double> dy(table.dy_min(), table.dy_max());
  std::uniform_real_distribution<double> second(table.second_axis().front(), table.second_axis().back());
  std::vector<Sample> out;
  ctab_location where;
  ctab_result r;
  for (std::size_t tries = 0; out.size() < count && tries < 20 * count; ++tries) {
    table.prelookup(dy(random), second(random), where);
    table.query(where, 0, r);
    if (!r.patch[0].present) continue;
    Sample& p = out.emplace_back();
    if (table.strip_profile(where, 0, 0, p.s, p.a, p.p0, lookup::kMaxCreepStrips, &p.n) < 0 || p.n < 2) {
      out.pop_back();
      continue;
    }
    p.force = r.patch[0].q[CTAB_NORMAL_FORCE_N];
    p.plane = r.patch[0].q[CTAB_PLANE_ANGLE_RAD];
  }
  return out;
}

void one_patch(const std::vector<Sample>& samples, int method, const char* label, double overhead_ns) {
  std::vector<double> times(samples.size());
  std::mt19937_64 random(99);
  std::uniform_real_distribution<double> creep(-0.01, 0.01);
  double sink = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Sample& p = samples[i];
    const ctab_creep_input input{creep(random), creep(random), 100.0 * creep(random), 0.3, 0.0, 0.0, method, 0};
    const lookup::StripPatch patch{p.s, p.a, p.p0, p.n, p.force, p.plane};
    ctab_creep_patch out;
    const auto start = Clock::now();
    (void)lookup::creep_patch(patch, input, out);
    times[i] = std::max(0.0, ns_since(start) - overhead_ns);
    sink += out.fx_N;
  }
  const double median = at(times, 0.5), p99 = at(times, 0.99), p9999 = at(times, 0.9999);
  const double worst = *std::max_element(times.begin(), times.end());
  std::printf("  creep, one patch, %-22s median %7.1f ns  p99 %7.1f ns  p99.99 %8.1f ns  max %9.1f ns  (%zu patches, "
              "%u strips; %g)\n",
              label, median, p99, p9999, worst, samples.size(), samples.empty() ? 0u : samples[0].n, sink * 0.0);
}

void hil_step(const lookup::Table& table, std::size_t steps, double overhead_ns) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> dy(table.dy_min(), table.dy_max());
  std::uniform_real_distribution<double> second(table.second_axis().front(), table.second_axis().back());
  std::uniform_real_distribution<double> creep(-0.005, 0.005);
  std::vector<double> times(steps);
  ctab_location where;
  ctab_result normal;
  ctab_creep_result forces;
  double sink = 0.0;
  for (std::size_t i = 0; i < steps; ++i) {
    double dys[4], seconds[4];
    for (int w = 0; w < 4; ++w) dys[w] = dy(random), seconds[w] = second(random);
    const ctab_creep_input input{creep(random), creep(random), 100.0 * creep(random), 0.3, 0.0, 0.0,
                                 CTAB_CREEP_STRIPS_CARTER, 0};
    const auto start = Clock::now();
    for (int w = 0; w < 4; ++w) {
      table.prelookup(dys[w], seconds[w], where);
      for (std::int32_t wheel = 0; wheel < 2; ++wheel) {
        table.query(where, wheel, normal);
        (void)lookup::creep_query(table, where, wheel, input, forces);
        sink += normal.patch[0].q[0] + forces.fx_N;
      }
    }
    times[i] = std::max(0.0, ns_since(start) - overhead_ns);
  }
  double mean = 0.0;
  for (const double t : times) mean += t / static_cast<double>(steps);
  std::printf("  HIL step, 8 wheels (normal query + creep, Carter strips): mean %.2f us  worst %.2f us  p99.99 %.2f us "
              "(%zu steps; %g)\n",
              mean * 1e-3, *std::max_element(times.begin(), times.end()) * 1e-3, at(times, 0.9999) * 1e-3, steps,
              sink * 0.0);
}

}  // namespace

void bench_creep(const lookup::Table& table, std::size_t points, double overhead_ns) {
  if (table.strip_samples() < 2 || table.strip_samples() > lookup::kMaxCreepStrips) {
    std::printf("creep: no strip profiles in this table (or more than %u samples)\n", lookup::kMaxCreepStrips);
    return;
  }
  std::printf("creep forces (random xi, eta in +-0.01, phi in +-1 1/m, mu 0.3, 16 cells per strip):\n");
  const std::vector<Sample> samples = patches(table, points);
  one_patch(samples, CTAB_CREEP_STRIPS_CARTER, "strips, Carter:", overhead_ns);
  one_patch(samples, CTAB_CREEP_STRIPS, "strips:", overhead_ns);
  one_patch(samples, CTAB_CREEP_FASTSIM_ELLIPSE, "ellipse FASTSIM:", overhead_ns);
  one_patch(samples, CTAB_CREEP_LINEAR, "linear Kalker:", overhead_ns);
  hil_step(table, std::max<std::size_t>(points / 8, 1000), overhead_ns);
}

}  // namespace ctab::cli
