// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The one option model of `solve`, `geometry` and `generate`: the wheel-rail set-up options fill the same
//! gen::TableConfig that a TOML config fills, starting from the embedded default config (gen::kDefaultTableConfig),
//! so that every subcommand and every config share one set of defaults (S1002 on UIC60 1:40, Manchester set-up,
//! wheelset mode, MIM-1D at 0.2 mm strips, steel). `--help` shows each default.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"

namespace ctab::cli {

//! Strip widths outside [gen::kMinStripWidth_m, gen::kMaxStripWidth_m] are input errors (the sweep's range).
using gen::kMaxStripWidth_m;
using gen::kMinStripWidth_m;
//! An explicit --threads above this is an input error; a larger OMP_NUM_THREADS is clamped to it (thousands of
//! threads exhaust memory and crashed the OpenMP runtime; no machine this targets has more cores).
inline constexpr int kMaxThreads = 1024;

//! Groups of set-up options a subcommand takes.
enum SetupGroup : unsigned {
  kProfiles = 1u,  //!< --wheel, --rail, --inclination, --smoothing
  kTrack = 2u,     //!< --gauge, --flange-back-distance, --nominal-radius
  kMode = 4u,      //!< --mode wheelset|wheel
  kSolver = 8u,    //!< --method, --strip-width, --reference-point, --reference-angle, --surface
  kMaterial = 16u  //!< --youngs-modulus, --poisson-ratio (hidden aliases --E, --nu)
};

//! Source name of a config built from command-line options: its errors name the option, not a file.
inline constexpr const char* kCommandLineSource = "command line";

//! The embedded default config, parsed (the single source of defaults), with `source` as its name.
[[nodiscard]] gen::TableConfig default_table_config(const std::string& source = kCommandLineSource);

//! Registers the options of `groups` on `app`, writing into `config` (whose current values are the defaults shown
//! in --help). Returns the visible options, e.g. for `excludes` (the hidden aliases --E and --nu are not among them).
//! Values are range-checked at parse time (exit code 2).
std::vector<CLI::Option*> add_setup_options(CLI::App& app, gen::TableConfig& config, unsigned groups);

//! After parsing: converts the inclination text given on the command line. Throws InputError naming the option.
void finish_setup_options(gen::TableConfig& config);

//! A CLI11 check: a finite number in [min, max] (NaN and infinities fail), with the unit in the message.
[[nodiscard]] CLI::Validator finite_range(double min, double max, const std::string& unit);
//! A CLI11 check: a value in the quantity's range, the same check a config makes (table_config.hpp).
[[nodiscard]] CLI::Validator quantity_check(const gen::QuantityRange& range);
//! A CLI11 check: a finite number > 0 (at most `max`).
[[nodiscard]] CLI::Validator finite_positive(const std::string& unit, double max = 1e300);

//! OpenMP threads for a sweep: `requested` > 0 as given (at most kMaxThreads, checked at parse time), 0 for the
//! OpenMP default (OMP_NUM_THREADS or the cores), clamped to kMaxThreads with a one-line warning on stderr.
[[nodiscard]] int sweep_threads(int requested);
//! Registers --threads on `app`.
CLI::Option* add_threads_option(CLI::App& app, int& threads);

}  // namespace ctab::cli
