// SPDX-License-Identifier: Apache-2.0
#pragma once
//! JSON form of a NormalSolution (SI units; the key names carry the unit).
#include <nlohmann/json.hpp>

#include "ctab/contact/normal_solution.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::gen {

//! {"status", "method", "approach_m", "normal_load_N", "iterations", "outer_iterations", "residual",
//!  "solve_time_s", "patches": [{"area_m2", "normal_force_N", "max_pressure_Pa", "centre_of_pressure_y_m",
//!  "y_min_m", "y_max_m", "strips": [{"y_m", "half_length_m", "p0_Pa"}]}]}
[[nodiscard]] nlohmann::json to_json(const NormalSolution& solution);

//! {"status", "dy_m", "roll_rad", "approach_m" (vertical, beyond first contact), "normal_load_N",
//!  "vertical_load_N", "iterations", "solve_time_s", "patches": [{"zone", "area_m2", "normal_force_N",
//!  "force_lateral_N", "force_vertical_N" (on the rail, side frame; they sum to the vertical load),
//!  "plane_angle_rad", "max_pressure_Pa", "approach_m" (normal), "contact_angle_rad", "y_rail_m", "y_wheel_m", "rolling_radius_m",
//!  "y_cop_rail_m", "strips": [{"s_m", "y_rail_m", "half_length_m", "p0_Pa"}]}],
//!  "near_misses": [{"y_wheel_m", "y_rail_m", "gap_m", "contact_angle_rad"}]}
[[nodiscard]] nlohmann::json to_json(const WheelContact& contact);

}  // namespace ctab::gen
