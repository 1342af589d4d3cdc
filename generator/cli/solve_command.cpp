// SPDX-License-Identifier: Apache-2.0
// `ctab solve`: one normal-contact problem: a gap profile (--gap), a wheel-rail case from options (--dy with the
// set-up options) or one case of a table config (--config FILE --dy [--load]), solved as the generator does.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include "commands.hpp"
#include "creep_output.hpp"
#include "ctab/core/error.hpp"
#include "ctab/contact/normal_contact.hpp"
#include "ctab/contact/strip_grid.hpp"
#include "ctab/io/gap_csv.hpp"
#include "solution_json.hpp"
#include "exit_codes.hpp"
#include "setup_options.hpp"
#include "solve_output.hpp"
#include "table_case.hpp"

namespace ctab::cli {

namespace {

struct SolveOptions {
  gen::TableConfig setup = default_table_config();
  std::string gap_path, config_path;
  std::optional<double> approach_m, load, normal_load_N, vertical_load_N, dy_m;
  std::string curvature = "smoothed", update = "newton", side;
  bool json = false;
  bool wheelrail_given = false;
  CreepOptions creep;
};

std::string millimetres(double metres) {
  std::ostringstream text;
  text << metres * 1e3 << " mm";
  return text.str();
}

void apply_mim1d_extras(const SolveOptions& o, gen::Mim1dOptions& options) {
  options.curvature.treatment =
      o.curvature == "pointwise" ? gen::CurvatureTreatment::Pointwise : gen::CurvatureTreatment::ContactSmoothed;
  options.update = o.update == "fixed-point" ? gen::Mim1dUpdate::FixedPoint : gen::Mim1dUpdate::Newton;
}

int solve_gap(const SolveOptions& o) {
  if (o.normal_load_N || o.vertical_load_N || o.dy_m)
    throw gen::InputError("solve", 0, "--normal-load, --vertical-load and --dy belong to wheel-rail cases, not --gap");
  if (o.approach_m.has_value() == o.load.has_value())
    throw gen::InputError("solve", 0, "give exactly one of --approach METRES or --load NEWTONS");
  const gen::GapProfile gap = gen::read_gap_csv(o.gap_path);
  const double E_star = gen::effective_modulus(o.setup.material, o.setup.material);
  // Set-up errors of the strip rungs (too many strips, too few in the gap's range) as messages, not statuses.
  if (o.setup.method != gen::NormalMethod::Hertz) (void)gen::make_strip_grid(gap, o.setup.strip_width_m);
  gen::MethodOptions options{o.setup.method, E_star, o.setup.strip_width_m, {}};
  apply_mim1d_extras(o, options.mim1d);
  const gen::NormalSolution solution = gen::solve_normal_contact(gap, options,
                                                                 o.approach_m ? gen::Loading::approach(*o.approach_m)
                                                                              : gen::Loading::normal_force(*o.load));
  if (o.json) std::cout << gen::to_json(solution).dump(1) << '\n';
  else print_summary(solution);
  if (gen::is_success(solution.status)) return kExitSuccess;
  std::fprintf(stderr, "ctab solve: %s, %s %g: %s\n", o.gap_path.c_str(), o.approach_m ? "approach_m" : "load_N",
               o.approach_m ? *o.approach_m : *o.load, gen::status_name(solution.status));
  return kExitCaseFailed;
}

// The config and the load value of a wheel-rail case: from --config, or from the set-up options.
gen::TableConfig wheelrail_config(const SolveOptions& o, double& load_value) {
  if (!o.config_path.empty()) {
    gen::TableConfig config = gen::read_table_config(o.config_path);
    const char* axis = gen::load_axis_name(config.load_kind);
    if (o.load) load_value = *o.load;
    else if (config.load_values.size() == 1) load_value = config.load_values.front();
    else
      throw gen::InputError("--load", 0,
                            o.config_path + " has a " + axis + " axis of " + std::to_string(config.load_values.size()) +
                                " values: give --load VALUE");
    if (config.load_kind == gen::LoadKind::Approach && !gen::kApproachRange_m.contains(load_value))
      throw gen::InputError("--load", 0,
                            std::string("expected ") + gen::kApproachRange_m.expectation + " (" + axis + " config)");
    return config;
  }
  if (o.load)
    throw gen::InputError("--load", 0,
                          "wheel-rail cases take --normal-load, --vertical-load or --approach "
                          "(or --load with --config)");
  const int loads = o.approach_m.has_value() + o.normal_load_N.has_value() + o.vertical_load_N.has_value();
  if (loads != 1)
    throw gen::InputError("solve", 0, "give exactly one of --normal-load N, --vertical-load N or --approach METRES");
  gen::TableConfig config = o.setup;
  finish_setup_options(config);
  config.load_kind = o.approach_m      ? gen::LoadKind::Approach
                     : o.normal_load_N ? gen::LoadKind::NormalForce
                                       : gen::LoadKind::VerticalForce;
  load_value = o.approach_m ? *o.approach_m : o.normal_load_N ? *o.normal_load_N : *o.vertical_load_N;
  return config;
}

// The creep forces of every solved patch, into each patch's JSON ("creep"), from its own strips.
void add_creep(nlohmann::json& json, const ctab_creep_input& input) {
  for (const char* wheel : {"right", "left"})
    if (json.contains(wheel))
      for (auto& patch : json[wheel]["patches"]) {
        gen::ContactPatch p;
        p.normal_force_N = patch["normal_force_N"].get<double>();
        p.plane_angle_rad = patch["plane_angle_rad"].get<double>();
        for (const auto& strip : patch["strips"])
          p.strips.push_back({strip["s_m"].get<double>(), strip["y_rail_m"].get<double>(),
                              strip["half_length_m"].get<double>(), strip["p0_Pa"].get<double>()});
        patch["creep"] = solved_patch_creep(p, input);
      }
}

void print_creep_lines(const nlohmann::json& json) {
  for (const char* wheel : {"right", "left"})
    if (json.contains(wheel))
      for (const auto& patch : json[wheel]["patches"])
        if (patch.contains("creep")) {
          std::printf("  %s %s patch ", wheel, patch["zone"].get<std::string>().c_str());
          print_creep("", patch["creep"]);
        }
}

int solve_wheelrail(const SolveOptions& o) {
  if (!o.dy_m) throw gen::InputError("--dy", 0, "wheel-rail cases need the lateral shift --dy METRES");
  double load_value = 0.0;
  const gen::TableConfig config = wheelrail_config(o, load_value);
  gen::SweepSetup setup = make_case_setup(config);
  if (o.config_path.empty()) apply_mim1d_extras(o, setup.options.mim1d);
  const gen::WheelSelection wheels{o.side != "left", o.side != "right"};
  const gen::CaseSolution solution = gen::solve_table_case(setup, *o.dy_m, load_value, wheels);
  // A shift that puts a wheel beside its rail is a typing error, not a case outcome (level when the roll failed).
  const double roll_rad = solution.roll.converged ? solution.roll.roll_rad : 0.0;
  for (std::size_t wheel = 0; wheel < wheels.size(); ++wheel)
    if (wheels[wheel] && !wheel_over_rail(setup, wheel, *o.dy_m, roll_rad))
      throw gen::InputError("--dy", 0,
                            std::string("the ") + (wheel == 0 ? "right" : "left") + " wheel is off its rail at dy = " +
                                millimetres(*o.dy_m) + " (no wheel point above the rail profile)");
  nlohmann::json json = to_json(config, solution);
  if (o.creep.wanted()) add_creep(json, o.creep.input(config.material));
  if (o.json) {
    add_smoothing(json, setup);
    std::cout << json.dump(1) << '\n';
  } else {
    print_summary(config, solution);
    print_creep_lines(json);
  }
  return report_failures(config, setup, solution) ? kExitCaseFailed : kExitSuccess;
}

int run_solve(const SolveOptions& o) {
  check_creep_options(o.creep);
  if (!o.gap_path.empty()) {
    if (o.creep.wanted()) throw gen::InputError("--creepage", 0, "creep forces need a wheel-rail case (--dy), not --gap");
    if (o.wheelrail_given)
      throw gen::InputError("solve", 0, "give either --gap FILE or a wheel-rail case (--dy), not both");
    return solve_gap(o);
  }
  if (!o.wheelrail_given)
    throw gen::InputError("solve", 0,
                          "give --gap FILE, a wheel-rail case (--dy METRES with a load) or --config FILE --dy METRES");
  return solve_wheelrail(o);
}

}  // namespace

Command add_solve_command(CLI::App& parent) {
  auto o = std::make_shared<SolveOptions>();
  CLI::App* app = parent.add_subcommand(
      "solve", "Solve one normal-contact problem: a gap profile, a wheel-rail case, or one case of a table config");
  CLI::Option* gap = app->add_option("--gap", o->gap_path, "CSV with columns y_m,h_m,A_per_m,B_per_m");
  CLI::Option* config = app->add_option("--config", o->config_path,
                                        "table config (TOML): solve its case at --dy [and --load] as `generate` does "
                                        "(no set-up options with it)");
  const auto load_check = quantity_check(gen::kLoadRange_N);
  CLI::Option* approach = app->add_option("--approach", o->approach_m, "prescribed approach [m] (wheel-rail: vertical)")
                              ->check(quantity_check(gen::kApproachRange_m));
  app->add_option("--load", o->load, "gap: normal load [N]; with --config: the value on its load axis [N or m]")
      ->check(load_check);
  CLI::Option* normal =
      app->add_option("--normal-load", o->normal_load_N, "wheel-rail: total normal force [N]")->check(load_check);
  CLI::Option* vertical =
      app->add_option("--vertical-load", o->vertical_load_N, "wheel-rail: vertical wheel load [N]")->check(load_check);
  app->add_option("--dy", o->dy_m,
                  "wheel-rail: lateral shift of the wheelset [m], + moves the right flange to its rail")
      ->check(finite_range(-1.0, 1.0, "m"));
  app->add_option("--side", o->side, "wheel-rail: solve only the right or the left wheel (default: both)")
      ->check(CLI::IsMember({"right", "left"}));
  std::vector<CLI::Option*> setup = add_setup_options(*app, o->setup, kProfiles | kTrack | kMode | kSolver | kMaterial);
  setup.push_back(app->add_option("--curvature", o->curvature, "lateral curvature in Eq. 26: smoothed or pointwise")
                      ->capture_default_str()
                      ->check(CLI::IsMember({"smoothed", "pointwise"})));
  setup.push_back(app->add_option("--update", o->update, "MIM-1D update: newton or fixed-point (paper Figure 3)")
                      ->capture_default_str()
                      ->check(CLI::IsMember({"newton", "fixed-point"})));
  for (CLI::Option* other : {gap, approach, normal, vertical}) setup.push_back(other);
  for (const char* alias : {"--E", "--nu"}) setup.push_back(app->get_option(alias));
  app->add_flag("--json", o->json, "print one JSON object");
  add_creep_options(*app, o->creep);
  // --config excludes the set-up options (checked here rather than with CLI11's excludes, which clutters --help).
  app->callback([app, o, config, setup] {
    for (const CLI::Option* other : setup)
      if (config->count() > 0 && other->count() > 0) {
        const std::string name = other->get_name().empty() ? "--" + other->get_single_name() : other->get_name();
        throw CLI::ExcludesError("--config", name);  // hidden aliases have no name in CLI11's messages
      }
    o->wheelrail_given = app->count("--wheel") + app->count("--rail") + app->count("--dy") + app->count("--config") > 0;
  });
  return {app, [o] { return run_solve(*o); }};
}

}  // namespace ctab::cli
