// SPDX-License-Identifier: Apache-2.0
// `ctab bench stability [--out DIR] [--quick] [--scene NAME]... [--strip-width W]`: the stability matrix
// (ctab/validation/stability_matrix.hpp): every rung on hard scenes. Writes DIR/stability.csv (one row per case x
// method) and prints per scene and method: cases, statuses, worst error against the reference, worst time. Exit 4 when
// a result holds a non-finite number or a converged case breaks the error bound ctab claims (the CSV stays).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ctab/validation/stability_matrix.hpp"
#include "exit_codes.hpp"

namespace ctab::cli {

namespace {

int run_bench_stability(const std::string& out_dir, const gen::StabilityOptions& options) {
  for (const std::string& scene : options.scenes) {
    const auto names = gen::stability_scene_names();
    if (std::find(names.begin(), names.end(), scene) == names.end()) {
      std::string all;
      for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
      std::fprintf(stderr, "error: --scene: unknown scene '%s' (expected one of %s)\n", scene.c_str(), all.c_str());
      return kExitUsage;
    }
  }
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) throw IoError(out_dir + ": cannot create the output directory (" + error.message() + ")");
  const std::vector<gen::StabilityRow> rows = gen::run_stability_matrix(options);
  const std::filesystem::path csv = std::filesystem::path(out_dir) / "stability.csv";
  {
    std::ofstream out(csv);
    out << gen::stability_csv(rows);
    out.flush();
    if (!out) throw IoError(csv.string() + ": cannot be written");
  }
  std::fputs(gen::stability_summary(rows).c_str(), stdout);
  std::printf("wrote %s (%zu rows)\n", csv.c_str(), rows.size());
  return gen::stability_claims_broken(rows) ? kExitCaseFailed : kExitSuccess;
}

}  // namespace

Command add_bench_stability_subcommand(CLI::App& bench) {
  auto out = std::make_shared<std::string>("stability");
  auto options = std::make_shared<gen::StabilityOptions>();
  CLI::App* app =
      bench.add_subcommand("stability",
                           "Every method on hard scenes: status, error against a reference, iterations, time per case");
  app->add_option("--out", *out, "output directory for stability.csv (default ./stability)");
  app->add_flag("--quick", options->quick, "a few cases per scene (what the fast tests run)");
  app->add_option("--scene", options->scenes, "only this scene (repeatable)");
  app->add_option("--strip-width", options->strip_width_m, "strip width / element size of every method [m]")
      ->capture_default_str()
      ->check(CLI::Range(0.02e-3, 2e-3));
  return {app, [out, options] { return run_bench_stability(*out, *options); }};
}

}  // namespace ctab::cli
