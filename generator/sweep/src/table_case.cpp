// SPDX-License-Identifier: Apache-2.0
// One table case (table_generator.hpp): the wheelset roll at a lateral shift, one wheel's contact, and a whole case
// as the sweep solves it (its warm-start chain replayed), for `ctab solve` and the sweep alike.
#include <algorithm>
#include <cmath>
#include <vector>

#include "ctab/sweep/case_partition.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/wheelrail/patch_extents.hpp"

namespace ctab::gen {

CaseRoll solve_case_roll(const SweepSetup& setup, double dy_m, const RollGuess* guess) noexcept {
  if (setup.mode != ContactMode::Wheelset) return {};
  try {
    const WheelsetPose pose = rigid_wheelset_pose(*setup.side, *setup.side, dy_m, guess);
    return {pose.roll_rad, pose.converged, pose.detail};
  } catch (...) {
    return {0.0, false, "the wheelset roll search threw"};
  }
}

namespace {

// Halvings of `width_m` that put kMinResolvedStrips strips across the narrowest counted patch of `contact`
// (at least one), or 0 where the finest such width is below kMinStripWidth_m.
int halvings_to_resolve(const WheelContact& contact, ContactMethod method, double width_m) {
  const double strips = min_resolved_strips(patch_extents(contact), method, width_m);
  int halvings = std::isfinite(strips) && strips > 0.0
                     ? std::max(1, static_cast<int>(std::ceil(std::log2(kMinResolvedStrips / strips) - 1e-9)))
                     : 1;
  while (halvings > 0 && std::ldexp(width_m, -halvings) < kMinStripWidth_m) --halvings;
  return halvings;
}

// An under-resolved wheel (fewer than kMinResolvedStrips strips across a counted patch) solved again, cold, at the
// halving of its strip width the narrowest patch asks for, and once more halved while a solve stays under-resolved,
// down to kMinStripWidth_m: the status stays where that width cannot resolve the patch. The warm start is left as
// the solve at the configured width made it, so the chain continues at that width.
void refine_strip_width(const SweepSetup& setup, double shift_m, double roll_rad, double load_value,
                        WheelContactWorkspace& workspace, CaseWheel& out) {
  WheelRailOptions options = setup.options;
  options.method = out.choice.method;
  double width_m = out.choice.strip_width_m;
  while (out.contact.status == SolveStatus::UnderResolved) {
    const int halvings = halvings_to_resolve(out.contact, options.method, width_m);
    if (halvings == 0) return;
    width_m = std::ldexp(width_m, -halvings);
    options.mim1d.strip_width_m = width_m;
    WheelContact finer = solve_wheel_contact(*setup.side, shift_m, roll_rad, setup.E_star_Pa, setup.load_kind,
                                             load_value, options, workspace);
    ++out.choice.solves;
    out.choice.matrix_entries += finer.matrix_entries;
    // a failure (or a contact lost at the finer width) keeps the coarser usable solution
    if (finer.status != SolveStatus::Converged && finer.status != SolveStatus::UnderResolved) return;
    out.contact = std::move(finer);
    out.choice.strip_width_m = width_m;
  }
}

}  // namespace

CaseWheel solve_case_wheel(const SweepSetup& setup, std::size_t wheel, double dy_m, const CaseRoll& roll,
                           double load_value, WheelContactWorkspace& workspace, Mim1dWarmStart* warm_start) noexcept {
  const double shift = wheel == 1 ? -dy_m : dy_m, angle = wheel == 1 ? -roll.roll_rad : roll.roll_rad;
  CaseWheel out;
  try {
    out.choice.method = setup.options.method;
    out.choice.strip_width_m = setup.options.mim1d.strip_width_m;
    out.choice.solves = 1;
    if (setup.auto_tolerance > 0.0)
      out.contact = solve_wheel_contact_auto(*setup.side, shift, angle, setup.E_star_Pa, setup.load_kind, load_value,
                                             setup.options, setup.auto_tolerance, workspace, &out.choice);
    else
      out.contact = warm_start == nullptr
                        ? solve_wheel_contact(*setup.side, shift, angle, setup.E_star_Pa, setup.load_kind, load_value,
                                              setup.options, workspace)
                        : solve_wheel_contact(*setup.side, shift, angle, setup.E_star_Pa, setup.load_kind, load_value,
                                              setup.options, workspace, *warm_start);
    if (roll.converged && setup.refine_under_resolved)
      refine_strip_width(setup, shift, angle, load_value, workspace, out);
    if (!roll.converged) {
      if (warm_start != nullptr) warm_start->clear();
      out.contact.status = SolveStatus::MaxIterations;
      out.contact.detail = "wheelset roll did not converge: " + roll.detail;
      out.contact.patches.clear();
    }
  } catch (...) {
    out = CaseWheel{};
    out.exception = true;
    if (warm_start != nullptr) warm_start->clear();
  }
  return out;
}

std::vector<std::size_t> warm_start_previous_rows(std::size_t n_dy, bool mirrored) {
  std::vector<std::size_t> previous(n_dy, kColdStart);
  for (const std::vector<std::size_t>& unit : sweep_units(n_dy, mirrored))
    for (std::size_t j = 1; j < unit.size(); ++j)
      if (unit[j] == unit[j - 1] + 1) previous[unit[j]] = unit[j - 1];
  return previous;
}

namespace {

// The row a wheel's solve is computed at: a mirrored sweep solves the left wheel as the right wheel at -dy.
struct SolvedRow {
  std::size_t side = 0, row = 0;
};
SolvedRow solved_row(const SweepSetup& setup, std::size_t wheel, std::size_t row) {
  if (setup.mirrored && wheel == 1) return {0, setup.dy_axis_m.size() - 1 - row};
  return {wheel, row};
}

// A wheel of the case at axis row `row` as the sweep solves it: its warm-start chain replayed from its cold row.
CaseWheel replay_chain(const SweepSetup& setup, std::size_t wheel, std::size_t row, const CaseRoll& roll,
                       double load_value, WheelContactWorkspace& workspace) {
  const SolvedRow target = solved_row(setup, wheel, row);
  const std::vector<std::size_t> previous = warm_start_previous_rows(setup.dy_axis_m.size(), setup.mirrored);
  std::vector<std::size_t> chain{target.row};
  while (previous[chain.back()] != kColdStart) chain.push_back(previous[chain.back()]);
  Mim1dWarmStart warm;
  for (std::size_t k = chain.size() - 1; k > 0; --k) {
    const double dy = setup.dy_axis_m[chain[k]];
    (void)solve_case_wheel(setup, target.side, dy, solve_case_roll(setup, dy), load_value, workspace, &warm);
  }
  // The target itself in the wheel's own frame (bit-identical to the solved row's frame, roll_mirror_test).
  return solve_case_wheel(setup, wheel, setup.dy_axis_m[row], roll, load_value, workspace, &warm);
}

}  // namespace

CaseSolution solve_table_case(const SweepSetup& setup, double dy_m, double load_value, WheelSelection wheels) {
  CaseSolution solution;
  solution.dy_m = dy_m;
  solution.load_value = load_value;
  solution.roll = solve_case_roll(setup, dy_m);
  solution.solved = wheels;
  WheelContactWorkspace workspace;
  // A shift on the axis is solved as the sweep solves it (warm-started along its chain), any other cold.
  const auto on_axis = std::find(setup.dy_axis_m.begin(), setup.dy_axis_m.end(), dy_m);
  const bool replay = setup.warm_start && on_axis != setup.dy_axis_m.end();
  for (std::size_t wheel = 0; wheel < tables::kWheels; ++wheel)
    if (wheels[wheel])
      solution.wheels[wheel] =
          replay ? replay_chain(setup, wheel, static_cast<std::size_t>(on_axis - setup.dy_axis_m.begin()),
                                solution.roll, load_value, workspace)
                 : solve_case_wheel(setup, wheel, dy_m, solution.roll, load_value, workspace);
  if (wheels == kBothWheels)
    solution.rolling_radius_difference_m = solution.wheels[0].contact.rigid_contact.rolling_radius_m -
                                           solution.wheels[1].contact.rigid_contact.rolling_radius_m;
  return solution;
}

}  // namespace ctab::gen
