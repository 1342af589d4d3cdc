// SPDX-License-Identifier: Apache-2.0
#include "patch_problem.hpp"

#include <algorithm>
#include <exception>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/strip_grid.hpp"
#include "wheelrail_tuning.hpp"

namespace ctab::gen {

GridAlignment strip_alignment(const WheelRailOptions& options) {
  return options.at_interpenetration_centre() || options.surface == ContactSurface::Conformal
             ? GridAlignment::CentresAtOrigin
             : GridAlignment::EdgesAtOrigin;
}

bool same_point(const GapMinimum& a, const GapMinimum& b) {
  return a.wheel_s_m == b.wheel_s_m && a.rail_y_m == b.rail_y_m && a.gap_m == b.gap_m &&
         a.contact_angle_rad == b.contact_angle_rad && a.rolling_radius_m == b.rolling_radius_m;
}

std::string prepare_mim1d_solver(std::unique_ptr<Mim1dSolver>& solver, const GapProfile& gap, double E_star,
                                 const Mim1dOptions& options) {
  const double strips = strip_count(gap, options.strip_width_m);
  if (!(strips <= static_cast<double>(kMaxStripsPerPatch)))
    return "patch needs " + number_text(strips) + " strips (max " + std::to_string(kMaxStripsPerPatch) +
           "): strip width too small";
  try {
    if (solver && solver->matches(E_star, options)) solver->reset(gap);
    else solver = std::make_unique<Mim1dSolver>(gap, E_star, options);
  } catch (const std::exception& e) {
    return std::string("MIM-1D set-up: ") + e.what();
  }
  return {};
}

double expected_approach(const SideGeometry& side, const GapMinimum& m, double dy, double roll, double E_star,
                         LoadKind load, double value) {
  const double c = std::cos(m.contact_angle_rad);
  if (load == LoadKind::Approach) return value * c;
  const WheelSurfacePoint w = side.wheel_point(m.wheel_s_m, dy, roll);
  const double A = c / (2.0 * w.radius_m);
  const double B =
      std::max(0.5 * (side.rail().at(m.rail_y_m).curvature() - w.curvature()), A / tuning::kCurvatureRatioLimit);
  const double force = load == LoadKind::VerticalForce ? value / std::max(c, tuning::kCosineFloor) : value;
  const HertzContact h = hertz_from_load(A, B, E_star, force);
  return h.status == SolveStatus::Converged ? h.approach_m : tuning::kFallbackApproach_m;
}

}  // namespace ctab::gen
