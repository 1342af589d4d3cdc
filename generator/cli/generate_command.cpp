// SPDX-License-Identifier: Apache-2.0
// `ctab generate [CONFIG.toml] [-o FILE.h5]`: the parallel table generator (the main job of `make run`).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/contact/solve_status.hpp"
#include "ctab/sweep/case_partition.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/sweep/table_shard.hpp"
#include "exit_codes.hpp"
#ifdef CTAB_WITH_MPI
#include "mpi_generate.hpp"
#endif
#include "output_guard.hpp"
#include "setup_options.hpp"
#include "table_output.hpp"
#include "version.hpp"

namespace ctab::cli {

namespace {

struct GenerateOptions {
  std::string config_path;
  std::string output = "ctab_table.h5";
  int threads = 0;
  bool quiet = false;
  bool force = false;
  std::string shard;  // "K/N" or empty
};

// The files a run reads (built-in profile names match no file): `-o` never replaces one of them.
std::vector<std::string> inputs_of(const gen::TableConfig& config, const GenerateOptions& o) {
  return {o.config_path, config.wheel, config.rail};
}

// Failed cases are always reported (also with --quiet): the table is written, the statuses say which.
bool report_failed_cases(const std::map<int, std::size_t>& counts, const std::string& output) {
  std::size_t failed = 0, total = 0;
  std::string names;
  for (const auto& [status, count] : counts) {
    total += count;
    if (status >= 0) continue;
    failed += count;
    names += std::string(names.empty() ? "" : ", ") +
             tables::case_status_name(static_cast<tables::CaseStatus>(status)) + " " + std::to_string(count);
  }
  if (failed > 0)
    std::fprintf(stderr,
                 "ctab generate: %zu of %zu wheel cases failed (%s); %s is written, its status dataset says which\n",
                 failed, total, names.c_str(), output.c_str());
  return failed > 0;
}

// `--shard K/N`: the shard's rows only, into a shard file (table_shard.hpp); its own cases decide the exit code.
int run_shard(const gen::TableConfig& config, const gen::GeneratorInfo& info, gen::ShardSpec spec,
              const GenerateOptions& o, const gen::ProgressCallback& progress) {
  const tables::Table shard = gen::generate_shard(config, info, spec, progress);
  write_table_checked(shard, o.output, info.threads);
  const std::vector<std::size_t> rows = *gen::parse_rows(shard.text_attributes.at("shard_rows"), shard.n_dy());
  std::map<int, std::size_t> counts;
  for (const std::size_t row : rows)
    for (std::size_t i_second = 0; i_second < shard.n_second(); ++i_second)
      for (std::size_t wheel = 0; wheel < tables::kWheels; ++wheel)
        ++counts[static_cast<int>(shard.status[shard.wheel_index(row, i_second, wheel)])];
  if (!o.quiet)
    std::printf("ctab generate: wrote shard %zu/%zu to %s: %zu of %zu lateral shifts (rows %s)\n", spec.index,
                spec.count, o.output.c_str(), rows.size(), shard.n_dy(),
                shard.text_attributes.at("shard_rows").c_str());
  return report_failed_cases(counts, o.output) ? kExitCaseFailed : kExitSuccess;
}

// The summary of a whole table (stdout unless quiet) and its failed cases (stderr); returns the exit code.
int report_table(const tables::Table& table, const GenerateOptions& o, double seconds, int threads, int ranks) {
  std::map<int, std::size_t> counts;
  for (const auto s : table.status) ++counts[static_cast<int>(s)];
  if (!o.quiet) {
    const std::string on_ranks = ranks > 1 ? " x " + std::to_string(ranks) + " MPI ranks" : "";
    std::printf("ctab generate: %zu lateral shifts x %zu %s x 2 wheels in %.2f s on %d thread(s)%s%s\n", table.n_dy(),
                table.n_second(), table.second_axis_name.c_str(), seconds, threads, on_ranks.c_str(),
                table.text_attributes.at("mirrored").rfind("true", 0) == 0 ? " (left wheel mirrored)" : "");
    std::printf("wrote %s (%.1f kB); statuses:", o.output.c_str(),
                static_cast<double>(std::filesystem::file_size(o.output)) / 1024.0);
    for (const auto& [status, count] : counts)
      std::printf(" %s %zu", tables::case_status_name(static_cast<tables::CaseStatus>(status)), count);
    std::printf("; %zu contact jumps\n", table.jumps.size());
  }
  return report_failed_cases(counts, o.output) ? kExitCaseFailed : kExitSuccess;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

#ifdef CTAB_WITH_MPI
// `mpirun -n R ctab generate` with R >= 2 (mpi_generate.hpp): rank 0 checks the output, gathers and writes.
int run_generate_mpi(const MpiSession& session, const gen::TableConfig& config, const gen::GeneratorInfo& info,
                     const GenerateOptions& o) {
  const bool root = session.rank() == 0;
  const auto start = std::chrono::steady_clock::now();
  ProgressReporter reporter(o.quiet || !root, "ctab generate");
  const auto progress = [&](std::size_t d, std::size_t t) { reporter(d, t); };
  const auto checks = [&] { check_output_path(o.output, inputs_of(config, o), OutputKind::Table, o.force); };
  const std::optional<tables::Table> table = generate_table_mpi(session, config, info, checks, progress);
  if (!table) return kExitSuccess;  // a worker: rank 0 writes the table and reports
  const double seconds = seconds_since(start);
  const InterruptCleanup cleanup(o.output);
  write_table_checked(*table, o.output, info.threads);
  return report_table(*table, o, seconds, info.threads, session.size());
}
#endif

int run_generate(const GenerateOptions& o) {
  const gen::TableConfig config =
      o.config_path.empty() ? default_table_config("default config") : gen::read_table_config(o.config_path);
  gen::require_table_axes(config);
  const gen::ShardSpec shard = o.shard.empty() ? gen::ShardSpec{} : gen::parse_shard_spec(o.shard, "--shard");
  gen::GeneratorInfo info;
  info.version = CTAB_VERSION;
  info.git_commit = CTAB_GIT_COMMIT;
  info.compiler = CTAB_COMPILER;
  info.build_flags = CTAB_BUILD_FLAGS;
  info.threads = sweep_threads(o.threads);
#ifdef CTAB_WITH_MPI
  const MpiSession session;
  if (session.size() > 1) {
    if (!o.shard.empty())
      throw gen::InputError("--shard", 0, "not with MPI: run one process per shard, or mpirun without --shard");
    return run_generate_mpi(session, config, info, o);
  }
#endif
  check_output_path(o.output, inputs_of(config, o), OutputKind::Table, o.force);  // before the sweep: a bad output costs no solving time
  const InterruptCleanup cleanup(o.output);
  const auto start = std::chrono::steady_clock::now();
  ProgressReporter reporter(o.quiet, "ctab generate");
  gen::ProgressCallback progress;  // none when quiet: no reporter thread
  if (!o.quiet) progress = [&](std::size_t d, std::size_t t) { reporter(d, t); };
  if (!o.shard.empty()) return run_shard(config, info, shard, o, progress);
  const tables::Table table = gen::generate_table(config, info, progress);
  const double seconds = seconds_since(start);
  write_table_checked(table, o.output, info.threads);
  return report_table(table, o, seconds, info.threads, 1);
}

}  // namespace

Command add_generate_command(CLI::App& parent) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* app =
      parent.add_subcommand("generate",
                            "Generate a contact table (HDF5) from a TOML config or the embedded default; "
                            "`mpirun -n R ctab generate` shares the cases among R ranks (a build with CTAB_WITH_MPI)");
  app->add_option("config", o->config_path,
                  "TOML config (default: `ctab config --print-default`: S1002 on UIC60 1:40, "
                  "wheelset, -12..12 mm, 78.5 kN)");
  app->add_option("-o,--output", o->output, "output table; replaced only on success, and only if it is a ctab table")
      ->capture_default_str();
  app->add_flag("--force", o->force, "replace OUTPUT even if it is a ctab blob (never anything else)");
  add_threads_option(*app, o->threads);
  app->add_option("--shard", o->shard,
                  "K/N: solve only shard K of N (1 <= K <= N) into a shard file for `ctab merge` (job arrays)");
  app->add_flag("--quiet", o->quiet, "no progress and no summary (errors and failed cases are still reported)");
  return {app, [o] { return run_generate(*o); }};
}

}  // namespace ctab::cli
