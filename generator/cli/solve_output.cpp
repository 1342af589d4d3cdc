// SPDX-License-Identifier: Apache-2.0
#include "solve_output.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "solution_json.hpp"
#include "table_case.hpp"

namespace ctab::cli {

namespace {

const char* mode_name(gen::ContactMode mode) { return mode == gen::ContactMode::Wheelset ? "wheelset" : "wheel"; }
using gen::method_name;
const char* wheel_name(std::size_t w) { return w == 0 ? "right" : "left"; }

// The table's name of a wheel's outcome ("converged", ..., "solver-exception").
const char* status_text(const gen::CaseWheel& wheel) { return tables::case_status_name(gen::case_status(wheel)); }

void print_wheel(const char* name, const gen::CaseWheel& wheel) {
  const gen::WheelContact& c = wheel.contact;
  std::printf("%s wheel: %s, vertical approach %.5f mm, normal load %.3f kN, vertical load %.3f kN, %d iterations, "
              "%.3f ms\n",
              name, status_text(wheel), c.vertical_approach_m * 1e3, c.normal_force_N * 1e-3, c.vertical_force_N * 1e-3,
              c.iterations, c.solve_time_s * 1e3);
  for (const auto& p : c.patches)
    std::printf("  %s patch: rail y %.3f mm (centre of pressure %.3f), wheel y %.3f mm, angle %.3f deg, radius %.3f "
                "mm, force %.3f kN, area %.3f mm^2, max pressure %.1f MPa, approach %.5f mm\n",
                p.zone.c_str(), p.y_rail_m * 1e3, p.y_cop_rail_m * 1e3, p.y_wheel_m * 1e3,
                p.contact_angle_rad * 180 / std::numbers::pi, p.rolling_radius_m * 1e3, p.normal_force_N * 1e-3,
                p.area_m2 * 1e6, p.max_pressure_Pa * 1e-6, p.approach_m * 1e3);
  for (const auto& m : c.near_misses)
    if (m.gap_m < 2e-3)
      std::printf("  near miss: rail y %.3f mm, wheel y %.3f mm, gap %.4f mm\n", m.rail_y_m * 1e3, m.wheel_s_m * 1e3,
                  m.gap_m * 1e3);
}

}  // namespace

void print_summary(const gen::NormalSolution& s) {
  std::printf("method %s: %s after %d iterations (%d outer), residual %.2e, %.3f ms\n", s.method.c_str(),
              gen::status_name(s.status), s.iterations, s.outer_iterations, s.residual, s.solve_time_s * 1e3);
  std::printf("approach %.6f mm, normal load %.4f kN, %zu patch(es)\n", s.approach_m * 1e3, s.normal_load_N * 1e-3,
              s.patches.size());
  for (std::size_t k = 0; k < s.patches.size(); ++k) {
    const auto& p = s.patches[k];
    std::printf("  patch %zu: y %.3f..%.3f mm, force %.4f kN, area %.4f mm^2, max pressure %.2f MPa, %zu strips\n",
                k + 1, p.y_min_m * 1e3, p.y_max_m * 1e3, p.normal_force_N * 1e-3, p.area_m2 * 1e6,
                p.max_pressure_Pa * 1e-6, p.strips.size());
  }
}

void print_summary(const gen::TableConfig& config, const gen::CaseSolution& solution) {
  std::printf("%s on %s (%s), %s mode, %s%s, strips %.3f mm: dy %.3f mm, roll %.4f mrad%s, %s %g\n",
              config.wheel.c_str(), config.rail.c_str(), config.inclination_text.c_str(), mode_name(config.mode),
              method_name(config.method),
              config.surface == gen::ContactSurface::Conformal ? " (conformal surface)" : "",
              config.strip_width_m * 1e3, solution.dy_m * 1e3, solution.roll.roll_rad * 1e3,
              solution.roll.converged ? "" : " (roll iteration failed)", gen::load_axis_name(config.load_kind),
              solution.load_value);
  for (std::size_t w = 0; w < solution.wheels.size(); ++w)
    if (solution.solved[w]) print_wheel(wheel_name(w), solution.wheels[w]);
}

nlohmann::json to_json(const gen::TableConfig& config, const gen::CaseSolution& solution) {
  nlohmann::json json = {{"mode", mode_name(config.mode)},
                         {"method", config.least_model ? "auto" : method_name(config.method)},
                         {"surface", std::string(gen::surface_name(config.surface))},
                         {"dy_m", solution.dy_m},
                         {"roll_rad", solution.roll.roll_rad},
                         {"roll_converged", solution.roll.converged},
                         {"load_kind", gen::load_axis_name(config.load_kind)},
                         {"load_value", solution.load_value},
                         {"config_source", config.source}};
  for (std::size_t w = 0; w < solution.wheels.size(); ++w) {
    if (!solution.solved[w]) continue;
    nlohmann::json& wheel = json[wheel_name(w)] = gen::to_json(solution.wheels[w].contact);
    wheel["dy_m"] = solution.dy_m;  // the wheelset's shift and roll, not the left side's mirrored frame
    wheel["roll_rad"] = solution.roll.roll_rad;
    wheel["status"] = status_text(solution.wheels[w]);
    wheel["strip_width_m"] = solution.wheels[w].choice.strip_width_m;  // the least model's choice with --method auto
  }
  return json;
}

void add_smoothing(nlohmann::json& json, const gen::SweepSetup& setup) {
  for (const auto& [body, smoothing] : {std::pair{"wheel", &setup.wheel_smoothing}, {"rail", &setup.rail_smoothing}})
    if (smoothing->point_data) {
      nlohmann::json& out = json[std::string(body) + "_profile_smoothing"];
      out = {{"automatic", smoothing->automatic},
             {"length_m", smoothing->length_m},
             {"length_near_jumps_m", smoothing->jump_length_m},
             {"noise_sigma_m", smoothing->noise_sigma_m}};
      if (smoothing->arc_junctions >= 0) out["arc_junctions"] = smoothing->arc_junctions;
    }
}

bool report_failures(const gen::TableConfig& config, const gen::SweepSetup& setup, const gen::CaseSolution& solution) {
  bool failed = false;
  for (std::size_t w = 0; w < solution.wheels.size(); ++w) {
    if (!solution.solved[w] || tables::is_success(gen::case_status(solution.wheels[w]))) continue;
    failed = true;
    // The wheel's own reason (a rung's message, e.g. bem2d's grid limit); a failed roll is told by the hint.
    const std::string& detail = solution.wheels[w].contact.detail;
    std::string hint = failure_hint(setup, w, solution);
    if (!detail.empty() && solution.roll.converged) hint = hint.empty() ? detail : detail + "; " + hint;
    std::fprintf(stderr, "ctab solve: %s wheel at dy = %g m, %s = %g (%s): %s%s%s\n", wheel_name(w), solution.dy_m,
                 gen::load_axis_name(config.load_kind), solution.load_value, config.source.c_str(),
                 status_text(solution.wheels[w]), hint.empty() ? "" : "; ", hint.c_str());
  }
  return failed;
}

}  // namespace ctab::cli
