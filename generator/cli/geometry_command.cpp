// `ctab geometry`: rigid contact geometry versus lateral shift as CSV, contact jumps, equivalent conicity.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "commands.hpp"
#include "ctab/wheelrail/contact_geometry_sweep.hpp"
#include "ctab/contact/error.hpp"
#include "wheelrail_setup.hpp"

namespace ctab::cli {

namespace {

struct GeometryOptions {
  WheelRailCliOptions wheelrail;
  std::string mode = "wheelset";
  double dy_min_m = -12e-3, dy_max_m = 12e-3, dy_step_m = 0.1e-3;
  double conicity_amplitude_m = 3e-3;
};

int run_geometry(const GeometryOptions& o) {
  if (!(o.dy_step_m > 0.0) || !(o.dy_max_m >= o.dy_min_m) || !std::isfinite(o.dy_min_m) || !std::isfinite(o.dy_max_m))
    throw gen::InputError("--dy-step", 0, "expected dy-min <= dy-max and a positive step in metres");
  const WheelRailSetup setup = build_wheelrail_setup(o.wheelrail);
  const gen::ContactMode mode = o.mode == "wheel" ? gen::ContactMode::SingleWheel : gen::ContactMode::Wheelset;
  const auto count = static_cast<std::size_t>(std::floor((o.dy_max_m - o.dy_min_m) / o.dy_step_m + 1e-9)) + 1;
  std::vector<gen::RigidContactRow> rows;
  for (std::size_t i = 0; i < count; ++i)
    rows.push_back(gen::rigid_contact(*setup.right, *setup.left, o.dy_min_m + o.dy_step_m * static_cast<double>(i), mode));
  // EN 15302 equivalent conicity from a fine wheelset sweep on [0, amplitude].
  std::vector<double> ys, delta_r;
  const double fine = 0.01e-3;
  for (double y = 0.0; y <= o.conicity_amplitude_m + 0.5 * fine; y += fine) {
    ys.push_back(y);
    delta_r.push_back(gen::rigid_contact(*setup.right, *setup.left, y, gen::ContactMode::Wheelset).rolling_radius_difference_m);
  }
  const double conicity = gen::equivalent_conicity(ys, delta_r, o.conicity_amplitude_m);
  std::printf("# ctab geometry: wheel %s, rail %s, inclination %s, mode %s\n", o.wheelrail.wheel.c_str(),
              o.wheelrail.rail.c_str(), o.wheelrail.inclination.c_str(), o.mode.c_str());
  std::printf("# equivalent conicity (EN 15302, amplitude %.1f mm): %.4f\n", o.conicity_amplitude_m * 1e3, conicity);
  for (const auto& jump : gen::find_contact_jumps(rows, std::max(1e-3, 10.0 * o.dy_step_m)))
    std::printf("# contact jump (%s wheel) between dy = %.2f and %.2f mm: wheel y %.2f -> %.2f mm\n",
                jump.right_side ? "right" : "left", jump.dy_before_m * 1e3, jump.dy_after_m * 1e3,
                jump.y_wheel_before_m * 1e3, jump.y_wheel_after_m * 1e3);
  std::printf("dy_m,roll_rad,right_y_wheel_m,right_y_rail_m,right_contact_angle_rad,right_rolling_radius_m,"
              "left_y_wheel_m,left_y_rail_m,left_contact_angle_rad,left_rolling_radius_m,rolling_radius_difference_m\n");
  for (const auto& r : rows)
    std::printf("%.6e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e\n", r.dy_m, r.roll_rad, r.right.wheel_s_m,
                r.right.rail_y_m, r.right.contact_angle_rad, r.right.rolling_radius_m, r.left.wheel_s_m, r.left.rail_y_m,
                r.left.contact_angle_rad, r.left.rolling_radius_m, r.rolling_radius_difference_m);
  return 0;
}

}  // namespace

Command add_geometry_command(CLI::App& parent) {
  auto o = std::make_shared<GeometryOptions>();
  CLI::App* app = parent.add_subcommand("geometry", "Rigid contact geometry versus lateral shift (CSV), jumps, equivalent conicity");
  add_wheelrail_options(*app, o->wheelrail);
  app->add_option("--mode", o->mode, "wheelset (default: rigid roll, both wheels touching) or wheel (roll 0)")
      ->check(CLI::IsMember({"wheel", "wheelset"}));
  app->add_option("--dy-min", o->dy_min_m, "first lateral shift [m] (default -12e-3)");
  app->add_option("--dy-max", o->dy_max_m, "last lateral shift [m] (default 12e-3)");
  app->add_option("--dy-step", o->dy_step_m, "step [m] (default 0.1e-3)");
  app->add_option("--conicity-amplitude", o->conicity_amplitude_m, "amplitude of the equivalent conicity [m] (default 3e-3)");
  return {app, [o] { return run_geometry(*o); }};
}

}  // namespace ctab::cli
