// SPDX-License-Identifier: Apache-2.0
#include "main_patch_strips.hpp"

#include <cmath>

#include "centre_following.hpp"
#include "linear_interpolation.hpp"
#include "wheelrail_tuning.hpp"

namespace ctab::gen {

namespace {

// p.strip_gap_rate: the change of every strip's h (sampled at gap_dz, plus gap_dz c) when gap_dz moves by dx.
void fill_strip_gap_rate(PatchProblem& p, double dx) {
  const StripGrid& grid = p.solver->grid();
  p.strip_gap_rate.resize(grid.size());
  ForwardInterpolation weight(p.gap.y_m, p.approach_weight);
  for (std::size_t i = 0; i < grid.size(); ++i) p.strip_gap_rate[i] = dx * (p.c - weight(grid.y_m[i]));
}

// shift_pass_start's separation change of a grid origin moving to rail y next_origin_y; false where it does not
// move or moves too far for the first order.
bool add_grid_move(PatchProblem& p, double next_origin_y) {
  const double from_y = p.grid_origin_y();
  if (!std::isfinite(next_origin_y) || next_origin_y == from_y) return false;
  if (!p.window_holds(from_y) || !p.window_holds(next_origin_y)) return false;
  const double ds = interpolate(p.rail_y, p.gap.y_m, next_origin_y) - interpolate(p.rail_y, p.gap.y_m, from_y);
  const StripGrid& grid = p.solver->grid();
  if (!(std::abs(ds) < tuning::kPredictedGridMove * grid.strip_width_m)) return false;
  ForwardInterpolation moved(p.gap.y_m, p.gap.h_m), here(p.gap.y_m, p.gap.h_m);
  for (std::size_t i = 0; i < grid.size(); ++i) p.strip_gap_rate[i] += moved(grid.y_m[i] + ds) - here(grid.y_m[i]);
  return true;
}

// A saved solution (the previous pass's, or the chain's) on this pass's grid: where the grid's origin or the plane's
// angle moved, its loads are moved to the same places on the rail (the contact has not moved, only the grid's
// origin), not kept by strip index.
const Mim1dWarmStart& start_on_grid(WheelCase& c, const Mim1dWarmStart& saved, const PatchProblem& main) {
  const double origin_y = main.grid_origin_y();
  if (saved.empty() || (saved.origin_y_m == origin_y && saved.origin_angle_rad == main.angle)) return saved;
  const double shift_m = (origin_y - saved.origin_y_m) / std::cos(0.5 * (main.angle + saved.origin_angle_rad));
  move_warm_start_origin(saved, shift_m, c.options.mim1d.strip_width_m, c.ws.moved_start);
  return c.ws.moved_start;
}

}  // namespace

bool prepare(WheelCase& c, PatchProblem& p) {
  if (!c.mim1d()) return true;
  c.detail = prepare_mim1d_solver(p.solver, p.gap, c.E_star_Pa, c.options.mim1d);
  return c.detail.empty();
}

bool build_main(WheelCase& c, PatchProblem& main, double depth) {
  if (!c.builder.build(main, depth, c.options.sample_step_m)) {
    c.detail = "the patch window at rail y = " + number_text(main.reference.rail_y_m) + " m has fewer than " +
               std::to_string(tuning::kMinPatchSamples) + " samples (contact at the end of a profile)";
    return false;
  }
  return prepare(c, main);
}

NormalSolution solve_other_rung(const WheelCase& c, const PatchProblem& p, Loading loading,
                                const Bem2dPressureField* bem2d_start, Bem2dPressureField* bem2d_field) {
  MethodOptions method;
  method.method = c.options.method;
  method.E_star_Pa = c.E_star_Pa;
  method.strip_width_m = c.options.mim1d.strip_width_m;
  method.bem2d_alignment = c.options.bem2d_alignment;
  method.bem2d_element_length_m = c.options.bem2d_element_length_m;
  method.bem2d_start = bem2d_start;
  method.bem2d_field = bem2d_field;
  return solve_normal_contact(p.gap, method, loading);
}

void solve_main_once(WheelCase& c, PatchProblem& main, double force, bool from_previous_pass, double tolerance,
                     const Mim1dSolver::EarlyStop* early_stop) {
  if (!c.mim1d()) {
    // bem2d starts each pass from the previous pass's field (the passes change the gap little).
    const bool bem2d = c.options.method == NormalMethod::Bem2d;
    const Bem2dPressureField* start = bem2d && from_previous_pass ? &c.ws.bem2d_pass_start : nullptr;
    main.solution = solve_other_rung(c, main, Loading::normal_force(force), start, bem2d ? &c.ws.bem2d_solved : nullptr);
    if (bem2d) std::swap(c.ws.bem2d_pass_start, c.ws.bem2d_solved);
  } else {
    static const Mim1dWarmStart cold;
    // Where the conformal grid follows the centre the chain's start is moved onto this case's grid: a neighbour's
    // centre lies up to a strip away from the one at this case's first sampling approach.
    const Mim1dWarmStart& start = from_previous_pass                  ? start_on_grid(c, c.ws.pass_start, main)
                                  : c.warm == nullptr                 ? cold
                                  : centres_conformal_grid(c.options) ? start_on_grid(c, c.ws.chain_start, main)
                                                                      : c.ws.chain_start;
    main.solution = early_stop != nullptr ? main.solver->solve_for_load(force, start, tolerance, *early_stop)
                                          : main.solver->solve_for_load(force, start, tolerance);
  }
  if (c.mim1d() && is_success(main.solution.status)) {
    main.solver->save_warm_start(main.solution, c.ws.pass_start);
    c.ws.pass_start.origin_y_m = main.grid_origin_y();
    c.ws.pass_start.origin_angle_rad = main.angle;
    c.ws.pass_start.same_contact = true;
  }
  c.result.iterations += main.solution.iterations;
  c.result.matrix_entries += main.solution.matrix_entries;
}

std::optional<double> gap_slope(const WheelCase& c, PatchProblem& p) {
  if (!c.mim1d() || !p.solver) return std::nullopt;
  fill_strip_gap_rate(p, 1.0);
  const std::optional<double> approach_rate = p.solver->approach_sensitivity(p.strip_gap_rate);
  if (!approach_rate) return std::nullopt;
  return *approach_rate / p.c;
}

std::optional<double> load_rate(const WheelCase& c, PatchProblem& p) {
  if (!c.mim1d() || !p.solver) return std::nullopt;
  fill_strip_gap_rate(p, 0.0);
  const std::optional<double> approach_rate = p.solver->approach_sensitivity(p.strip_gap_rate, 1.0);
  if (!approach_rate) return std::nullopt;
  return *approach_rate / p.c;
}

void shift_pass_start(WheelCase& c, PatchProblem& p, double dx, double dF, double next_origin_y) {
  if (!c.mim1d() || !p.solver || c.ws.pass_start.empty()) return;
  fill_strip_gap_rate(p, dx);
  const bool moves = add_grid_move(p, next_origin_y);
  if (p.solver->shift_warm_start(p.strip_gap_rate, dF, c.ws.pass_start) && moves)
    c.ws.pass_start.origin_y_m = next_origin_y;
}

bool weighted_vertical_load(const WheelCase& c) {
  return c.mim1d() && c.options.surface == ContactSurface::Conformal && c.load == LoadKind::VerticalForce;
}

bool set_vertical_load_weights(PatchProblem& main) {
  const StripGrid& grid = main.solver->grid();
  main.load_weight.resize(grid.size());
  ForwardInterpolation normal_angle(main.gap.y_m, main.normal_angle);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    main.load_weight[i] = std::cos(normal_angle(grid.y_m[i]));
    if (!(main.load_weight[i] > tuning::kCosineFloor)) return false;
  }
  main.solver->set_load_weights(main.load_weight);
  return true;
}

}  // namespace ctab::gen
