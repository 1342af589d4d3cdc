// SPDX-License-Identifier: Apache-2.0
// `ctab geometry`: rigid contact geometry versus lateral shift as CSV, contact jumps, equivalent conicity.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/wheelrail/contact_geometry_sweep.hpp"
#include "setup_options.hpp"
#include "table_case.hpp"

namespace ctab::cli {

namespace {

constexpr std::size_t kMaxRows = 1000000;          // at most 10^6 shifts
constexpr double kMaxConicityAmplitude_m = 20e-3;  // EN 15302 amplitudes are a few mm
constexpr double kConicityStep_m = 0.01e-3;        // fine sweep of the equivalent conicity

struct GeometryOptions {
  gen::TableConfig setup = default_table_config();
  double dy_min_m = -12e-3, dy_max_m = 12e-3, dy_step_m = 0.1e-3;
  double conicity_amplitude_m = 3e-3;
};

std::size_t row_count(const GeometryOptions& o) {
  if (o.dy_max_m < o.dy_min_m) throw gen::InputError("--dy-max", 0, "must not be below --dy-min (empty range)");
  const double steps = std::floor((o.dy_max_m - o.dy_min_m) / o.dy_step_m + 1e-9);
  if (!(steps < static_cast<double>(kMaxRows)))
    throw gen::InputError("--dy-step", 0,
                          "gives more than 10^6 shifts between --dy-min and --dy-max; use a larger step");
  return static_cast<std::size_t>(steps) + 1;
}

int run_geometry(GeometryOptions o) {
  const std::size_t count = row_count(o);
  finish_setup_options(o.setup);
  const gen::SweepSetup setup = make_case_setup(o.setup);
  const gen::SideGeometry& side = *setup.side;
  std::vector<gen::RigidContactRow> rows;
  for (std::size_t i = 0; i < count; ++i)
    rows.push_back(gen::rigid_contact(side, side, o.dy_min_m + o.dy_step_m * static_cast<double>(i), o.setup.mode));
  // EN 15302 equivalent conicity from a fine wheelset sweep on [0, amplitude].
  std::vector<double> ys, delta_r;
  for (double y = 0.0; y <= o.conicity_amplitude_m + 0.5 * kConicityStep_m; y += kConicityStep_m) {
    ys.push_back(y);
    delta_r.push_back(gen::rigid_contact(side, side, y, gen::ContactMode::Wheelset).rolling_radius_difference_m);
  }
  const double conicity = gen::equivalent_conicity(ys, delta_r, o.conicity_amplitude_m);
  std::printf("# ctab geometry: wheel %s, rail %s, inclination %s, mode %s\n", o.setup.wheel.c_str(),
              o.setup.rail.c_str(), o.setup.inclination_text.c_str(),
              o.setup.mode == gen::ContactMode::Wheelset ? "wheelset" : "wheel");
  std::printf("# equivalent conicity (EN 15302, amplitude %.1f mm): %.4f\n", o.conicity_amplitude_m * 1e3, conicity);
  for (const auto& jump : gen::find_contact_jumps(rows, std::max(1e-3, 10.0 * o.dy_step_m)))
    std::printf("# contact jump (%s wheel) between dy = %.2f and %.2f mm: wheel y %.2f -> %.2f mm\n",
                jump.right_side ? "right" : "left", jump.dy_before_m * 1e3, jump.dy_after_m * 1e3,
                jump.y_wheel_before_m * 1e3, jump.y_wheel_after_m * 1e3);
  std::printf(
      "dy_m,roll_rad,right_y_wheel_m,right_y_rail_m,right_contact_angle_rad,right_rolling_radius_m,"
      "left_y_wheel_m,left_y_rail_m,left_contact_angle_rad,left_rolling_radius_m,rolling_radius_difference_m\n");
  for (const auto& r : rows)
    std::printf("%.6e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e\n", r.dy_m, r.roll_rad, r.right.wheel_s_m,
                r.right.rail_y_m, r.right.contact_angle_rad, r.right.rolling_radius_m, r.left.wheel_s_m,
                r.left.rail_y_m, r.left.contact_angle_rad, r.left.rolling_radius_m, r.rolling_radius_difference_m);
  return 0;
}

}  // namespace

Command add_geometry_command(CLI::App& parent) {
  auto o = std::make_shared<GeometryOptions>();
  CLI::App* app =
      parent.add_subcommand("geometry",
                            "Rigid contact geometry versus lateral shift (CSV), jumps, equivalent conicity");
  add_setup_options(*app, o->setup, kProfiles | kTrack | kMode);
  app->add_option("--dy-min", o->dy_min_m, "first lateral shift [m]")
      ->capture_default_str()
      ->check(finite_range(-1.0, 1.0, "m"));
  app->add_option("--dy-max", o->dy_max_m, "last lateral shift [m]")
      ->capture_default_str()
      ->check(finite_range(-1.0, 1.0, "m"));
  app->add_option("--dy-step", o->dy_step_m, "step [m] (at most 10^6 shifts)")
      ->capture_default_str()
      ->check(finite_positive("m"));
  app->add_option("--conicity-amplitude", o->conicity_amplitude_m, "amplitude of the equivalent conicity [m]")
      ->capture_default_str()
      ->check(finite_positive("m", kMaxConicityAmplitude_m));
  return {app, [o] { return run_geometry(*o); }};
}

}  // namespace ctab::cli
