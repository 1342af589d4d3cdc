// SPDX-License-Identifier: Apache-2.0
// Set-up of a table sweep (table_generator.hpp): the profiles loaded and placed on the track, the solver options
// from the config, the process-wide tables built, and the plan of what the sweep solves.
#include <algorithm>
#include <cmath>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/strip_kernel.hpp"
#include "ctab/core/number_text.hpp"
#include "ctab/io/profile_io.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "sweep_plan.hpp"

namespace ctab::gen {

namespace {

// Mirror test of the lateral axis: nodes parsed from the same decimal text agree to round-off, far inside 1e-9 of
// the span; the absolute floor lets an axis of a single zero node count as symmetric.
constexpr double kMirrorTolerance = 1e-9;
constexpr double kMirrorFloor_m = 1e-15;

ProfileTable load_checked(const TableConfig& config, const std::string& spec, ProfileRole role, const char* key,
                          ProfileSmoothing& smoothing) {
  ProfileReadOptions read;
  read.smoothing = role == ProfileRole::Wheel ? config.wheel_smoothing : config.rail_smoothing;
  read.inclination = config.inclination;
  try {
    return load_profile(spec, role, read, smoothing);
  } catch (const InputError& e) {
    throw SweepSetupError(config, key, e.what());
  }
}

void check_strip_width(const TableConfig& config) {
  if (config.strip_width_m >= kMinStripWidth_m && config.strip_width_m <= kMaxStripWidth_m) return;
  throw SweepSetupError(config, "solver.strip_width_m",
                        "expected a strip width in [" + number_text(kMinStripWidth_m) + ", " +
                            number_text(kMaxStripWidth_m) + "] m, got " + number_text(config.strip_width_m));
}

}  // namespace

namespace detail {

bool symmetric_axis(const std::vector<double>& dy_m) {
  const double span = std::max(std::abs(dy_m.front()), std::abs(dy_m.back()));
  for (std::size_t i = 0, n = dy_m.size(); i < n; ++i)
    if (std::abs(dy_m[i] + dy_m[n - 1 - i]) > kMirrorTolerance * span + kMirrorFloor_m) return false;
  return true;
}

SweepPlan make_plan(const TableConfig& config, const GeneratorInfo& info) {
  SweepPlan plan;
  plan.dy_m = config.lateral_displacement_m;
  plan.load_values = config.load_values;
  plan.mirrored = symmetric_axis(plan.dy_m);
  plan.sides = plan.mirrored ? 1 : 2;
  plan.threads = std::max(1, info.threads);
  return plan;
}

}  // namespace detail

SweepSetupError::SweepSetupError(const TableConfig& config, std::string key, std::string reason)
    : InputError(config.source, config.key_line(key), "'" + key + "': " + reason), key_(std::move(key)),
      reason_(std::move(reason)) {}

SweepSetup make_sweep_setup(const TableConfig& config) {
  check_strip_width(config);
  SweepSetup setup;
  setup.wheel = std::make_unique<const ProfileTable>(
      load_checked(config, config.wheel, ProfileRole::Wheel, "profiles.wheel", setup.wheel_smoothing));
  setup.rail = std::make_unique<const ProfileTable>(
      load_checked(config, config.rail, ProfileRole::Rail, "profiles.rail", setup.rail_smoothing));
  setup.side = std::make_unique<const SideGeometry>(place_profiles(config, *setup.wheel, *setup.rail));
  setup.E_star_Pa = effective_modulus(config.material, config.material);
  setup.options.method = config.method;
  setup.auto_tolerance = config.least_model ? config.tolerance : 0.0;
  setup.options.mim1d.strip_width_m = config.strip_width_m;  // range checked by the config
  setup.options.reference = config.reference;
  setup.options.surface = config.surface;
  setup.mode = config.mode;
  setup.load_kind = config.load_kind;
  setup.dy_axis_m = config.lateral_displacement_m;
  setup.mirrored = !setup.dy_axis_m.empty() && detail::symmetric_axis(setup.dy_axis_m);
  setup.warm_start = config.warm_start && config.method == NormalMethod::Mim1d && !config.least_model;
  (void)StripKernel::instance();  // process-wide tables are built here, not inside a parallel region
  HertzCoefficients warm_up;
  (void)hertz_coefficients_tabulated(1.0, 2.0, warm_up);
  return setup;
}

}  // namespace ctab::gen
