// ctab: wheel-rail contact tables. One executable, subcommands; exceptions stop here.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <vector>

#include "commands.hpp"
#include "version.hpp"
#include "ctab/contact/error.hpp"


int main(int argc, char** argv) {
  CLI::App app{"ctab - wheel-rail contact tables: MIM-1D normal contact, table generation, real-time lookup"};
  app.set_version_flag("--version", std::string("ctab ") + CTAB_VERSION + " (" + CTAB_GIT_COMMIT + ")");
  app.require_subcommand(1);
  const std::vector<ctab::cli::Command> commands = {ctab::cli::add_generate_command(app),
                                                    ctab::cli::add_inspect_command(app),
                                                    ctab::cli::add_solve_command(app),
                                                    ctab::cli::add_paper_cases_command(app),
                                                    ctab::cli::add_geometry_command(app),
                                                    ctab::cli::add_bench_command(app),
                                                    ctab::cli::add_export_command(app),
                                                    ctab::cli::add_query_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (const auto& command : commands)
      if (command.app->parsed()) return command.run();
  } catch (const ctab::gen::Error& e) {
    std::cerr << "ctab: error: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ctab: internal error: " << e.what() << '\n';
    return 3;
  }
  return 1;
}
