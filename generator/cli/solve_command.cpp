// `ctab solve`: one normal-contact problem, either on a gap profile (--gap) or for a wheel on its rail
// (--wheel/--rail/--dy); readable summary or JSON.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "ctab/wheelrail/contact_geometry_sweep.hpp"
#include "ctab/contact/error.hpp"
#include "ctab/io/gap_csv.hpp"
#include "ctab/contact/hertz_strip.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/io/solution_json.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "wheelrail_setup.hpp"

namespace ctab::cli {

namespace {

struct SolveOptions {
  std::string gap_path;
  std::optional<double> approach_m, load_N, normal_load_N, vertical_load_N, dy_m;
  std::string method = "mim1d", curvature = "smoothed", update = "newton", mode = "wheel", side = "right";
  double strip_width_m = 0.2e-3;
  double youngs_modulus_Pa = gen::kSteel.youngs_modulus_Pa;
  double poisson_ratio = gen::kSteel.poisson_ratio;
  bool json = false;
  WheelRailCliOptions wheelrail;
  bool wheelrail_given = false;
};

void print_summary(const gen::NormalSolution& s) {
  std::printf("method %s: %s after %d iterations (%d outer), residual %.2e, %.3f ms\n", s.method.c_str(),
              gen::status_name(s.status), s.iterations, s.outer_iterations, s.residual, s.solve_time_s * 1e3);
  std::printf("approach %.6f mm, normal load %.4f kN, %zu patch(es)\n", s.approach_m * 1e3, s.normal_load_N * 1e-3,
              s.patches.size());
  for (std::size_t k = 0; k < s.patches.size(); ++k) {
    const auto& p = s.patches[k];
    std::printf("  patch %zu: y %.3f..%.3f mm, force %.4f kN, area %.4f mm^2, max pressure %.2f MPa, %zu strips\n", k + 1,
                p.y_min_m * 1e3, p.y_max_m * 1e3, p.normal_force_N * 1e-3, p.area_m2 * 1e6, p.max_pressure_Pa * 1e-6,
                p.strips.size());
  }
}

void print_summary(const gen::WheelContact& c) {
  std::printf("%s: dy %.3f mm, roll %.4f mrad, vertical approach %.5f mm, normal load %.3f kN, vertical load %.3f kN, "
              "%d iterations, %.3f ms\n",
              gen::status_name(c.status), c.dy_m * 1e3, c.roll_rad * 1e3, c.vertical_approach_m * 1e3,
              c.normal_force_N * 1e-3, c.vertical_force_N * 1e-3, c.iterations, c.solve_time_s * 1e3);
  for (const auto& p : c.patches)
    std::printf("  %s patch: rail y %.3f mm (centre of pressure %.3f), wheel y %.3f mm, angle %.3f deg, radius %.3f mm, "
                "force %.3f kN, area %.3f mm^2, max pressure %.1f MPa, approach %.5f mm\n",
                p.zone.c_str(), p.y_rail_m * 1e3, p.y_cop_rail_m * 1e3, p.y_wheel_m * 1e3, p.contact_angle_rad * 180 / M_PI,
                p.rolling_radius_m * 1e3, p.normal_force_N * 1e-3, p.area_m2 * 1e6, p.max_pressure_Pa * 1e-6, p.approach_m * 1e3);
  for (const auto& m : c.near_misses)
    if (m.gap_m < 2e-3)
      std::printf("  near miss: rail y %.3f mm, wheel y %.3f mm, gap %.4f mm\n", m.rail_y_m * 1e3, m.wheel_s_m * 1e3, m.gap_m * 1e3);
}

gen::Mim1dOptions mim1d_options(const SolveOptions& o) {
  gen::Mim1dOptions options;
  options.strip_width_m = o.strip_width_m;
  options.curvature.treatment =
      o.curvature == "pointwise" ? gen::CurvatureTreatment::Pointwise : gen::CurvatureTreatment::ContactSmoothed;
  options.update = o.update == "fixed-point" ? gen::Mim1dUpdate::FixedPoint : gen::Mim1dUpdate::Newton;
  return options;
}

int solve_gap(const SolveOptions& o, double E_star) {
  if (o.normal_load_N || o.vertical_load_N || o.dy_m)
    throw gen::InputError("solve", 0, "--normal-load, --vertical-load and --dy belong to the wheel-rail mode (--wheel/--rail)");
  if (o.approach_m.has_value() == o.load_N.has_value())
    throw gen::InputError("solve", 0, "give exactly one of --approach METRES or --load NEWTONS");
  const gen::GapProfile gap = gen::read_gap_csv(o.gap_path);
  gen::NormalSolution solution;
  if (o.method == "hertz") {
    solution = o.approach_m ? gen::solve_hertz_for_approach(gap, E_star, o.strip_width_m, *o.approach_m)
                            : gen::solve_hertz_for_load(gap, E_star, o.strip_width_m, *o.load_N);
  } else {
    gen::Mim1dSolver solver(gap, E_star, mim1d_options(o));
    solution = o.approach_m ? solver.solve_for_approach(*o.approach_m) : solver.solve_for_load(*o.load_N);
  }
  if (o.json) std::cout << gen::to_json(solution).dump(1) << '\n';
  else print_summary(solution);
  return gen::is_success(solution.status) ? 0 : 4;
}

int solve_wheelrail(const SolveOptions& o, double E_star) {
  if (o.load_N) throw gen::InputError("--load", 0, "in wheel-rail mode use --normal-load or --vertical-load");
  if (!o.dy_m) throw gen::InputError("--dy", 0, "wheel-rail mode needs the lateral shift --dy METRES");
  const int loads = o.approach_m.has_value() + o.normal_load_N.has_value() + o.vertical_load_N.has_value();
  if (loads != 1) throw gen::InputError("solve", 0, "give exactly one of --normal-load N, --vertical-load N or --approach METRES");
  const WheelRailSetup setup = build_wheelrail_setup(o.wheelrail);
  const gen::ContactMode mode = o.mode == "wheelset" ? gen::ContactMode::Wheelset : gen::ContactMode::SingleWheel;
  const double roll = mode == gen::ContactMode::Wheelset ? gen::rigid_wheelset_pose(*setup.right, *setup.left, *o.dy_m).roll_rad : 0.0;
  const bool right = o.side == "right";
  const gen::LoadKind kind = o.approach_m ? gen::LoadKind::Approach
                             : o.normal_load_N ? gen::LoadKind::NormalForce
                                               : gen::LoadKind::VerticalForce;
  const double value = o.approach_m ? *o.approach_m : o.normal_load_N ? *o.normal_load_N : *o.vertical_load_N;
  gen::WheelRailOptions options;
  options.method = o.method == "hertz" ? gen::NormalMethod::Hertz : gen::NormalMethod::Mim1d;
  options.mim1d = mim1d_options(o);
  gen::WheelContact contact = gen::solve_wheel_contact(right ? *setup.right : *setup.left, right ? *o.dy_m : -*o.dy_m,
                                                       right ? roll : -roll, E_star, kind, value, options);
  contact.dy_m = *o.dy_m;
  contact.roll_rad = roll;
  if (o.json) {
    auto json = gen::to_json(contact);
    json["method"] = o.method;
    json["mode"] = o.mode;
    json["side"] = o.side;
    std::cout << json.dump(1) << '\n';
  } else {
    print_summary(contact);
  }
  return gen::is_success(contact.status) ? 0 : 4;
}

int run_solve(const SolveOptions& o) {
  if (!(o.strip_width_m > 0.0 && std::isfinite(o.strip_width_m)))
    throw gen::InputError("--strip-width", 0, "expected a positive width in metres");
  if (!(o.youngs_modulus_Pa > 0.0 && std::isfinite(o.youngs_modulus_Pa)))
    throw gen::InputError("--E", 0, "expected a positive Young's modulus in Pa");
  if (!(o.poisson_ratio > -1.0 && o.poisson_ratio < 0.5))
    throw gen::InputError("--nu", 0, "expected a Poisson's ratio in (-1, 0.5)");
  if (o.approach_m && !std::isfinite(*o.approach_m)) throw gen::InputError("--approach", 0, "expected a finite number");
  for (const auto& [name, value] : {std::pair{"--load", o.load_N}, std::pair{"--normal-load", o.normal_load_N},
                                    std::pair{"--vertical-load", o.vertical_load_N}})
    if (value && !(std::isfinite(*value) && *value >= 0.0))
      throw gen::InputError(name, 0, "expected a finite, non-negative force in N");
  if (o.dy_m && !std::isfinite(*o.dy_m)) throw gen::InputError("--dy", 0, "expected a finite shift in metres");
  const gen::ElasticMaterial material{o.youngs_modulus_Pa, o.poisson_ratio};
  const double E_star = gen::effective_modulus(material, material);
  if (o.gap_path.empty() == !o.wheelrail_given)
    throw gen::InputError("solve", 0, "give either --gap FILE or a wheel-rail case (--wheel, --rail, --dy)");
  return o.gap_path.empty() ? solve_wheelrail(o, E_star) : solve_gap(o, E_star);
}

}  // namespace

Command add_solve_command(CLI::App& parent) {
  auto o = std::make_shared<SolveOptions>();
  CLI::App* app = parent.add_subcommand("solve", "Solve one normal-contact problem: a gap profile or a wheel on its rail (SI units)");
  app->add_option("--gap", o->gap_path, "CSV with columns y_m,h_m,A_per_m,B_per_m");
  app->add_option("--approach", o->approach_m, "prescribed approach [m] (wheel-rail: vertical, beyond first contact)");
  app->add_option("--load", o->load_N, "prescribed normal load on the gap profile [N]");
  app->add_option("--normal-load", o->normal_load_N, "wheel-rail: total normal force [N]");
  app->add_option("--vertical-load", o->vertical_load_N, "wheel-rail: vertical wheel load [N]");
  app->add_option("--dy", o->dy_m, "wheel-rail: lateral shift of the wheelset [m], + moves the right flange to its rail");
  app->add_option("--mode", o->mode, "wheel-rail: wheel (single wheel, roll 0) or wheelset (rigid roll)")
      ->check(CLI::IsMember({"wheel", "wheelset"}));
  app->add_option("--side", o->side, "wheel-rail: right or left wheel")->check(CLI::IsMember({"right", "left"}));
  add_wheelrail_options(*app, o->wheelrail);
  app->add_option("--method", o->method, "normal-contact method")->check(CLI::IsMember({"mim1d", "hertz"}));
  app->add_option("--strip-width", o->strip_width_m, "strip width 2b [m] (default 0.2e-3)");
  app->add_option("--E", o->youngs_modulus_Pa, "Young's modulus of both bodies [Pa] (default 208e9)");
  app->add_option("--nu", o->poisson_ratio, "Poisson's ratio of both bodies [-] (default 0.3)");
  app->add_option("--curvature", o->curvature, "lateral curvature in Eq. 26: smoothed (default) or pointwise")
      ->check(CLI::IsMember({"smoothed", "pointwise"}));
  app->add_option("--update", o->update, "MIM-1D update: newton (default) or fixed-point (paper Figure 3)")
      ->check(CLI::IsMember({"newton", "fixed-point"}));
  app->add_flag("--json", o->json, "print one JSON object");
  app->callback([app, o] {
    o->wheelrail_given = app->count("--wheel") + app->count("--rail") + app->count("--dy") > 0;
  });
  return {app, [o] { return run_solve(*o); }};
}

}  // namespace ctab::cli
