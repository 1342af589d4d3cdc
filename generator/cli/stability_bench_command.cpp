// `ctab bench stability [--out DIR] [--quick] [--scene NAME]... [--strip-width W]`: the stability matrix
// (ctab/sweep/stability_matrix.hpp): every rung on hard scenes. Writes DIR/stability.csv (one row per case x method)
// and prints per scene and method: cases, statuses, worst error against the reference, worst time. Exit 4 when a
// result holds a non-finite number or a converged case breaks the error bound ctab claims (the CSV stays).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ctab/sweep/stability_matrix.hpp"
#include "exit_codes.hpp"

namespace ctab::cli {

namespace {

//! One line of the printed summary: a scene and a method over its cases.
struct SummaryLine {
  int cases = 0, converged = 0, no_contact = 0, under_resolved = 0, failed = 0, claimed = 0, broken = 0, non_finite = 0;
  double worst_error = 0.0, worst_time_s = 0.0;
  std::map<std::string, int> failures;  // status name -> count
};

void print_summary(const std::vector<gen::StabilityRow>& rows) {
  std::map<std::pair<std::string, std::string>, SummaryLine> lines;
  std::vector<std::pair<std::string, std::string>> order;
  for (const gen::StabilityRow& r : rows) {
    const auto key = std::make_pair(r.scene, r.method);
    if (!lines.count(key)) order.push_back(key);
    SummaryLine& l = lines[key];
    ++l.cases;
    l.converged += r.status == gen::SolveStatus::Converged;
    l.no_contact += r.status == gen::SolveStatus::NoContact;
    l.under_resolved += r.status == gen::SolveStatus::UnderResolved;
    if (!gen::is_success(r.status)) {
      ++l.failed;
      ++l.failures[gen::status_name(r.status)];
    }
    l.non_finite += r.finite ? 0 : 1;
    const double e = r.error_rel();
    if (std::isfinite(e)) l.worst_error = std::max(l.worst_error, e);
    l.worst_time_s = std::max(l.worst_time_s, r.time_s);
    if (gen::stability_claim_applies(r)) {
      ++l.claimed;
      l.broken += e > gen::stability_error_bound(r) ? 1 : 0;
    }
  }
  std::printf("%-22s %-7s %5s %5s %5s %5s %6s %7s %6s %9s %9s  %s\n", "scene", "method", "cases", "conv", "noc",
              "under", "failed", "claimed", "broken", "worst err", "worst s", "failures");
  for (const auto& key : order) {
    const SummaryLine& l = lines[key];
    std::string failures;
    for (const auto& [name, count] : l.failures) failures += name + " x" + std::to_string(count) + " ";
    if (l.non_finite) failures += "NON-FINITE x" + std::to_string(l.non_finite);
    std::printf("%-22s %-7s %5d %5d %5d %5d %6d %7d %6d %8.1f%% %9.2e  %s\n", key.first.c_str(), key.second.c_str(),
                l.cases, l.converged, l.no_contact, l.under_resolved, l.failed, l.claimed, l.broken,
                100.0 * l.worst_error, l.worst_time_s, failures.c_str());
  }
}

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
  print_summary(rows);
  std::printf("wrote %s (%zu rows)\n", csv.c_str(), rows.size());
  const bool bad = std::any_of(rows.begin(), rows.end(), [](const gen::StabilityRow& r) {
    return !r.finite || (gen::stability_claim_applies(r) && r.error_rel() > gen::stability_error_bound(r));
  });
  return bad ? kExitCaseFailed : kExitSuccess;
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
