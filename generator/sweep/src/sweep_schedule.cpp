// SPDX-License-Identifier: Apache-2.0
// The schedule of a table sweep (sweep_schedule.hpp): roll runs and their mirrors, warm-start chains and their order.
#include "sweep_schedule.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ctab::gen::detail {

namespace {

// For each of `rows` (lateral-shift indices), the position in `rows` of the row whose roll it mirrors, or
// kSolveRoll where its roll is solved. Mirrored wheelset sweeps solve only dy >= 0: on mirror-image sides
// roll(-dy) = -roll(dy) to the bit (the mismatch z_right - z_left is exactly antisymmetric in (dy, roll), and the
// bracketed root finder's steps, from the symmetric bracket on, are exactly mirrored). The rows of a mirrored
// sweep are mirror-closed (TableSweep::solve_rows, sweep_units), so the source row is always among them.
constexpr std::size_t kSolveRoll = static_cast<std::size_t>(-1);

std::vector<std::size_t> roll_sources(const SweepSetup& setup, const SweepPlan& plan,
                                      const std::vector<std::size_t>& rows) {
  std::vector<std::size_t> source(rows.size(), kSolveRoll);
  if (!plan.mirrored || setup.mode != ContactMode::Wheelset) return source;
  const std::size_t n_dy = plan.dy_m.size();
  std::vector<std::size_t> position(n_dy, kSolveRoll);
  for (std::size_t k = 0; k < rows.size(); ++k) position[rows[k]] = k;
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (plan.dy_m[rows[k]] < 0.0) source[k] = position[n_dy - 1 - rows[k]];
  return source;
}

// Consecutive rows (lateral-shift indices) whose rolls are solved, in runs of at most kRollRunRows: each run is
// one task, every roll after its first searched from its predecessors' (linear extrapolation). The guess changes
// only the search's cost, never its result (rigid_wheelset_pose), so any split gives the same table.
constexpr std::size_t kRollRunRows = 8;

std::vector<std::vector<std::size_t>> roll_runs(const std::vector<std::size_t>& rows,
                                                const std::vector<std::size_t>& solved) {
  std::vector<std::vector<std::size_t>> runs;
  for (std::size_t j = 0; j < solved.size(); ++j) {
    if (runs.empty() || runs.back().size() == kRollRunRows || rows[solved[j]] != rows[runs.back().back()] + 1)
      runs.emplace_back();
    runs.back().push_back(solved[j]);
  }
  return runs;
}

// The guess for the next roll of a run from the rolls before it (none for the run's first).
const RollGuess* next_roll_guess(const std::vector<CaseRoll>& rolls, const std::vector<std::size_t>& run,
                                 std::size_t position, RollGuess& guess) {
  if (position == 0 || !rolls[run[position - 1]].converged) return nullptr;
  const double previous = rolls[run[position - 1]].roll_rad;
  const bool two = position >= 2 && rolls[run[position - 2]].converged;
  const double change = two ? previous - rolls[run[position - 2]].roll_rad : 0.0;
  guess = {previous + change, std::abs(change)};
  return &guess;
}

}  // namespace

RollSchedule roll_schedule(const SweepSetup& setup, const SweepPlan& plan, const std::vector<std::size_t>& rows) {
  const std::vector<std::size_t> source = roll_sources(setup, plan, rows);
  std::vector<std::size_t> solved;
  RollSchedule schedule;
  schedule.mirrors.resize(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (source[k] == kSolveRoll) solved.push_back(k);
    else schedule.mirrors[source[k]].push_back(k);
  }
  std::sort(solved.begin(), solved.end(), [&](std::size_t a, std::size_t b) { return rows[a] < rows[b]; });
  schedule.runs = roll_runs(rows, solved);
  return schedule;
}

void solve_roll_run(const SweepSetup& setup, const SweepPlan& plan, const std::vector<std::size_t>& rows,
                    const std::vector<std::size_t>& run, const std::vector<std::vector<std::size_t>>& mirrors,
                    std::vector<CaseRoll>& rolls) {
  RollGuess guess;
  for (std::size_t j = 0; j < run.size(); ++j) {
    const std::size_t k = run[j];
    rolls[k] = solve_case_roll(setup, plan.dy_m[rows[k]], next_roll_guess(rolls, run, j, guess));
    for (const std::size_t m : mirrors[k])
      rolls[m] =
          rolls[k].converged ? CaseRoll{-rolls[k].roll_rad, true, ""} : solve_case_roll(setup, plan.dy_m[rows[m]]);
  }
}

std::vector<std::vector<std::size_t>> warm_start_chains(const SweepSetup& setup, const SweepPlan& plan,
                                                        const std::vector<std::size_t>& rows) {
  const std::size_t n_dy = plan.dy_m.size();
  std::vector<std::size_t> position(n_dy, kColdStart);
  for (std::size_t k = 0; k < rows.size(); ++k) position[rows[k]] = k;
  const std::vector<std::size_t> previous =
      setup.warm_start ? warm_start_previous_rows(n_dy, plan.mirrored) : std::vector<std::size_t>(n_dy, kColdStart);
  std::vector<std::size_t> next(n_dy, kColdStart);
  for (const std::size_t row : rows)
    if (previous[row] != kColdStart && position[previous[row]] != kColdStart) next[previous[row]] = row;
  std::vector<std::vector<std::size_t>> chains;
  for (const std::size_t row : rows) {
    if (previous[row] != kColdStart && position[previous[row]] != kColdStart) continue;  // not a chain's start
    chains.emplace_back();
    for (std::size_t r = row; r != kColdStart; r = next[r]) chains.back().push_back(position[r]);
  }
  return chains;
}

std::vector<std::size_t> chain_order(const SweepPlan& plan, const std::vector<std::size_t>& rows,
                                     const std::vector<std::vector<std::size_t>>& chains) {
  std::vector<double> nearest(chains.size(), std::numeric_limits<double>::infinity());
  for (std::size_t c = 0; c < chains.size(); ++c)
    for (const std::size_t k : chains[c]) nearest[c] = std::min(nearest[c], std::abs(plan.dy_m[rows[k]]));
  std::vector<std::size_t> order(chains.size());
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return nearest[a] < nearest[b]; });
  return order;
}

}  // namespace ctab::gen::detail
