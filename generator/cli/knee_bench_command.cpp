// SPDX-License-Identifier: Apache-2.0
// `ctab bench knee [--out DIR] [--from M --to M --step M] [--reference-width M] [--reference-length M] [--load N]...
// [set-up options]`:
// the knee sweep (ctab/validation/knee_sweep.hpp). The candidate is --method (mim1d at --strip-width, or auto at
// --tolerance); the reference bem2d at --reference-width. Writes DIR/knee.csv (one row per bem2d patch and case)
// and prints how well each shape indicator predicts a patch (>= 5 % of the load) failing the targets.
// Exit 4 when any such patch fails them.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ctab/validation/knee_sweep.hpp"
#include "exit_codes.hpp"
#include "setup_options.hpp"

namespace ctab::cli {

namespace {

// Patches below this share of the wheel's normal force are outside the least model's per-patch bound [-].
constexpr double kBoundedLoadShare = 0.05;

struct KneeArgs {
  std::string out = "knee";
  double from_m = 4e-3, to_m = 9e-3, step_m = 0.02e-3, reference_width_m = 0.1e-3, reference_length_m = 0.0;
  std::vector<double> loads_N{50e3, 78.5e3, 110e3};
};

int run_bench_knee(const KneeArgs& args, const gen::TableConfig& config) {
  gen::KneeSweepOptions options;
  options.profiles = config;
  options.vertical_loads_N = args.loads_N;
  options.reference_width_m = args.reference_width_m;
  options.reference_length_m = args.reference_length_m;
  options.candidate_method = config.method;
  options.candidate_width_m = config.strip_width_m;
  options.candidate_tolerance = config.least_model ? config.tolerance : 0.0;
  for (double dy = args.from_m; dy <= args.to_m + 0.5 * args.step_m; dy += args.step_m) options.shifts_m.push_back(dy);
  std::error_code error;
  std::filesystem::create_directories(args.out, error);
  if (error) throw IoError(args.out + ": cannot create the output directory (" + error.message() + ")");
  const std::vector<gen::KneeRow> rows = gen::run_knee_sweep(options);
  const std::filesystem::path csv = std::filesystem::path(args.out) / "knee.csv";
  {
    std::ofstream out(csv);
    out << gen::knee_csv(rows);
    out.flush();
    if (!out) throw IoError(csv.string() + ": cannot be written");
  }
  const gen::KneeTargets targets;
  std::fputs(gen::knee_indicator_summary(rows, targets, kBoundedLoadShare).c_str(), stdout);
  std::printf("wrote %s (%zu rows)\n", csv.c_str(), rows.size());
  for (const gen::KneeRow& r : rows)
    if (r.load_share >= kBoundedLoadShare && r.errors.exceeds(targets)) return kExitCaseFailed;
  return kExitSuccess;
}

}  // namespace

Command add_bench_knee_subcommand(CLI::App& bench) {
  auto args = std::make_shared<KneeArgs>();
  auto config = std::make_shared<gen::TableConfig>(default_table_config());
  CLI::App* app = bench.add_subcommand(
      "knee", "A method against bem2d per patch over a dense dy range (single right wheel, vertical loads)");
  app->add_option("--out", args->out, "output directory for knee.csv (default ./knee)");
  app->add_option("--from", args->from_m, "first lateral shift [m]")->capture_default_str();
  app->add_option("--to", args->to_m, "last lateral shift [m]")->capture_default_str();
  app->add_option("--step", args->step_m, "shift step [m]")->capture_default_str()->check(CLI::Range(1e-6, 1e-2));
  app->add_option("--reference-width", args->reference_width_m, "bem2d element size of the reference [m]")
      ->capture_default_str()
      ->check(CLI::Range(0.02e-3, 1e-3));
  app->add_option("--reference-length", args->reference_length_m,
                  "its element length along the rolling direction [m] (default: squares)")
      ->check(CLI::Range(0.02e-3, 2e-3));
  app->add_option("--load", args->loads_N, "vertical wheel loads [N] (repeatable; default 50, 78.5, 110 kN)");
  (void)add_setup_options(*app, *config, kProfiles | kSolver);
  return {app, [args, config] {
            finish_setup_options(*config);
            return run_bench_knee(*args, *config);
          }};
}

}  // namespace ctab::cli
