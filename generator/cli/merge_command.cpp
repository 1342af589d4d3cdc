// SPDX-License-Identifier: Apache-2.0
// `ctab merge SHARD.h5... -o TABLE.h5`: joins the shard files of `ctab generate --shard K/N` into the table a
// single run gives (generator/sweep/include/ctab/sweep/table_shard.hpp).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/sweep/table_shard.hpp"
#include "exit_codes.hpp"
#include "isolated_read.hpp"
#include "output_guard.hpp"
#include "table_output.hpp"

namespace ctab::cli {

namespace {

struct MergeOptions {
  std::vector<std::string> shards;
  std::string output;
  bool force = false;
  bool quiet = false;
};

// In a child process (isolated_read.hpp): the shards may be HDF5 files from anywhere.
int merge_files(const MergeOptions& o, IsolatedChild& child) {
  std::vector<gen::ShardFile> shards;
  for (const std::string& path : o.shards) {
    gen::ShardFile shard{path, {}};
    child.reading(path);
    if (const tables::TableResult read = tables::read_table(path, shard.table); !read.ok())
      throw gen::InputError(path, 0, "cannot be read as a shard: " + read.message);
    shards.push_back(std::move(shard));
  }
  child.trusted_from_here();
  const tables::Table table = gen::merge_shards(std::move(shards));
  const InterruptCleanup cleanup(o.output);
  write_table_checked(table, o.output);
  std::size_t failed = 0;
  for (const auto s : table.status) failed += tables::is_success(s) ? 0u : 1u;
  if (!o.quiet)
    std::printf("ctab merge: %zu shards -> %s: %zu lateral shifts x %zu %s; %zu contact jumps\n", o.shards.size(),
                o.output.c_str(), table.n_dy(), table.n_second(), table.second_axis_name.c_str(), table.jumps.size());
  if (failed > 0)
    std::fprintf(stderr, "ctab merge: %zu of %zu wheel cases failed; %s is written, its status dataset says which\n",
                 failed, table.status.size(), o.output.c_str());
  return failed > 0 ? kExitCaseFailed : kExitSuccess;
}

int run_merge(const MergeOptions& o) {
  check_output_path(o.output, o.shards, OutputKind::Table, o.force);
  return run_isolated([&](IsolatedChild& child) { return merge_files(o, child); }).exit_code;
}

}  // namespace

Command add_merge_command(CLI::App& parent) {
  auto o = std::make_shared<MergeOptions>();
  CLI::App* app = parent.add_subcommand("merge", "Join the shard files of `ctab generate --shard K/N` into one table");
  app->add_option("shards", o->shards, "every shard file of one table (any order)")
      ->required()
      ->check(CLI::ExistingFile);
  app->add_option("-o,--output", o->output, "output table; replaced only on success, and only if it is a ctab table")
      ->required();
  app->add_flag("--force", o->force, "replace OUTPUT even if it is a ctab blob (never anything else)");
  app->add_flag("--quiet", o->quiet, "no summary (errors and failed cases are still reported)");
  return {app, [o] { return run_merge(*o); }};
}

}  // namespace ctab::cli
