// SPDX-License-Identifier: Apache-2.0
// `ctab config --print-default` prints the embedded default config; `ctab config FILE.toml` checks a config.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/sweep/table_config.hpp"

namespace ctab::cli {

namespace {

struct ConfigOptions {
  std::string path;
  bool print_default = false;
};

int run_config(const ConfigOptions& o) {
  if (o.print_default) {
    std::fputs(gen::kDefaultTableConfig, stdout);
    return 0;
  }
  if (o.path.empty()) throw gen::InputError("config", 0, "give --print-default or a config FILE.toml to check");
  const gen::TableConfig config = gen::read_table_config(o.path);
  gen::require_table_axes(config);
  std::printf("%s: valid; %zu lateral shifts x %zu %s, %s mode, %s\n", o.path.c_str(),
              config.lateral_displacement_m.size(), config.load_values.size(), gen::load_axis_name(config.load_kind),
              config.mode == gen::ContactMode::Wheelset ? "wheelset" : "wheel",
              config.least_model ? "auto" : gen::method_name(config.method));
  return 0;
}

}  // namespace

Command add_config_command(CLI::App& parent) {
  auto o = std::make_shared<ConfigOptions>();
  CLI::App* app = parent.add_subcommand("config", "Print the embedded default table config, or check a config file");
  CLI::Option* print = app->add_flag("--print-default", o->print_default, "print the default config (TOML) to stdout");
  app->add_option("file", o->path, "config to check (TOML)")->excludes(print);
  return {app, [o] { return run_config(*o); }};
}

}  // namespace ctab::cli
