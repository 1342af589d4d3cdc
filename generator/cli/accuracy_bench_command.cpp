// SPDX-License-Identifier: Apache-2.0
// `ctab bench accuracy [--out DIR] [--quick] [--reference DIR] [--wheel F --rail F --inclination I]`: the accuracy
// bench (ctab/validation/accuracy_bench.hpp) with CONTACT's wheel-rail summary from --reference DIR. Writes
// DIR/accuracy.csv (one row per scene x region x method x discretisation) and charts it with scripts/accuracy_chart.py
// into DIR/accuracy.png and .svg (exit 3 when the chart fails; the CSV stays).
#include <spawn.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "creep_accuracy.hpp"
#include "ctab/validation/accuracy_bench.hpp"
#include "exit_codes.hpp"
#include "setup_options.hpp"

extern char** environ;

namespace ctab::cli {

namespace {

//! The chart script: the source tree's scripts/ (CTAB_SCRIPTS_DIR), else the working directory's.
std::filesystem::path chart_script() {
  const std::filesystem::path built = std::filesystem::path(CTAB_SCRIPTS_DIR) / "accuracy_chart.py";
  if (std::filesystem::exists(built)) return built;
  return std::filesystem::path("scripts") / "accuracy_chart.py";
}

//! Runs /usr/bin/python3 SCRIPT CSV PREFIX; its exit code (-1 when it could not start or was killed).
int run_chart(const std::filesystem::path& csv, const std::filesystem::path& prefix) {
  std::vector<std::string> args = {"/usr/bin/python3", chart_script().string(), csv.string(), prefix.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

int run_bench_accuracy(const std::string& out_dir, const gen::AccuracyBenchOptions& options) {
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) throw IoError(out_dir + ": cannot create the output directory (" + error.message() + ")");
  const std::vector<gen::AccuracyRow> rows = gen::run_accuracy_bench(options);
  const std::filesystem::path csv = std::filesystem::path(out_dir) / "accuracy.csv";
  {
    std::ofstream out(csv);
    out << gen::accuracy_csv(rows);
    out.flush();
    if (!out) throw IoError(csv.string() + ": cannot be written");
  }
  std::printf("wrote %s (%zu rows)\n", csv.c_str(), rows.size());
  const std::filesystem::path prefix = std::filesystem::path(out_dir) / "accuracy";
  const int chart = run_chart(csv, prefix);
  if (chart != 0) {
    std::fprintf(stderr, "error: the chart failed (/usr/bin/python3 %s exited %d); %s is kept\n",
                 chart_script().c_str(), chart, csv.c_str());
    return kExitIo;
  }
  std::printf("wrote %s.png and %s.svg\n", prefix.c_str(), prefix.c_str());
  return kExitSuccess;
}

}  // namespace

Command add_bench_accuracy_subcommand(CLI::App& bench) {
  auto out = std::make_shared<std::string>("accuracy");
  auto quick = std::make_shared<bool>(false);
  auto reference = std::make_shared<std::string>();
  auto profiles = std::make_shared<gen::TableConfig>(default_table_config());
  CLI::App* app =
      bench.add_subcommand("accuracy",
                           "Every method at several discretisations against a reference: error against time per case");
  app->add_option("--out", *out, "output directory for accuracy.csv, .png, .svg (default ./accuracy)");
  app->add_flag("--quick", *quick, "fewer shifts, a coarser reference (about a minute; what the tests run)");
  app->add_option(
      "--reference", *reference,
      "CONTACT reference directory (wheelrail/summary.csv, wheelrail/flange/planar_normal_force.csv); its "
      "wheel-rail cases are compared when the profiles are CONTACT's (the Manchester files, inclination 0)");
  (void)add_setup_options(*app, *profiles, kProfiles);
  auto creep = std::make_shared<std::string>();
  app->add_option("--creep", *creep, "CONTACT's creep references (wheelrail/tangential): the tangential ladder instead");
  return {app, [out, quick, reference, profiles, creep] {
            if (!creep->empty()) return run_creep_accuracy(*out, *creep);
            finish_setup_options(*profiles);
            gen::AccuracyBenchOptions options;
            options.quick = *quick;
            options.profiles = *profiles;
            if (!reference->empty()) options.contact = gen::read_contact_wheelrail(*reference);
            return run_bench_accuracy(*out, options);
          }};
}

}  // namespace ctab::cli
