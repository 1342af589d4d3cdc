// SPDX-License-Identifier: Apache-2.0
#include "setup_options.hpp"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>

#include "ctab/core/number_text.hpp"
#include "ctab/io/profile_io.hpp"

namespace ctab::cli {

namespace {

// A rule on a number option: what is expected (for messages) and the test.
struct NumberRule {
  std::string expectation;
  std::function<bool(double)> accept;
};

// Parses the whole text as a number; false if it is not one.
bool parse_number(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end != text.c_str() && *end == '\0';
}

// A number check run by CLI11 on the option's text; an unparsable text is left to CLI11's conversion error.
CLI::Validator number_check(const NumberRule& rule) {
  return CLI::Validator(
      [rule](std::string& text) -> std::string {
        double value = 0.0;
        if (!parse_number(text, value) || rule.accept(value)) return {};
        return "expected " + rule.expectation + ", got " + text;
      },
      rule.expectation);
}

// A hidden alias of `main` (the short names scripts may use). Hidden CLI11 options have no name in CLI11's messages, so
// the alias checks its value itself and names itself in errors.
void add_hidden_alias(CLI::App& app, const std::string& alias, CLI::Option* main, double& target,
                      const NumberRule& rule) {
  app.add_option_function<std::string>(
         alias,
         [alias, main, &target, rule](const std::string& text) {
           if (main->count() > 0) throw CLI::ValidationError(alias, "alias of " + main->get_name() + "; give only one");
           double value = 0.0;
           if (!parse_number(text, value)) throw CLI::ValidationError(alias, "expected a number, got " + text);
           if (!rule.accept(value)) throw CLI::ValidationError(alias, "expected " + rule.expectation + ", got " + text);
           target = value;
         },
         "alias of " + main->get_name())
      ->group("");
}

NumberRule quantity_rule(const gen::QuantityRange& range) {
  return {range.expectation, [range](double v) { return range.contains(v); }};
}

}  // namespace

CLI::Validator finite_range(double min, double max, const std::string& unit) {
  return number_check({"a number in [" + gen::number_text(min) + ", " + gen::number_text(max) + "] " + unit,
                       [min, max](double v) { return std::isfinite(v) && v >= min && v <= max; }});
}

CLI::Validator finite_positive(const std::string& unit, double max) {
  const std::string bound = max < 1e300 ? " up to " + gen::number_text(max) : "";
  return number_check({"a finite number > 0" + bound + " " + unit,
                       [max](double v) { return std::isfinite(v) && v > 0.0 && v <= max; }});
}

CLI::Validator quantity_check(const gen::QuantityRange& range) { return number_check(quantity_rule(range)); }

gen::TableConfig default_table_config(const std::string& source) {
  return gen::parse_table_config(gen::kDefaultTableConfig, source);
}

namespace {

// The options one call of add_setup_options defines, in order.
using AddedOptions = std::vector<CLI::Option*>;

CLI::Option* keep(AddedOptions& added, CLI::Option* option) {
  added.push_back(option);
  return option;
}

// A smoothing option setting every setting of `into`: "auto", "auto-arcs" or a smoothing length.
void add_smoothing_option(CLI::App& app, AddedOptions& added, const std::string& name,
                          std::vector<gen::SmoothingSetting*> into, const std::string& help) {
  const NumberRule length{"\"auto\", \"auto-arcs\" or a smoothing length in [0, 0.05] m",
                          [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 0.05; }};
  keep(added, app.add_option_function<std::string>(
                     name,
                     [into, length, name](const std::string& text) {
                       gen::SmoothingSetting setting;
                       if (const auto automatic = gen::automatic_smoothing(text)) {
                         setting = *automatic;
                       } else {
                         double value = 0.0;
                         if (!parse_number(text, value) || !length.accept(value))
                           throw CLI::ValidationError(name, "expected " + length.expectation + ", got " + text);
                         setting.automatic = false;
                         setting.length_m = value;
                       }
                       for (gen::SmoothingSetting* s : into) *s = setting;
                     },
                     help)
                  ->default_str(gen::smoothing_text(*into.front())));
}

void add_profile_options(CLI::App& app, gen::TableConfig& c, AddedOptions& added) {
  keep(added,
       app.add_option("--wheel", c.wheel, "wheel profile: S1002 (built in) or a file (.prw, .whl, 2-column y z in mm)")
           ->capture_default_str());
  keep(added, app.add_option("--rail", c.rail,
                             "rail profile: UIC60 (built-in 60E1) or a file (.prr, .ban, 2-column y z in mm)")
                  ->capture_default_str());
  keep(added,
       app.add_option("--inclination", c.inclination_text, "rail inclination: 1/40, 1/30, 1/20 or 0 (already inclined)")
           ->capture_default_str());
  // --smoothing sets both; --wheel-smoothing and --rail-smoothing, defined after it, run after it and override.
  add_smoothing_option(
      app, added, "--smoothing", {&c.wheel_smoothing, &c.rail_smoothing},
      "smoothing of point profiles: auto (from the points' noise: the cubic spline of 1 mm when clean, "
      "the adaptive smoother on noise; docs/method.md \"Curvature and smoothing\"), auto-arcs (the same for profiles "
      "drawn "
      "as circular arcs and straight lines, such as new rails: keeps their curvature jumps) "
      "or the cubic spline of a length [m] (0 interpolates)");
  add_smoothing_option(app, added, "--wheel-smoothing", {&c.wheel_smoothing}, "the wheel's alone (as --smoothing)");
  add_smoothing_option(app, added, "--rail-smoothing", {&c.rail_smoothing}, "the rail's alone (as --smoothing)");
}

void add_track_options(CLI::App& app, gen::TableConfig& c, AddedOptions& added) {
  keep(added, app.add_option("--gauge", c.track.gauge_m, "track gauge [m]")
                  ->capture_default_str()
                  ->check(finite_positive("m", 3.0)));
  keep(added,
       app.add_option("--flange-back-distance", c.track.flange_back_distance_m, "wheelset flange-back distance [m]")
           ->capture_default_str()
           ->check(finite_positive("m", 3.0)));
  keep(added, app.add_option("--nominal-radius", c.track.nominal_radius_m, "nominal rolling radius [m]")
                  ->capture_default_str()
                  ->check(finite_positive("m", 2.0)));
}

void add_mode_option(CLI::App& app, gen::TableConfig& c, AddedOptions& added) {
  keep(added, app.add_option_function<std::string>(
                     "--mode",
                     [&c](const std::string& mode) {
                       c.mode = mode == "wheel" ? gen::ContactMode::SingleWheel : gen::ContactMode::Wheelset;
                     },
                     "wheelset (rigid roll, both wheels touching) or wheel (single wheel, roll 0)")
                  ->check(CLI::IsMember({"wheelset", "wheel"}))
                  ->default_str(c.mode == gen::ContactMode::Wheelset ? "wheelset" : "wheel"));
}

// Method, tolerance and strip width of the normal-contact solve.
void add_method_options(CLI::App& app, gen::TableConfig& c, AddedOptions& added) {
  keep(added, app.add_option_function<std::string>(
                     "--method",
                     [&c](const std::string& method) {
                       c.least_model = method == "auto";
                       c.method = c.least_model ? gen::NormalMethod::Mim1d : *gen::parse_contact_method(method);
                     },
                     "normal-contact method (docs/method.md \"The method ladder\"): " + gen::contact_method_choices() +
                         ", or auto (the least model: MIM-1D at the coarsest strip width within --tolerance)")
                  ->check(CLI::IsMember({"hertz", "kp", "analyn", "mim1d", "bem2d", "auto"}))
                  ->default_str(gen::method_name(c.method)));
  keep(added,
       app.add_option("--tolerance", c.tolerance, "--method auto: relative error tolerance in area and max pressure")
           ->capture_default_str()
           ->check(finite_range(1e-6, 0.5, "")));
  keep(added, app.add_option("--strip-width", c.strip_width_m, "strip width 2b [m]")
                  ->capture_default_str()
                  ->check(finite_range(kMinStripWidth_m, kMaxStripWidth_m, "m")));
}

// --reference-point and --reference-angle each change one half of the rule, on top of a config's, in either order;
// CONTACT's reference point with the tangent is refused whichever comes second.
[[noreturn]] void refuse_centre_with_tangent() {
  throw CLI::ValidationError("--reference-angle", "tangent needs --reference-point deepest: CONTACT's reference point "
                                                  "(interpenetration-centre) takes CONTACT's reference angle");
}

void set_reference_point(gen::TableConfig& c, bool interpenetration_centre) {
  const bool tangent = c.reference == gen::ReferenceRule::DeepestTangent;
  if (interpenetration_centre && tangent) refuse_centre_with_tangent();
  if (interpenetration_centre) c.reference = gen::ReferenceRule::InterpenetrationCentre;
  else if (!tangent) c.reference = gen::ReferenceRule::DeepestContactsAngle;
}

void set_reference_angle(gen::TableConfig& c, gen::ReferenceAngle angle) {
  const bool centre = c.reference == gen::ReferenceRule::InterpenetrationCentre;
  if (angle == gen::ReferenceAngle::Tangent && centre) refuse_centre_with_tangent();
  if (angle == gen::ReferenceAngle::Tangent) c.reference = gen::ReferenceRule::DeepestTangent;
  else if (!centre) c.reference = gen::ReferenceRule::DeepestContactsAngle;
}

// Where a patch's contact plane or surface lies: reference point, reference angle, planar or conformal.
void add_contact_surface_options(CLI::App& app, gen::TableConfig& c, AddedOptions& added) {
  keep(added,
       app.add_option_function<std::string>(
              "--reference-point",
              [&c](const std::string& name) { set_reference_point(c, *gen::parse_reference_point(name)); },
              "contact plane of a patch: deepest (rigid deepest point) or interpenetration-centre (CONTACT's rule; "
              "docs/validation.md \"Flange and flank\")")
           ->check(CLI::IsMember({std::string(gen::kReferencePointDeepest), std::string(gen::kReferencePointCentre)}))
           ->default_str(std::string(gen::reference_point_name(c.reference))));
  keep(added,
       app.add_option_function<std::string>(
              "--reference-angle",
              [&c](const std::string& name) { set_reference_angle(c, *gen::parse_reference_angle(name)); },
              "inclination of a patch's contact plane: tangent (the rail's at the reference point) or "
              "interpenetration-mean (CONTACT's: the mean over the interpenetration region; "
              "docs/validation.md \"Flange and flank\")")
           ->check(CLI::IsMember({std::string(gen::kReferenceAngleTangent), std::string(gen::kReferenceAngleMean)}))
           ->default_str(std::string(gen::kReferenceAngleMean)));
  keep(added,
       app.add_option_function<std::string>(
              "--surface", [&c](const std::string& name) { c.surface = *gen::parse_contact_surface(name); },
              "contact surface of a patch: conformal (curved surface midway between the profiles, one normal per "
              "strip, CONTACT's conformal approach) or planar (one plane; docs/validation.md \"Flange and flank\")")
           ->check(CLI::IsMember({std::string(gen::kSurfacePlanar), std::string(gen::kSurfaceConformal)}))
           ->default_str(std::string(gen::surface_name(c.surface))));
}

void add_material_options(CLI::App& app, gen::TableConfig& c, AddedOptions& added) {
  const NumberRule youngs = quantity_rule(gen::kYoungsModulusRange_Pa);
  const NumberRule poisson{"a Poisson's ratio in (-1, 0.5]", [](double v) { return v > -1.0 && v <= 0.5; }};
  CLI::Option* E = keep(added, app.add_option("--youngs-modulus", c.material.youngs_modulus_Pa,
                                              "Young's modulus of both bodies [Pa]")
                                   ->capture_default_str()
                                   ->check(number_check(youngs)));
  CLI::Option* nu =
      keep(added, app.add_option("--poisson-ratio", c.material.poisson_ratio, "Poisson's ratio of both bodies [-]")
                      ->capture_default_str()
                      ->check(number_check(poisson)));
  add_hidden_alias(app, "--E", E, c.material.youngs_modulus_Pa, youngs);
  add_hidden_alias(app, "--nu", nu, c.material.poisson_ratio, poisson);
}

}  // namespace

std::vector<CLI::Option*> add_setup_options(CLI::App& app, gen::TableConfig& c, unsigned groups) {
  AddedOptions added;
  if (groups & kProfiles) add_profile_options(app, c, added);
  if (groups & kTrack) add_track_options(app, c, added);
  if (groups & kMode) add_mode_option(app, c, added);
  if (groups & kSolver) {
    add_method_options(app, c, added);
    add_contact_surface_options(app, c, added);
  }
  if (groups & kMaterial) add_material_options(app, c, added);
  return added;
}

void finish_setup_options(gen::TableConfig& config) {
  config.inclination = gen::parse_inclination(config.inclination_text, "--inclination", 0, "");
}

int sweep_threads(int requested) {
  if (requested > 0) return requested;
  const int available = omp_get_max_threads();
  if (available <= kMaxThreads) return available;
  std::fprintf(stderr, "ctab: warning: OMP_NUM_THREADS asks for %d threads; using %d\n", available, kMaxThreads);
  return kMaxThreads;
}

CLI::Option* add_threads_option(CLI::App& app, int& threads) {
  return app.add_option("--threads", threads, "OpenMP threads (0: OMP_NUM_THREADS or all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, kMaxThreads));
}

}  // namespace ctab::cli
