// SPDX-License-Identifier: Apache-2.0
#include "solution_json.hpp"

namespace ctab::gen {

nlohmann::json to_json(const NormalSolution& solution) {
  nlohmann::json patches = nlohmann::json::array();
  for (const PatchSolution& patch : solution.patches) {
    nlohmann::json strips = nlohmann::json::array();
    for (const StripSolution& strip : patch.strips)
      strips.push_back({{"y_m", strip.y_m}, {"half_length_m", strip.half_length_m}, {"p0_Pa", strip.p0_Pa}});
    patches.push_back({{"area_m2", patch.area_m2},
                       {"normal_force_N", patch.normal_force_N},
                       {"max_pressure_Pa", patch.max_pressure_Pa},
                       {"centre_of_pressure_y_m", patch.centre_of_pressure_y_m},
                       {"y_min_m", patch.y_min_m},
                       {"y_max_m", patch.y_max_m},
                       {"strips", std::move(strips)}});
  }
  nlohmann::json json = {{"status", status_name(solution.status)}, {"method", solution.method},
                         {"approach_m", solution.approach_m},      {"normal_load_N", solution.normal_load_N},
                         {"iterations", solution.iterations},      {"outer_iterations", solution.outer_iterations},
                         {"residual", solution.residual},          {"solve_time_s", solution.solve_time_s},
                         {"patches", std::move(patches)}};
  if (!solution.detail.empty()) json["detail"] = solution.detail;  // why it failed, in words
  return json;
}

nlohmann::json to_json(const WheelContact& contact) {
  nlohmann::json patches = nlohmann::json::array();
  for (const ContactPatch& patch : contact.patches) {
    nlohmann::json strips = nlohmann::json::array();
    for (const PatchStrip& strip : patch.strips)
      strips.push_back({{"s_m", strip.s_m},
                        {"y_rail_m", strip.y_rail_m},
                        {"half_length_m", strip.half_length_m},
                        {"p0_Pa", strip.p0_Pa}});
    patches.push_back({{"zone", patch.zone},
                       {"area_m2", patch.area_m2},
                       {"normal_force_N", patch.normal_force_N},
                       {"force_lateral_N", patch.force_lateral_N},
                       {"force_vertical_N", patch.force_vertical_N},
                       {"plane_angle_rad", patch.plane_angle_rad},
                       {"max_pressure_Pa", patch.max_pressure_Pa},
                       {"approach_m", patch.approach_m},
                       {"contact_angle_rad", patch.contact_angle_rad},
                       {"y_rail_m", patch.y_rail_m},
                       {"y_wheel_m", patch.y_wheel_m},
                       {"rolling_radius_m", patch.rolling_radius_m},
                       {"y_cop_rail_m", patch.y_cop_rail_m},
                       {"strips", std::move(strips)}});
  }
  nlohmann::json misses = nlohmann::json::array();
  for (const GapMinimum& m : contact.near_misses)
    misses.push_back({{"y_wheel_m", m.wheel_s_m},
                      {"y_rail_m", m.rail_y_m},
                      {"gap_m", m.gap_m},
                      {"contact_angle_rad", m.contact_angle_rad}});
  nlohmann::json json = {{"status", status_name(contact.status)},
                         {"dy_m", contact.dy_m},
                         {"roll_rad", contact.roll_rad},
                         {"approach_m", contact.vertical_approach_m},
                         {"normal_load_N", contact.normal_force_N},
                         {"vertical_load_N", contact.vertical_force_N},
                         {"iterations", contact.iterations},
                         {"solve_time_s", contact.solve_time_s},
                         {"patches", std::move(patches)},
                         {"near_misses", std::move(misses)}};
  if (!contact.detail.empty()) json["detail"] = contact.detail;  // why it failed, in words
  return json;
}

}  // namespace ctab::gen
