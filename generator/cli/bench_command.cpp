// SPDX-License-Identifier: Apache-2.0
// `ctab bench solver|wheelrail|generate [--json]`: ctab's own speed figures (strips, iterations, mean, min,
// median, worst per row). Comparisons with CONTACT and the paper live in scripts/speed_vs_contact.py, which reads
// the --json output: no reference times of other programs in the binary.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

#include "bench_progress.hpp"
#include "bench_stats.hpp"
#include "commands.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/fixtures/paper_cases.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "exit_codes.hpp"
#include "setup_options.hpp"
#include "table_output.hpp"
#include "version.hpp"

namespace ctab::cli {

namespace {

constexpr double kHertzForce_N = 963.0e3;     // paper section 3.1, sphere R = 40 mm on a flat
constexpr double kWheelRailForce_N = 78.5e3;  // paper section 3.2, total normal force per wheel
const std::vector<double> kHertzStripWidths_m = {0.2e-3, 0.08e-3, 0.04e-3};     // paper Table 1
const std::vector<double> kWheelRailShifts_m = {-1e-3, 0.0, 1e-3, 2e-3, 5e-3};  // paper Figure 8

// The JSON document of a benchmark: what was run, where, and its rows (filled by the caller).
nlohmann::json bench_document(const char* benchmark, const char* description, double seconds_per_row) {
  return {{"benchmark", benchmark},
          {"description", description},
          {"ctab_version", CTAB_VERSION},
          {"git_commit", CTAB_GIT_COMMIT},
          {"threads", 1},
          {"seconds_per_row", seconds_per_row},
          {"units", "SI: m, N, s"},
          {"rows", nlohmann::json::array()}};
}

void print_timing(const Timing& t) {
  std::printf(" %8zu %10.3f %10.3f %10.3f %10.3f\n", t.samples, t.mean_s * 1e3, t.min_s * 1e3, t.median_s * 1e3,
              t.worst_s * 1e3);
}

constexpr const char* kTimingHeader = " %8s %10s %10s %10s %10s\n";

// MIM-1D on the sphere with the load prescribed, at the paper's three strip widths.
int run_bench_solver(double seconds_per_row, bool json) {
  const char* description = "MIM-1D, sphere R = 40 mm on a flat, N = 963 kN prescribed (single thread)";
  nlohmann::json document = bench_document("solver", description, seconds_per_row);
  document["normal_load_N"] = kHertzForce_N;
  if (!json) {
    std::printf("%s\n%8s %7s %6s", description, "strip mm", "strips", "iters");
    std::printf(kTimingHeader, "samples", "mean ms", "min ms", "median ms", "worst ms");
  }
  const double E_star = gen::effective_modulus(gen::kSteel, gen::kSteel);
  const gen::GapProfile gap = gen::paper::hertz_sphere_gap();
  for (const double width_m : kHertzStripWidths_m) {
    gen::Mim1dOptions options;
    options.strip_width_m = width_m;
    gen::Mim1dSolver solver(gap, E_star, options);
    gen::NormalSolution solution = solver.solve_for_load(kHertzForce_N);  // warm-up
    const Timing timing = time_repeatedly(seconds_per_row, [&] { solution = solver.solve_for_load(kHertzForce_N); });
    const std::size_t strips = solution.patches.empty() ? 0 : solution.patches.front().strips.size();
    nlohmann::json row = {{"strip_width_m", width_m}, {"strips", strips}, {"iterations", solution.iterations}};
    add_timing(row, timing);
    document["rows"].push_back(row);
    if (!json) {
      std::printf("%8.2f %7zu %6d", width_m * 1e3, strips, solution.iterations);
      print_timing(timing);
    }
  }
  if (json) std::cout << document.dump(1) << '\n';
  return kExitSuccess;
}

// Geometry (rigid contact search, strip problem) plus MIM-1D per wheel-rail case: S1002 on UIC60 1:40, right wheel,
// single-wheel mode, N = 78.5 kN, strips 0.2 mm, at the shifts of the paper's wheel-rail cases.
int run_bench_wheelrail(double seconds_per_row, bool json) {
  const char* description =
      "Wheel-rail case: S1002 on UIC60 1:40, single wheel, N = 78.5 kN, strips 0.2 mm (single thread)";
  nlohmann::json document = bench_document("wheelrail", description, seconds_per_row);
  document["normal_load_N"] = kWheelRailForce_N;
  if (!json) {
    std::printf("%s\n%8s %8s %7s", description, "dy mm", "patches", "iters");
    std::printf(kTimingHeader, "samples", "mean ms", "min ms", "median ms", "worst ms");
  }
  const double E_star = gen::effective_modulus(gen::kSteel, gen::kSteel);
  const gen::ProfileTable wheel = gen::load_profile("S1002", gen::ProfileRole::Wheel, {});
  const gen::ProfileTable rail = gen::load_profile("UIC60", gen::ProfileRole::Rail, {});
  const gen::SideGeometry side(wheel, rail, gen::TrackSetup{});
  for (const double dy_m : kWheelRailShifts_m) {
    auto solve = [&] {
      return gen::solve_wheel_contact(side, dy_m, 0.0, E_star, gen::LoadKind::NormalForce, kWheelRailForce_N,
                                      gen::WheelRailOptions{});
    };
    gen::WheelContact contact = solve();  // warm-up
    const Timing timing = time_repeatedly(seconds_per_row, [&] { contact = solve(); });
    nlohmann::json row = {{"dy_m", dy_m}, {"patches", contact.patches.size()}, {"iterations", contact.iterations}};
    add_timing(row, timing);
    document["rows"].push_back(row);
    if (!json) {
      std::printf("%8.1f %8zu %7d", dy_m * 1e3, contact.patches.size(), contact.iterations);
      print_timing(timing);
    }
  }
  if (json) std::cout << document.dump(1) << '\n';
  return kExitSuccess;
}

// The default table (241 shifts x 2 wheels) at 1 and 2 threads: best of several runs of the generator, the
// parallel efficiency t1 / (2 t2), and the size of the written file.
int run_bench_generate(int repetitions, bool json, bool progress) {
  const gen::TableConfig config = gen::parse_table_config(gen::kDefaultTableConfig, "default config");
  (void)gen::generate_table(config, gen::GeneratorInfo{});  // warm-up: process-wide tables
  if (!json)
    std::printf("Default table: %zu lateral shifts x 2 wheels, wheelset mode, MIM-1D 0.2 mm (best of %d runs)\n",
                config.lateral_displacement_m.size(), repetitions);
  nlohmann::json document = {{"benchmark", "generate"},
                             {"description", "default table, wheelset mode, MIM-1D 0.2 mm"},
                             {"ctab_version", CTAB_VERSION},
                             {"git_commit", CTAB_GIT_COMMIT},
                             {"lateral_shifts", config.lateral_displacement_m.size()},
                             {"repetitions", repetitions},
                             {"units", "SI: s, bytes"},
                             {"rows", nlohmann::json::array()}};
  double best_s[3] = {0, 1e9, 1e9};
  tables::Table table;
  BenchProgress runs_done(progress, 2 * repetitions);
  for (int threads = 1; threads <= 2; ++threads) {
    gen::GeneratorInfo info;
    info.threads = threads;
    for (int r = 0; r < repetitions; ++r) {
      runs_done.step(threads == 1 ? "default table, 1 thread" : "default table, 2 threads");
      const auto start = std::chrono::steady_clock::now();
      table = gen::generate_table(config, info);
      best_s[threads] =
          std::min(best_s[threads], std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    document["rows"].push_back({{"threads", threads}, {"best_s", best_s[threads]}});
    if (!json) std::printf("  %d thread(s): %.3f s\n", threads, best_s[threads]);
  }
  const std::string path = (std::filesystem::temp_directory_path() / "ctab_bench_table.h5").string();
  double write_s[3] = {0, 0, 0};  // as `ctab generate` writes: chunks deflated on 1 and on 2 threads
  for (int threads = 1; threads <= 2; ++threads) {
    const auto start = std::chrono::steady_clock::now();
    const tables::TableResult written = tables::write_table(table, path, openmp_parallel_for(threads));
    if (!written.ok()) throw IoError(written.message);  // names the file
    write_s[threads] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  const auto file_bytes = std::filesystem::file_size(path);
  std::filesystem::remove(path);
  const double efficiency = best_s[1] / (2.0 * best_s[2]);
  document["parallel_efficiency"] = efficiency;
  document["write_s"] = write_s[2];
  document["write_1_thread_s"] = write_s[1];
  document["file_bytes"] = file_bytes;
  if (json) {
    std::cout << document.dump(1) << '\n';
  } else {
    std::printf("  parallel efficiency 1 -> 2 threads: %.0f %%\n", 100.0 * efficiency);
    std::printf("  HDF5 write %.3f s on 2 threads (%.3f s on 1), file size %.1f kB\n", write_s[2], write_s[1],
                static_cast<double>(file_bytes) / 1024.0);
  }
  return kExitSuccess;
}

}  // namespace

Command add_bench_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand("bench", "Print speed figures (benchmarks, never timed tests)");
  app->require_subcommand(1);
  auto seconds = std::make_shared<double>(1.0);
  const CLI::Validator seconds_check = finite_positive("s", 3600.0);
  CLI::App* solver = app->add_subcommand("solver", "MIM-1D on the Hertz case at strip widths 0.2, 0.08, 0.04 mm");
  solver->add_option("--seconds", *seconds, "measuring time per width [s]")
      ->capture_default_str()
      ->check(seconds_check);
  CLI::App* wheelrail =
      app->add_subcommand("wheelrail", "Geometry plus MIM-1D per wheel-rail case (the paper's cases)");
  wheelrail->add_option("--seconds", *seconds, "measuring time per case [s]")
      ->capture_default_str()
      ->check(seconds_check);
  auto repetitions = std::make_shared<int>(5);
  CLI::App* generate =
      app->add_subcommand("generate", "The default table at 1 and 2 threads: time, parallel efficiency, file size");
  generate->add_option("--repetitions", *repetitions, "runs per thread count")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  auto progress = std::make_shared<bool>(false);
  generate->add_flag("--progress", *progress, "a progress line on stderr also when it is not a terminal");
  auto json = std::make_shared<bool>(false);
  for (CLI::App* bench : {solver, wheelrail, generate})
    bench->add_flag("--json", *json, "print one JSON object (SI units; read by scripts/speed_vs_contact.py)");
  const Command lookup = add_bench_lookup_subcommand(*app);
  const Command accuracy = add_bench_accuracy_subcommand(*app);
  const Command stability = add_bench_stability_subcommand(*app);
  const Command knee = add_bench_knee_subcommand(*app);
  return {app, [seconds, solver, wheelrail, repetitions, json, progress, lookup, accuracy, stability, knee] {
            if (knee.app->parsed()) return knee.run();
            if (lookup.app->parsed()) return lookup.run();
            if (accuracy.app->parsed()) return accuracy.run();
            if (stability.app->parsed()) return stability.run();
            if (solver->parsed()) return run_bench_solver(*seconds, *json);
            if (wheelrail->parsed()) return run_bench_wheelrail(*seconds, *json);
            return run_bench_generate(*repetitions, *json, *progress);
          }};
}

}  // namespace ctab::cli
