// SPDX-License-Identifier: Apache-2.0
#include "patch_forces.hpp"

#include <cmath>

#include "linear_interpolation.hpp"

namespace ctab::gen {

double strip_normal_angle(const PatchProblem& p, const StripSolution& strip) {
  return interpolate(p.gap.y_m, p.normal_angle, strip.y_m);
}

ForceComponents run_force(const PatchProblem& p, const PatchSolution& run) {
  ForceComponents f;
  for (const StripSolution& st : run.strips) {
    const double angle = strip_normal_angle(p, st);
    f.lateral_N -= st.load_N * std::sin(angle);
    f.vertical_N += st.load_N * std::cos(angle);
  }
  return f;
}

ForceComponents solution_force(const PatchProblem& p) {
  ForceComponents total;
  for (const PatchSolution& run : p.solution.patches) {
    const ForceComponents f = run_force(p, run);
    total.lateral_N += f.lateral_N;
    total.vertical_N += f.vertical_N;
  }
  return total;
}

std::string patch_failure(ContactMethod method, const NormalSolution& solution, std::size_t slot) {
  const std::string at = " at patch " + std::to_string(slot + 1);
  const std::string solver = method == ContactMethod::Mim1d ? std::string("MIM-1D") : std::string(method_name(method));
  if (!solution.detail.empty()) return solver + ": " + solution.detail + at;
  switch (solution.status) {
    case SolveStatus::MaxIterations:
      return solver + " did not converge in " + std::to_string(solution.iterations) + " iterations" + at;
    case SolveStatus::InvalidInput:
      return solver + " rejected the strip problem" + at + " (non-finite input or curvature out of range)";
    case SolveStatus::NumericalFailure:
      return solver + " failed numerically" + at + " (singular system or non-finite value)";
    case SolveStatus::ZoneTruncated:
      return "the contact reaches the end of the window" + at + " (the profiles end inside the contact)";
    default: return std::string(status_name(solution.status)) + at;
  }
}

}  // namespace ctab::gen
