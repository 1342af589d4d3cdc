// `ctab bench solver`: MIM-1D on the Hertz case with prescribed load at three strip widths (paper Table 1).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "commands.hpp"
#include "setup_options.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/fixtures/paper_cases.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include <filesystem>

namespace ctab::cli {

namespace {

struct Row {
  double width_m;
  double paper_matlab_s;  // Qazi et al. 2022, Table 1
  double contact_s;       // CONTACT whole process, this machine kind (reference/contact/hertz_sphere.csv)
};

int run_bench_solver(double seconds_per_case) {
  const double E_star = gen::effective_modulus(gen::kSteel, gen::kSteel);
  const double force = 963.0e3;
  const std::vector<Row> rows = {{0.2e-3, 2.0e-3, 0.033}, {0.08e-3, 2.9e-2, 0.205}, {0.04e-3, 9.2e-2, 0.99}};
  std::printf("MIM-1D, sphere R = 40 mm on a flat, N = 963 kN prescribed (single thread)\n");
  std::printf("%8s %7s %6s %11s %11s %11s %13s %11s %9s\n", "strip mm", "strips", "iters", "mean ms", "min ms",
              "worst ms", "paper Matlab", "CONTACT", "speed-up");
  const gen::GapProfile gap = gen::paper::hertz_sphere_gap();
  for (const Row& row : rows) {
    gen::Mim1dOptions options;
    options.strip_width_m = row.width_m;
    gen::Mim1dSolver solver(gap, E_star, options);
    gen::NormalSolution solution = solver.solve_for_load(force);  // warm-up
    std::vector<double> times;
    double total = 0.0;
    while (total < seconds_per_case || times.size() < 5) {
      const auto start = std::chrono::steady_clock::now();
      solution = solver.solve_for_load(force);
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      times.push_back(t);
      total += t;
    }
    const double mean = total / static_cast<double>(times.size());
    std::printf("%8.2f %7zu %6d %11.3f %11.3f %11.3f %11.1f ms %8.0f ms %8.0fx\n", row.width_m * 1e3,
                solution.patches.empty() ? 0 : solution.patches.front().strips.size(), solution.iterations, mean * 1e3,
                *std::min_element(times.begin(), times.end()) * 1e3, *std::max_element(times.begin(), times.end()) * 1e3,
                row.paper_matlab_s * 1e3, row.contact_s * 1e3, row.contact_s / mean);
  }
  return 0;
}

// Geometry (rigid contact search, strip problem) plus MIM-1D per wheel-rail case: S1002 on UIC60 1:40, right wheel,
// single-wheel mode, N = 78.5 kN, strips 0.2 mm, at the shifts of the CONTACT reference cases.
int run_bench_wheelrail(double seconds_per_case) {
  const double E_star = gen::effective_modulus(gen::kSteel, gen::kSteel);
  const gen::ProfileTable wheel = gen::load_profile("S1002", gen::ProfileRole::Wheel, {});
  const gen::ProfileTable rail = gen::load_profile("UIC60", gen::ProfileRole::Rail, {});
  const gen::SideGeometry side(wheel, rail, gen::TrackSetup{});
  struct WheelRailRow {
    double dy_m, contact_s;  // CONTACT whole-process CPU time per case, this machine kind (summary.csv cpu_s_case)
  };
  const std::vector<WheelRailRow> rows = {{-1e-3, 0.146}, {0.0, 0.195}, {1e-3, 0.207}, {2e-3, 0.138}, {5e-3, 0.135}};
  std::printf("Wheel-rail case: S1002 on UIC60 1:40, single wheel, N = 78.5 kN, strips 0.2 mm (single thread)\n");
  std::printf("%8s %8s %7s %11s %11s %11s %10s %9s\n", "dy mm", "patches", "iters", "mean ms", "min ms", "worst ms", "CONTACT",
              "speed-up");
  for (const WheelRailRow& row : rows) {
    gen::WheelContact contact =
        gen::solve_wheel_contact(side, row.dy_m, 0.0, E_star, gen::LoadKind::NormalForce, 78.5e3, gen::WheelRailOptions{});
    std::vector<double> times;
    double total = 0.0;
    while (total < seconds_per_case || times.size() < 5) {
      const auto start = std::chrono::steady_clock::now();
      contact = gen::solve_wheel_contact(side, row.dy_m, 0.0, E_star, gen::LoadKind::NormalForce, 78.5e3, gen::WheelRailOptions{});
      const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      times.push_back(t);
      total += t;
    }
    const double mean = total / static_cast<double>(times.size());
    std::printf("%8.1f %8zu %7d %11.3f %11.3f %11.3f %7.0f ms %8.0fx\n", row.dy_m * 1e3, contact.patches.size(), contact.iterations,
                mean * 1e3, *std::min_element(times.begin(), times.end()) * 1e3,
                *std::max_element(times.begin(), times.end()) * 1e3, row.contact_s * 1e3, row.contact_s / mean);
  }
  return 0;
}

// The default table (241 shifts x 2 wheels) at 1 and 2 threads: best of several runs of the generator, the
// parallel efficiency t1 / (2 t2), and the size of the written file.
int run_bench_generate(int repetitions) {
  const gen::TableConfig config = gen::parse_table_config(gen::kDefaultTableConfig, "default config");
  (void)gen::generate_table(config, gen::GeneratorInfo{});  // warm-up: process-wide tables
  std::printf("Default table: %zu lateral shifts x 2 wheels, wheelset mode, MIM-1D 0.2 mm (best of %d runs)\n",
              config.lateral_displacement_m.size(), repetitions);
  double best[3] = {0, 1e9, 1e9};
  tables::Table table;
  for (int threads = 1; threads <= 2; ++threads) {
    gen::GeneratorInfo info;
    info.threads = threads;
    for (int r = 0; r < repetitions; ++r) {
      const auto start = std::chrono::steady_clock::now();
      table = gen::generate_table(config, info);
      best[threads] = std::min(best[threads], std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::printf("  %d thread(s): %.3f s\n", threads, best[threads]);
  }
  const std::string path = (std::filesystem::temp_directory_path() / "ctab_bench_table.h5").string();
  const auto start = std::chrono::steady_clock::now();
  if (!tables::write_table(table, path).ok()) return 4;
  const double write = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("  parallel efficiency 1 -> 2 threads: %.0f %%\n", 100.0 * best[1] / (2.0 * best[2]));
  std::printf("  HDF5 write %.3f s, file size %.1f kB\n", write, static_cast<double>(std::filesystem::file_size(path)) / 1024.0);
  std::filesystem::remove(path);
  return 0;
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
  CLI::App* wheelrail = app->add_subcommand("wheelrail", "Geometry plus MIM-1D per wheel-rail case (the CONTACT cases)");
  wheelrail->add_option("--seconds", *seconds, "measuring time per case [s]")
      ->capture_default_str()
      ->check(seconds_check);
  auto repetitions = std::make_shared<int>(5);
  CLI::App* generate = app->add_subcommand("generate", "The default table at 1 and 2 threads: time, parallel efficiency, file size");
  generate->add_option("--repetitions", *repetitions, "runs per thread count")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  const Command lookup = add_bench_lookup_subcommand(*app);
  return {app, [seconds, solver, wheelrail, repetitions, lookup] {
            if (lookup.app->parsed()) return lookup.run();
            if (solver->parsed()) return run_bench_solver(*seconds);
            if (wheelrail->parsed()) return run_bench_wheelrail(*seconds);
            return run_bench_generate(*repetitions);
          }};
}

}  // namespace ctab::cli
