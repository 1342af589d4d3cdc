// `ctab generate [CONFIG.toml] [-o FILE.h5]`: the parallel table generator (the main job of `make run`).
#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "commands.hpp"
#include "version.hpp"
#include "ctab/contact/error.hpp"
#include "ctab/contact/solve_status.hpp"
#include "ctab/sweep/table_generator.hpp"


namespace ctab::cli {

namespace {

struct GenerateOptions {
  std::string config_path;
  std::string output = "ctab_table.h5";
  int threads = 0;
  bool quiet = false;
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

int run_generate(const GenerateOptions& o) {
  const gen::TableConfig config =
      o.config_path.empty() ? gen::parse_table_config(gen::kDefaultTableConfig, "default config") : gen::read_table_config(o.config_path);
  gen::GeneratorInfo info;
  info.version = CTAB_VERSION;
  info.git_commit = CTAB_GIT_COMMIT;
  info.compiler = "unknown";     // the integrator wires CTAB_COMPILER here
  info.build_flags = "unknown";  // and CTAB_BUILD_FLAGS
  if (o.threads < 0) throw gen::InputError("--threads", 0, "expected a positive number of threads");
  info.threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  const auto start = std::chrono::steady_clock::now();
  ProgressReporter reporter(o.quiet);
  const tables::Table table = gen::generate_table(config, info, [&](std::size_t d, std::size_t t) { reporter(d, t); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const tables::TableResult written = tables::write_table(table, o.output);
  if (!written.ok()) throw gen::Error(written.message);
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
  for (const auto& [status, count] : counts)
    if (status < 0) return 4;  // the table is written, but some cases failed (their status says which)
  return 0;
}

}  // namespace

Command add_generate_command(CLI::App& parent) {
  auto o = std::make_shared<GenerateOptions>();
  CLI::App* app = parent.add_subcommand("generate", "Generate a contact table (HDF5) from a TOML config or the embedded default");
  app->add_option("config", o->config_path, "TOML config (default: S1002 on UIC60 1:40, wheelset, -12..12 mm, 78.5 kN)");
  app->add_option("-o,--output", o->output, "output table (default ctab_table.h5); replaced only on success");
  app->add_option("--threads", o->threads, "OpenMP threads (default: all)");
  app->add_flag("--quiet", o->quiet, "no progress and no summary");
  return {app, [o] { return run_generate(*o); }};
}

}  // namespace ctab::cli
