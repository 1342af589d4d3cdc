// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/normal_contact.hpp"

#include <cmath>

#include "ctab/contact/analyn.hpp"
#include "ctab/contact/bem2d.hpp"
#include "ctab/core/error.hpp"
#include "ctab/contact/hertz_strip.hpp"
#include "ctab/contact/kik_piotrowski.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/contact/resolution.hpp"
#include "ctab/contact/semi_analytic.hpp"

namespace ctab::gen {

namespace {

bool approach_given(Loading loading) noexcept { return loading.kind == Loading::Kind::Approach; }

// A function pair of one rung: (gap, E*, strip width, approach or force) -> solution.
using RungFunction = NormalSolution (*)(const GapProfile&, double, double, double);

NormalSolution solve_rung(RungFunction for_approach, RungFunction for_load, const GapProfile& gap,
                          const MethodOptions& options, Loading loading) {
  return (approach_given(loading) ? for_approach : for_load)(gap, options.E_star_Pa, options.strip_width_m,
                                                             loading.value);
}

NormalSolution solve_mim1d(const GapProfile& gap, const MethodOptions& options, Loading loading) {
  Mim1dOptions mim1d = options.mim1d;
  mim1d.strip_width_m = options.strip_width_m;
  try {
    Mim1dSolver solver(gap, options.E_star_Pa, mim1d);
    return approach_given(loading) ? solver.solve_for_approach(loading.value) : solver.solve_for_load(loading.value);
  } catch (const InputError&) {
    return status_solution(SolveStatus::InvalidInput, method_name(ContactMethod::Mim1d));
  }
}

// The reference on elements of the strip width (one element row per strip), square unless a length is given.
NormalSolution solve_bem2d(const GapProfile& gap, const MethodOptions& options, Loading loading) {
  const double length_m = options.bem2d_element_length_m > 0.0 ? options.bem2d_element_length_m : options.strip_width_m;
  Bem2dGrid grid{.dx_m = length_m, .dy_m = options.strip_width_m};
  grid.alignment = options.bem2d_alignment;
  return approach_given(loading)
             ? solve_bem2d_for_approach(gap, options.E_star_Pa, grid, loading.value, options.bem2d_field)
             : solve_bem2d_for_load(gap, options.E_star_Pa, grid, loading.value, options.bem2d_field,
                                    options.bem2d_start);
}

// Input every rung needs; false for InvalidInput.
bool valid_input(const GapProfile& gap, const MethodOptions& options, Loading loading) {
  if (!(std::isfinite(options.E_star_Pa) && options.E_star_Pa > 0.0)) return false;
  if (!(std::isfinite(options.strip_width_m) && options.strip_width_m > 0.0)) return false;
  if (!std::isfinite(loading.value) || (loading.kind == Loading::Kind::NormalForce && loading.value < 0.0))
    return false;
  try {
    validate(gap);
  } catch (const InputError&) {
    return false;
  }
  return true;
}

// The rung's own solve, before the resolution check.
NormalSolution solve_rung_of(const GapProfile& gap, const MethodOptions& options, Loading loading) {
  switch (options.method) {
    case ContactMethod::Hertz: return solve_rung(solve_hertz_for_approach, solve_hertz_for_load, gap, options, loading);
    case ContactMethod::Kp: return solve_rung(solve_kp_for_approach, solve_kp_for_load, gap, options, loading);
    case ContactMethod::Analyn:
      return solve_rung(solve_analyn_for_approach, solve_analyn_for_load, gap, options, loading);
    case ContactMethod::Mim1d: return solve_mim1d(gap, options, loading);
    case ContactMethod::Bem2d: return solve_bem2d(gap, options, loading);
  }
  return status_solution(SolveStatus::InvalidInput, method_name(options.method));
}

}  // namespace

NormalSolution solve_normal_contact(const GapProfile& gap, const MethodOptions& options, Loading loading) {
  if (!valid_input(gap, options, loading)) {
    NormalSolution invalid = status_solution(SolveStatus::InvalidInput, method_name(options.method));
    if (approach_given(loading)) invalid.approach_m = loading.value;
    return invalid;
  }
  NormalSolution solution = solve_rung_of(gap, options, loading);
  solution.status = resolution_status(solution.status, options.method, patch_extents(solution), options.strip_width_m);
  return solution;
}

}  // namespace ctab::gen
