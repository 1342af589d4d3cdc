#pragma once
//! JSON form of a NormalSolution (SI units; the key names carry the unit).
#include <nlohmann/json.hpp>

#include "ctab/gen/normal_solution.hpp"

namespace ctab::gen {

//! {"status", "method", "approach_m", "normal_load_N", "iterations", "outer_iterations", "residual",
//!  "solve_time_s", "patches": [{"area_m2", "normal_force_N", "max_pressure_Pa", "centre_of_pressure_y_m",
//!  "y_min_m", "y_max_m", "strips": [{"y_m", "half_length_m", "p0_Pa"}]}]}
[[nodiscard]] nlohmann::json to_json(const NormalSolution& solution);

}  // namespace ctab::gen
