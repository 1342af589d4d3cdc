// ctab: wheel-rail contact tables. One executable, subcommands; exceptions stop here and become exit codes
// (exit_codes.hpp): 0 success, 2 usage or input error, 3 I/O failure, 4 failed solves or table cases.
#include <CLI/CLI.hpp>
#include <hdf5.h>

#include <csignal>
#include <cstring>
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
  CLI::App app{"ctab - wheel-rail contact tables: MIM-1D normal contact, table generation, real-time lookup"};
  app.set_version_flag("--version", ctab::cli::version_text());
  app.require_subcommand(1);
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("ctab: error: ") + e.what() + "\nRun with --help for more information.\n";
  });
  const std::vector<ctab::cli::Command> commands = add_commands(app, argc, argv);
  return ctab::cli::finish_standard_output(run(app, commands, argc, argv));
}
