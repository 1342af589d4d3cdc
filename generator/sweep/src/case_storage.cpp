// SPDX-License-Identifier: Apache-2.0
// Storage of one solved wheel of one case in a table (table_generator.hpp): its status (the solver's mapped onto
// the table's), its patches in slots with their force components, s origin, equivalent ellipse and strip profiles.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ctab/sweep/slot_assignment.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "rail_geometry.hpp"

namespace ctab::gen {

// Status mapping: every value the two enums share is the same number.
using tables::CaseStatus;
static_assert(static_cast<int>(SolveStatus::Converged) == static_cast<int>(CaseStatus::Converged));
static_assert(static_cast<int>(SolveStatus::NoContact) == static_cast<int>(CaseStatus::NoContact));
static_assert(static_cast<int>(SolveStatus::UnderResolved) == static_cast<int>(CaseStatus::UnderResolved));
static_assert(static_cast<int>(SolveStatus::MaxIterations) == static_cast<int>(CaseStatus::MaxIterations));
static_assert(static_cast<int>(SolveStatus::InvalidInput) == static_cast<int>(CaseStatus::InvalidInput));
static_assert(static_cast<int>(SolveStatus::ZoneTruncated) == static_cast<int>(CaseStatus::ZoneTruncated));
static_assert(static_cast<int>(SolveStatus::NumericalFailure) == static_cast<int>(CaseStatus::NumericalFailure));

tables::CaseStatus case_status(SolveStatus status) noexcept {
  switch (status) {
    case SolveStatus::Converged: return CaseStatus::Converged;
    case SolveStatus::NoContact: return CaseStatus::NoContact;
    case SolveStatus::UnderResolved: return CaseStatus::UnderResolved;
    case SolveStatus::MaxIterations: return CaseStatus::MaxIterations;
    case SolveStatus::InvalidInput: return CaseStatus::InvalidInput;
    case SolveStatus::ZoneTruncated: return CaseStatus::ZoneTruncated;
    case SolveStatus::NumericalFailure: return CaseStatus::NumericalFailure;
  }
  return CaseStatus::NumericalFailure;
}

tables::CaseStatus case_status(const CaseWheel& solved) noexcept {
  return solved.exception ? CaseStatus::SolverException : case_status(solved.contact.status);
}

void equivalent_ellipse(double area_m2, double length_m, double width_m, double& a_m, double& b_m) noexcept {
  if (!(area_m2 > 0.0 && length_m > 0.0 && width_m > 0.0)) {
    a_m = b_m = 0.0;
    return;
  }
  const double radius = std::sqrt(area_m2 / std::numbers::pi), ratio = std::sqrt(length_m / width_m);
  a_m = radius * ratio;
  b_m = radius / ratio;
}

namespace {

// Linear interpolation of a strip profile at s (0 outside the strips).
double sample_strips(const std::vector<PatchStrip>& strips, double s, bool pressure) {
  if (strips.empty() || s < strips.front().s_m || s > strips.back().s_m) return 0.0;
  const auto upper =
      std::lower_bound(strips.begin(), strips.end(), s, [](const PatchStrip& a, double v) { return a.s_m < v; });
  if (upper == strips.begin()) return pressure ? upper->p0_Pa : upper->half_length_m;
  const PatchStrip& hi = *upper;
  const PatchStrip& lo = *(upper - 1);
  const double t = (s - lo.s_m) / (hi.s_m - lo.s_m);
  return pressure ? (1 - t) * lo.p0_Pa + t * hi.p0_Pa : (1 - t) * lo.half_length_m + t * hi.half_length_m;
}

void store_patch(tables::Table& table, const ProfileTable& rail, std::size_t k, const ContactPatch& patch) {
  auto& p = table.patch;
  p.present[k] = 1;
  p.normal_force_N[k] = patch.normal_force_N;
  // Force of the wheel on the rail, the solver's own components (those of its load balance): vertical + down,
  // lateral + to the field side (a flange force is > 0).
  p.force_vertical_N[k] = patch.force_vertical_N;
  p.force_lateral_N[k] = patch.force_lateral_N;
  p.area_m2[k] = patch.area_m2;
  p.max_pressure_Pa[k] = patch.max_pressure_Pa;
  p.approach_m[k] = patch.approach_m;
  p.contact_angle_rad[k] = patch.contact_angle_rad;
  p.plane_angle_rad[k] = patch.plane_angle_rad;
  p.s_origin_y_rail_m[k] = detail::s_origin_y_rail(patch, rail);
  p.s_origin_z_rail_m[k] = rail.at(p.s_origin_y_rail_m[k]).z;
  p.y_wheel_m[k] = patch.y_wheel_m;
  p.y_rail_m[k] = patch.y_rail_m;
  p.y_cop_rail_m[k] = patch.y_cop_rail_m;
  p.rolling_radius_m[k] = patch.rolling_radius_m;
  p.s_min_m[k] = patch.s_min_m;
  p.s_max_m[k] = patch.s_max_m;
  double longest = 0.0;
  for (const PatchStrip& s : patch.strips) longest = std::max(longest, 2.0 * s.half_length_m);
  equivalent_ellipse(patch.area_m2, longest, patch.s_max_m - patch.s_min_m, p.semi_axis_a_m[k], p.semi_axis_b_m[k]);
  const std::size_t n = table.strip_samples;
  for (std::size_t j = 0; j < n; ++j) {
    const double s =
        patch.s_min_m + (patch.s_max_m - patch.s_min_m) * static_cast<double>(j) / static_cast<double>(n - 1);
    p.strip_half_length_m[k * n + j] = sample_strips(patch.strips, s, false);
    p.strip_peak_pressure_Pa[k * n + j] = sample_strips(patch.strips, s, true);
  }
}

SlotCase slot_case(const CaseWheel& solved) {
  SlotCase out;
  out.success = !solved.exception && tables::is_success(case_status(solved.contact.status));
  if (out.success)
    for (const ContactPatch& patch : solved.contact.patches)
      out.patches.push_back({patch.y_rail_m, patch.zone == "flange"});
  return out;
}

// Status and patches of one wheel of one case in the slots `assignment` gives them.
void store_wheel(tables::Table& table, const SweepSetup& setup, std::size_t i_dy, std::size_t i_second,
                 std::size_t wheel, const CaseWheel& solved, const SlotAssignment& assignment) {
  const std::size_t w = table.wheel_index(i_dy, i_second, wheel);
  table.method[w] = static_cast<std::int8_t>(solved.choice.method);
  table.strip_width_m[w] = solved.choice.strip_width_m;
  CaseStatus& status = table.status[w];
  status = case_status(solved);
  if (!tables::is_success(status)) return;  // a failed case holds no patches
  if (assignment.overflow) {
    status = CaseStatus::SlotOverflow;
    return;
  }
  for (std::size_t i = 0; i < assignment.slot_of.size(); ++i)
    store_patch(table, *setup.rail, table.patch_index(i_dy, i_second, wheel, assignment.slot_of[i]),
                solved.contact.patches[i]);
}

}  // namespace

void store_case_wheel(tables::Table& table, const SweepSetup& setup, std::size_t i_dy, std::size_t i_second,
                      std::size_t wheel, const CaseWheel& solved) {
  const std::vector<SlotAssignment> assignment = assign_slots_along_dy({slot_case(solved)}, table.n_slots);
  store_wheel(table, setup, i_dy, i_second, wheel, solved, assignment.front());
}

}  // namespace ctab::gen
