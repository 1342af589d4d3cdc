// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Subcommands of the `ctab` executable. Each registers its options on the app and runs when selected.
#include <CLI/CLI.hpp>
#include <functional>

namespace ctab::cli {

//! A registered subcommand: `run` executes it and returns the process exit code.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command add_solve_command(CLI::App& parent);
Command add_paper_cases_command(CLI::App& parent);
Command add_bench_command(CLI::App& parent);
Command add_geometry_command(CLI::App& parent);
Command add_generate_command(CLI::App& parent);
Command add_inspect_command(CLI::App& parent);
Command add_config_command(CLI::App& parent);
Command add_export_command(CLI::App& parent);
Command add_query_command(CLI::App& parent);
Command add_merge_command(CLI::App& parent);
Command add_batch_command(CLI::App& parent);
Command add_verify_command(CLI::App& parent);
//! `ctab bench lookup`, registered on the bench subcommand.
Command add_bench_lookup_subcommand(CLI::App& bench);
//! `ctab bench accuracy`, registered on the bench subcommand.
Command add_bench_accuracy_subcommand(CLI::App& bench);
//! `ctab bench knee`, registered on the bench subcommand.
Command add_bench_knee_subcommand(CLI::App& bench);
//! `ctab bench stability`, registered on the bench subcommand.
Command add_bench_stability_subcommand(CLI::App& bench);

}  // namespace ctab::cli
