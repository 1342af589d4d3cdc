// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Accuracy measures of a normal-contact result against a reference (`ctab bench accuracy`): the result of any
//! rung (a strip problem's NormalSolution or a wheel's WheelContact) reduced to a ContactSummary, and the errors
//! of one summary against another. Never throws.
#include <vector>

#include "ctab/contact/normal_solution.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"

namespace ctab::gen {

//! One point of a p0 profile: strip centre y [m] and its peak pressure p0 [Pa].
struct PressurePoint {
  double y_m = 0.0;
  double p0_Pa = 0.0;
};

//! What the chart compares: totals over all patches and the p0 profile of each patch (points sorted by y).
struct ContactSummary {
  double area_m2 = 0.0;                              //!< sum of the patch areas [m^2]
  double max_pressure_Pa = 0.0;                      //!< largest p0 of any patch [Pa]
  double centre_of_pressure_m = 0.0;                 //!< load-weighted mean lateral position of all patches [m]
  double normal_force_N = 0.0;                       //!< sum of the patch loads [N]
  std::vector<std::vector<PressurePoint>> profiles;  //!< one per patch, y increasing
};

//! Strip problems (y: the gap's lateral coordinate).
[[nodiscard]] ContactSummary summarise(const NormalSolution& solution);
//! A wheel on its rail (y: the rail profile coordinate y_rail, as CONTACT's y_cop_rail).
[[nodiscard]] ContactSummary summarise(const WheelContact& contact);

//! p0 of a summary at y [Pa]: linear between the strip centres of the patch that covers y, the end strip's p0 over
//! the outer half of that strip (half the spacing to its neighbour), else 0.
[[nodiscard]] double profile_pressure_at(const ContactSummary& summary, double y_m) noexcept;

struct AccuracyErrors {
  double area_rel = 0.0;          //!< |A - A_ref| / A_ref [-]
  double max_pressure_rel = 0.0;  //!< |pmax - pmax_ref| / pmax_ref [-]
  //! RMS relative error of the p0 profile at the reference's strips: sqrt(sum (p - p_ref)^2 / sum p_ref^2) [-]
  double p0_profile_rms_rel = 0.0;
  double contact_point_m = 0.0;  //!< |centre of pressure - reference's| [m]
};

//! Errors of `candidate` against `reference` (a reference without contact gives infinite relative errors).
[[nodiscard]] AccuracyErrors accuracy_errors(const ContactSummary& candidate, const ContactSummary& reference) noexcept;

}  // namespace ctab::gen
