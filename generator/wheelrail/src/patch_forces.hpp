// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Forces of a solved patch (internal to ctab::wheelrail): each strip pushes along its own normal.
#include <cstddef>
#include <string>

#include "ctab/contact/contact_method.hpp"
#include "ctab/contact/normal_solution.hpp"
#include "patch_problem.hpp"

namespace ctab::gen {

//! Force of the wheel on the rail in the side frame [N]: lateral + towards the field side, vertical + down.
struct ForceComponents {
  double lateral_N = 0.0, vertical_N = 0.0;
};

//! Direction of a strip's normal force (inclination from the vertical, < 0 on the gauge side) [rad]: the normal of
//! the surface at the strip's centre (planar: the plane's for every strip).
[[nodiscard]] double strip_normal_angle(const PatchProblem& p, const StripSolution& strip);

//! One run of strips' force, summed strip by strip along each strip's normal: the components that the load balance
//! uses and that are reported (so that they add up to the prescribed vertical load).
[[nodiscard]] ForceComponents run_force(const PatchProblem& p, const PatchSolution& run);

//! The force of every run of the patch's solution.
[[nodiscard]] ForceComponents solution_force(const PatchProblem& p);

//! Why a patch's normal solve failed, in words (slot: the patch's index).
[[nodiscard]] std::string patch_failure(ContactMethod method, const NormalSolution& solution, std::size_t slot);

}  // namespace ctab::gen
