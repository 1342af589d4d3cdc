// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Timing statistics of `ctab bench`: one operation run repeatedly on the calling thread, summarised as sample
//! count, mean, min, median and worst wall time [s]. ctab's own figures only: reference times of other programs
//! (CONTACT, the paper's Matlab) are compared outside the binary (scripts/speed_vs_contact.py).
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <numeric>
#include <vector>

namespace ctab::cli {

inline constexpr std::size_t kMinBenchSamples = 5;  //!< at least this many timed runs per row

struct Timing {
  std::size_t samples = 0;
  double mean_s = 0.0, min_s = 0.0, median_s = 0.0, worst_s = 0.0;  //!< wall time per run [s]
};

//! Statistics of the run times [s] (empty: all zero). The median of an even count is the mean of the middle two.
[[nodiscard]] inline Timing summarize_times(std::vector<double> times_s) {
  Timing t;
  t.samples = times_s.size();
  if (times_s.empty()) return t;
  std::sort(times_s.begin(), times_s.end());
  t.mean_s = std::accumulate(times_s.begin(), times_s.end(), 0.0) / static_cast<double>(t.samples);
  t.min_s = times_s.front();
  t.worst_s = times_s.back();
  const std::size_t half = t.samples / 2;
  t.median_s = t.samples % 2 == 1 ? times_s[half] : 0.5 * (times_s[half - 1] + times_s[half]);
  return t;
}

//! Runs `once()` until `seconds` of run time are measured and at least kMinBenchSamples runs are made (warm up
//! before calling: the first run is timed like the others).
template <class Operation>
[[nodiscard]] Timing time_repeatedly(double seconds, Operation&& once) {
  std::vector<double> times_s;
  double total_s = 0.0;
  while (total_s < seconds || times_s.size() < kMinBenchSamples) {
    const auto start = std::chrono::steady_clock::now();
    once();
    times_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    total_s += times_s.back();
  }
  return summarize_times(std::move(times_s));
}

//! Adds "samples", "mean_s", "min_s", "median_s", "worst_s" to a JSON row.
inline void add_timing(nlohmann::json& row, const Timing& t) {
  row["samples"] = t.samples;
  row["mean_s"] = t.mean_s;
  row["min_s"] = t.min_s;
  row["median_s"] = t.median_s;
  row["worst_s"] = t.worst_s;
}

}  // namespace ctab::cli
