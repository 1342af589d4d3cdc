// `ctab generate [CONFIG.toml] [-o FILE.h5]`: the parallel table generator (the main job of `make run`).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "commands.hpp"
#include "ctab/contact/error.hpp"
#include "ctab/contact/solve_status.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "exit_codes.hpp"
#include "output_guard.hpp"
#include "setup_options.hpp"
#include "version.hpp"

namespace ctab::cli {

namespace {

struct GenerateOptions {
  std::string config_path;
  std::string output = "ctab_table.h5";
  int threads = 0;
  bool quiet = false;
  bool force = false;
};

// A progress bar on a terminal, a plain line every few seconds otherwise.
class ProgressReporter {
 public:
  explicit ProgressReporter(bool quiet) : quiet_(quiet), terminal_(::isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()) {}
  void operator()(std::size_t done, std::size_t total) {
    if (quiet_ || total == 0) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
    const double left = rate > 0 ? static_cast<double>(total - done) / rate : 0.0;
    if (terminal_) {
      const int width = 40, filled = static_cast<int>(width * static_cast<double>(done) / static_cast<double>(total));
      std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu cases, %.0f/s, %.1f s left ", filled, "########################################",
                   width - filled, "", done, total, rate, left);
      if (done == total) std::fputc('\n', stderr);
    } else if (done == total || elapsed - last_line_ >= 5.0) {
      last_line_ = elapsed;
      std::fprintf(stderr, "ctab generate: %zu/%zu cases, %.0f cases/s, %.1f s left\n", done, total, rate, left);
    }
  }

 private:
  bool quiet_, terminal_;
  std::chrono::steady_clock::time_point start_;
  double last_line_ = -1e9;
};

// The writer names its temporary file in some messages; the user gave OUTPUT, so messages name OUTPUT.
std::string name_output(std::string message, const std::string& output) {
  const std::string temporary = temporary_table_path(output);
  for (auto at = message.find(temporary); at != std::string::npos; at = message.find(temporary, at + output.size()))
    message.replace(at, temporary.size(), output);
  return message;
}

// Failed cases are always reported (also with --quiet): the table is written, the statuses say which.
bool report_failed_cases(const std::map<int, std::size_t>& counts, const std::string& output) {
  std::size_t failed = 0, total = 0;
  std::string names;
  for (const auto& [status, count] : counts) {
    total += count;
    if (status >= 0) continue;
    failed += count;
    names += std::string(names.empty() ? "" : ", ") + tables::case_status_name(static_cast<tables::CaseStatus>(status)) + " " +
             std::to_string(count);
  }
  if (failed > 0)
    std::fprintf(stderr,
                 "ctab generate: %zu of %zu wheel cases failed (%s); %s is written, its status dataset says which\n",
                 failed, total, names.c_str(), output.c_str());
  return failed > 0;
}

int run_generate(const GenerateOptions& o) {
  const gen::TableConfig config =
      o.config_path.empty() ? default_table_config("default config") : gen::read_table_config(o.config_path);
  check_output_path(o.output, o.config_path, o.force);  // before the sweep: a bad output costs no solving time
  gen::GeneratorInfo info;
  info.version = CTAB_VERSION;
  info.git_commit = CTAB_GIT_COMMIT;
  info.compiler = CTAB_COMPILER;
  info.build_flags = CTAB_BUILD_FLAGS;
  info.threads = sweep_threads(o.threads);
  const InterruptCleanup cleanup(o.output);
  const auto start = std::chrono::steady_clock::now();
  ProgressReporter reporter(o.quiet);
  const tables::Table table = gen::generate_table(config, info, [&](std::size_t d, std::size_t t) { reporter(d, t); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const tables::TableResult written = tables::write_table(table, o.output);
  if (!written.ok()) throw IoError(name_output(written.message, o.output));
  std::map<int, std::size_t> counts;
  for (const auto s : table.status) ++counts[static_cast<int>(s)];
  if (!o.quiet) {
    std::printf("ctab generate: %zu lateral shifts x %zu %s x 2 wheels in %.2f s on %d thread(s)%s\n", table.n_dy(),
                table.n_second(), table.second_axis_name.c_str(), seconds, info.threads,
                table.text_attributes.at("mirrored").rfind("true", 0) == 0 ? " (left wheel mirrored)" : "");
    std::printf("wrote %s (%.1f kB); statuses:", o.output.c_str(), static_cast<double>(std::filesystem::file_size(o.output)) / 1024.0);
    for (const auto& [status, count] : counts) std::printf(" %s %zu", tables::case_status_name(static_cast<tables::CaseStatus>(status)), count);
    std::printf("; %zu contact jumps\n", table.jumps.size());
  }
  return report_failed_cases(counts, o.output) ? kExitCaseFailed : kExitSuccess;
}

}  // namespace

Command add_generate_command(CLI::App& parent) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* app = parent.add_subcommand("generate", "Generate a contact table (HDF5) from a TOML config or the embedded default");
  app->add_option("config", o->config_path,
                  "TOML config (default: `ctab config --print-default`: S1002 on UIC60 1:40, "
                  "wheelset, -12..12 mm, 78.5 kN)");
  app->add_option("-o,--output", o->output, "output table; replaced only on success, and only if it is a table")
      ->capture_default_str();
  app->add_flag("--force", o->force, "replace OUTPUT even if it is not an HDF5 table (a symlink, FIFO, other file)");
  add_threads_option(*app, o->threads);
  app->add_flag("--quiet", o->quiet, "no progress and no summary (errors and failed cases are still reported)");
  return {app, [o] { return run_generate(*o); }};
}

}  // namespace ctab::cli
