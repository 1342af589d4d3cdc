#include "ctab/gen/solution_json.hpp"

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
  return {{"status", status_name(solution.status)},
          {"method", solution.method},
          {"approach_m", solution.approach_m},
          {"normal_load_N", solution.normal_load_N},
          {"iterations", solution.iterations},
          {"outer_iterations", solution.outer_iterations},
          {"residual", solution.residual},
          {"solve_time_s", solution.solve_time_s},
          {"patches", std::move(patches)}};
}

}  // namespace ctab::gen
