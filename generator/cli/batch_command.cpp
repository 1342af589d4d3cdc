// SPDX-License-Identifier: Apache-2.0
// `ctab batch MANIFEST.toml -o DIR`: one table per profile pair of a manifest (batch_manifest.hpp), each written
// atomically, plus DIR/index.csv with each pair's status, case counts and hashes. Resumes: a pair whose table is
// already in DIR, complete and made by this ctab build from the same config and profiles, is not solved again.
// A bad profile fails its pair (status input-error in the index) and the batch goes on.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/io/sha256.hpp"
#include "ctab/profiles/builtin_profiles.hpp"
#include "ctab/sweep/batch_manifest.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "exit_codes.hpp"
#include "isolated_read.hpp"
#ifdef CTAB_WITH_MPI
#include "mpi_generate.hpp"
#endif
#include "output_guard.hpp"
#include "setup_options.hpp"
#include "table_output.hpp"
#include "version.hpp"

namespace ctab::cli {

namespace {

namespace fs = std::filesystem;

struct BatchOptions {
  std::string manifest;
  std::string directory;
  int threads = 0;
  bool quiet = false;
};

//! One row of index.csv.
struct PairOutcome {
  std::string status = "not-run";  // ok | failed-cases | input-error | write-error | not-run
  std::string run = "-";           // generated | resumed | -
  std::size_t wheel_cases = 0, failed_wheel_cases = 0;
  std::string wheel_sha256, rail_sha256, config_sha256;
  double seconds = 0.0;
  std::string message;
};

std::string sha256_of_text(const std::string& text) { return gen::sha256_hex(text.data(), text.size()); }

// SHA-256 of a profile file's bytes; "builtin" for a built-in profile, "unreadable" when the file cannot be read.
std::string profile_sha256(const std::string& spec) {
  if (gen::is_builtin_profile(spec)) return "builtin";
  std::ifstream in(spec, std::ios::binary);
  if (!in) return "unreadable";
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return sha256_of_text(bytes.str());
}

std::string samples_sha256(const gen::ProfileTable& profile) {
  return gen::sha256_hex(profile.z_samples().data(), profile.z_samples().size() * sizeof(double));
}

std::string csv_field(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return quoted + "\"";
}

// index.csv, written to a temporary file and renamed (after every pair, so an interrupted batch leaves a true index).
void write_index(const std::string& directory, const gen::BatchManifest& manifest,
                 const std::vector<PairOutcome>& outcomes) {
  const fs::path path = fs::path(directory) / "index.csv";
  const std::string temporary = path.string() + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << "table,wheel,rail,status,run,wheel_cases,failed_wheel_cases,wheel_sha256,rail_sha256,config_sha256,seconds,"
           "message\n";
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      const gen::ProfilePair& pair = manifest.pairs[i];
      const PairOutcome& o = outcomes[i];
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%.3f", o.seconds);
      out << csv_field(pair.table_name) << ',' << csv_field(pair.wheel) << ',' << csv_field(pair.rail) << ','
          << o.status << ',' << o.run << ',' << o.wheel_cases << ',' << o.failed_wheel_cases << ',' << o.wheel_sha256
          << ',' << o.rail_sha256 << ',' << o.config_sha256 << ',' << seconds << ',' << csv_field(o.message) << '\n';
    }
    out.close();
    if (!out) {
      std::remove(temporary.c_str());  // a full disk leaves the previous index and no temporary
      throw IoError(path.string() + ": cannot write the batch index");
    }
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    std::remove(temporary.c_str());
    throw IoError(path.string() + ": cannot rename the batch index into place: " + error.message());
  }
}

void count_statuses(const tables::Table& table, PairOutcome& outcome) {
  outcome.wheel_cases = table.status.size();
  outcome.failed_wheel_cases = 0;
  for (const auto s : table.status) outcome.failed_wheel_cases += tables::is_success(s) ? 0u : 1u;
  outcome.status = outcome.failed_wheel_cases > 0 ? "failed-cases" : "ok";
}

// A table already at `path` that this build made from the same config text and profiles (by their samples). Read in
// a child process (isolated_read.hpp): the directory may hold any file; a corrupt one is an error of its pair.
bool is_complete(const std::string& path, const gen::TableConfig& config, const gen::SweepSetup& setup,
                 PairOutcome& outcome) {
  if (!fs::is_regular_file(path)) return false;
  const IsolatedResult result = run_isolated([&](IsolatedChild& child) {
    tables::Table table;
    child.reading(path);
    if (!tables::read_table(path, table).ok()) return 1;
    child.trusted_from_here();
    const auto& a = table.text_attributes;
    auto has = [&](const char* name, const std::string& value) { return a.count(name) && a.at(name) == value; };
    if (!(has("config", config.text) && has("wheel_profile", config.wheel) && has("rail_profile", config.rail) &&
          has("generator_version", CTAB_VERSION) && has("git_commit", CTAB_GIT_COMMIT) &&
          has("wheel_profile_sha256", samples_sha256(*setup.wheel)) &&
          has("rail_profile_sha256", samples_sha256(*setup.rail))))
      return 1;
    PairOutcome counted;
    count_statuses(table, counted);
    child.reply(std::to_string(counted.wheel_cases) + " " + std::to_string(counted.failed_wheel_cases));
    return 0;
  });
  if (result.exit_code != 0) return false;
  std::istringstream counts(result.reply);
  counts >> outcome.wheel_cases >> outcome.failed_wheel_cases;
  outcome.status = outcome.failed_wheel_cases > 0 ? "failed-cases" : "ok";
  return true;
}

#ifdef CTAB_WITH_MPI
using Ranks = MpiSession;
// Thrown by rank 0's checks to skip a pair whose table is complete (not an error: caught in solve_pair).
struct PairResumed {};
#else
struct Ranks {  // a build without MPI: one process
  [[nodiscard]] int rank() const noexcept { return 0; }
  [[nodiscard]] int size() const noexcept { return 1; }
};
#endif

// One pair's table, or nullopt when `is_resumed` (run first, on rank 0 alone) finds it complete. Under
// `mpirun -n R` (R >= 2) every rank solves cases of it (mpi_generate.hpp) and only rank 0 gets the table.
std::optional<tables::Table> solve_pair([[maybe_unused]] const Ranks& ranks, const gen::TableConfig& config,
                                        const gen::GeneratorInfo& info, const std::function<bool()>& is_resumed,
                                        const gen::ProgressCallback& progress) {
#ifdef CTAB_WITH_MPI
  if (ranks.size() > 1) {
    try {
      return generate_table_mpi(
          ranks, config, info,
          [&] {
            if (is_resumed()) throw PairResumed{};
          },
          progress);
    } catch (const PairResumed&) {
      return std::nullopt;
    }
  }
#endif
  if (is_resumed()) return std::nullopt;
  return gen::generate_table(config, info, progress);
}

#ifdef CTAB_WITH_MPI
// A worker rank of `mpirun -n R ctab batch`: takes part in every pair rank 0 solves; rank 0 reports the pairs.
int run_batch_worker(const Ranks& ranks, const gen::BatchManifest& manifest, const gen::GeneratorInfo& info) {
  for (const gen::ProfilePair& pair : manifest.pairs) {
    std::optional<gen::TableConfig> config;
    try {
      config = gen::pair_config(manifest, pair);  // throws on every rank alike: rank 0 skips the pair too
    } catch (const gen::Error&) {
      continue;
    }
    try {
      (void)generate_table_mpi(ranks, *config, info, {}, {});
    } catch (const gen::Error&) {  // this rank's set-up of the pair failed: rank 0 reports it
    }
  }
  return kExitSuccess;
}
#endif

int run_batch(const BatchOptions& o) {
  const gen::BatchManifest manifest = gen::read_batch_manifest(o.manifest);
  gen::require_table_axes(manifest.base);
  gen::GeneratorInfo info;
  info.version = CTAB_VERSION;
  info.git_commit = CTAB_GIT_COMMIT;
  info.threads = sweep_threads(o.threads);
  const Ranks ranks;
#ifdef CTAB_WITH_MPI
  if (ranks.rank() != 0) return run_batch_worker(ranks, manifest, info);
#endif
  std::error_code error;
  fs::create_directories(o.directory, error);
  if (!fs::is_directory(o.directory)) throw IoError(o.directory + ": cannot create the output directory");
  const std::string config_sha256 = sha256_of_text(manifest.base.text);
  // One progress bar over the batch: every pair counts its wheel cases, whether solved, resumed or failed.
  const std::size_t per_pair =
      manifest.base.lateral_displacement_m.size() * manifest.base.load_values.size() * tables::kWheels;
  const std::size_t total = per_pair * manifest.pairs.size();
  ProgressReporter reporter(o.quiet, "ctab batch");
  std::vector<PairOutcome> outcomes(manifest.pairs.size());
  bool io_failed = false;
  for (std::size_t i = 0; i < manifest.pairs.size(); ++i) {
    const gen::ProfilePair& pair = manifest.pairs[i];
    PairOutcome& outcome = outcomes[i];
    outcome.wheel_sha256 = profile_sha256(pair.wheel);
    outcome.rail_sha256 = profile_sha256(pair.rail);
    outcome.config_sha256 = config_sha256;
    const std::string path = (fs::path(o.directory) / pair.table_name).string();
    const auto start = std::chrono::steady_clock::now();
    try {
      const gen::TableConfig config = gen::pair_config(manifest, pair);
      const auto is_resumed = [&] {
        const gen::SweepSetup setup = gen::make_sweep_setup(config);  // a bad profile throws here
        if (is_complete(path, config, setup, outcome)) return true;
        check_output_path(path, {o.manifest, pair.wheel, pair.rail}, OutputKind::Table, false);
        return false;
      };
      const std::optional<tables::Table> table =
          solve_pair(ranks, config, info, is_resumed, [&](std::size_t done, std::size_t of) {
            reporter(i * per_pair + (of > 0 ? done * per_pair / of : 0), total);
          });
      if (!table) {
        outcome.run = "resumed";
      } else {
        const InterruptCleanup cleanup(path);
        write_table_checked(*table, path, info.threads);
        count_statuses(*table, outcome);
        outcome.run = "generated";
      }
    } catch (const IoError& e) {
      outcome.status = "write-error";
      outcome.message = e.what();
      io_failed = true;
    } catch (const gen::Error& e) {
      outcome.status = "input-error";
      outcome.message = e.what();
    }
    outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!outcome.message.empty())
      std::fprintf(stderr, "ctab batch: %s: %s\n", pair.table_name.c_str(), outcome.message.c_str());
    reporter((i + 1) * per_pair, total);
    write_index(o.directory, manifest, outcomes);
  }
  std::size_t ok = 0, resumed = 0, failed = 0;
  for (const PairOutcome& outcome : outcomes) {
    ok += outcome.status == "ok" ? 1u : 0u;
    resumed += outcome.run == "resumed" ? 1u : 0u;
    failed += outcome.status != "ok" ? 1u : 0u;
  }
  if (!o.quiet)
    std::printf("ctab batch: %zu pairs: %zu ok, %zu failed, %zu resumed; index %s\n", outcomes.size(), ok, failed,
                resumed, (fs::path(o.directory) / "index.csv").string().c_str());
  if (failed > 0)
    std::fprintf(stderr, "ctab batch: %zu of %zu pairs failed or have failed cases; index.csv says which\n", failed,
                 outcomes.size());
  return io_failed ? kExitIo : failed > 0 ? kExitCaseFailed : kExitSuccess;
}

}  // namespace

Command add_batch_command(CLI::App& parent) {
  auto o = std::make_shared<BatchOptions>();
  CLI::App* app = parent.add_subcommand("batch", "One table per wheel/rail profile pair of a manifest, with an index");
  app->add_option("manifest", o->manifest, "TOML manifest: config, wheels, rails, pairing, pairs")
      ->required()
      ->check(CLI::ExistingFile);
  app->add_option("-o,--output", o->directory, "output directory (created if missing): tables and index.csv")
      ->required();
  add_threads_option(*app, o->threads);
  app->add_flag("--quiet", o->quiet, "no progress and no summary (failed pairs are still reported)");
  return {app, [o] { return run_batch(*o); }};
}

}  // namespace ctab::cli
