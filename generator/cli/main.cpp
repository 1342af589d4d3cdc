// SPDX-License-Identifier: Apache-2.0
// ctab: wheel-rail contact tables. One executable, subcommands; exceptions stop here and become exit codes
// (exit_codes.hpp): 0 success, 2 usage or input error, 3 I/O failure, 4 failed solves or table cases.
#include <CLI/CLI.hpp>
#include <hdf5.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <vector>

#include "commands.hpp"
#include "error_exit.hpp"
#include "exit_codes.hpp"
#include "version.hpp"

namespace {

int run(CLI::App& app, const std::vector<ctab::cli::Command>& commands, int argc, char** argv) {
  using namespace ctab::cli;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0 (printed on stdout); every other parse error is a usage error.
    return app.exit(e) == 0 ? kExitSuccess : kExitUsage;
  }
  return run_reporting_errors([&] {
    for (const auto& command : commands)
      if (command.app->parsed()) return command.run();
    return static_cast<int>(kExitInternal);
  });
}

// Every subcommand by name and its registration. Registering all of them took 0.5 ms of every start (CLI11 options
// and validators), so a command line whose first argument names one registers that one alone: its options are all
// the parse needs. Help, version and a misspelt or missing command register them all (CLI11 lists and reports them
// as usual). cli_test checks each name against its subcommand's (`ctab NAME --help`).
struct CommandEntry {
  const char* name;
  ctab::cli::Command (*add)(CLI::App&);
};
constexpr CommandEntry kCommands[] = {
    {"generate", ctab::cli::add_generate_command}, {"inspect", ctab::cli::add_inspect_command},
    {"solve", ctab::cli::add_solve_command},       {"paper-cases", ctab::cli::add_paper_cases_command},
    {"geometry", ctab::cli::add_geometry_command}, {"bench", ctab::cli::add_bench_command},
    {"config", ctab::cli::add_config_command},     {"export", ctab::cli::add_export_command},
    {"query", ctab::cli::add_query_command},       {"merge", ctab::cli::add_merge_command},
    {"batch", ctab::cli::add_batch_command},       {"verify", ctab::cli::add_verify_command}};

// Levenshtein distance between two short words.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

// A first argument that is neither an option nor a command: a usage error naming the nearest command (within a
// third of its length, at least 2 edits) or, failing one, every command. Returns true when it reported one.
bool reported_unknown_command(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-' || argv[1][0] == '\0') return false;
  const std::string_view word = argv[1];
  const CommandEntry* nearest = nullptr;
  std::size_t best = 0;
  for (const CommandEntry& entry : kCommands) {
    const std::size_t distance = edit_distance(word, entry.name);
    if (distance == 0) return false;
    if (nearest == nullptr || distance < best) nearest = &entry, best = distance;
  }
  if (best <= std::max<std::size_t>(2, std::string_view(nearest->name).size() / 3)) {
    std::fprintf(stderr, "ctab: error: unknown command '%s'; did you mean '%s'?\n", argv[1], nearest->name);
  } else {
    std::fprintf(stderr, "ctab: error: unknown command '%s'; the commands are:", argv[1]);
    for (const CommandEntry& entry : kCommands) std::fprintf(stderr, " %s", entry.name);
    std::fprintf(stderr, "\n");
  }
  std::fprintf(stderr, "Run with --help for more information.\n");
  return true;
}

std::vector<ctab::cli::Command> add_commands(CLI::App& app, int argc, char** argv) {
  std::vector<ctab::cli::Command> commands;
  for (const CommandEntry& entry : kCommands)
    if (argc > 1 && std::strcmp(argv[1], entry.name) == 0) commands.push_back(entry.add(app));
  if (commands.empty())
    for (const CommandEntry& entry : kCommands) commands.push_back(entry.add(app));
  return commands;
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGPIPE, SIG_IGN);
  // No HDF5 clean-up at exit: after a failed write (a full disk) libhdf5 1.10 keeps a file it could not close and
  // crashes closing it again at exit. Every file ctab opens is closed by its reader or writer before the exit.
  H5dont_atexit();
  if (reported_unknown_command(argc, argv)) return ctab::cli::kExitUsage;
  CLI::App app{"ctab - wheel-rail contact tables: MIM-1D normal contact, table generation, real-time lookup"};
  app.set_version_flag("--version", ctab::cli::version_text());
  app.require_subcommand(1);
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("ctab: error: ") + e.what() + "\nRun with --help for more information.\n";
  });
  const std::vector<ctab::cli::Command> commands = add_commands(app, argc, argv);
  return ctab::cli::finish_standard_output(run(app, commands, argc, argv));
}
