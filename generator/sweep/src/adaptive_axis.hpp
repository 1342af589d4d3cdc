// SPDX-License-Identifier: Apache-2.0
#pragma once
// The error-controlled dy axis of a config with [axes] tolerance (docs/method.md "Error-controlled axes"): the
// nodes, their solutions (every load, each solved side) and the error measured in every cell. Private to the sweep
// library.
//
// Rounds: every open cell gets two check solves at 1/3 and 2/3 of its width, all of a round's solves run in
// parallel (each case solved cold, alone: its result does not depend on the thread or the round), then every cell
// is decided serially in axis order from those results. A cell whose checks show a jump, or an error above the
// tolerance while its thirds are not finer than min_step_m, is split at its check points (which become nodes: no
// solve is lost); otherwise it is closed with the error measured (check solves then discarded). A cell of at most
// tables::kJumpCellWidth_m is closed unmeasured. So the axis is a function of the config alone: the same at any
// thread count, and in every shard and MPI rank (each decides it in full).
#include <cstddef>
#include <vector>

#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "sweep_plan.hpp"

namespace ctab::gen::detail {

struct AdaptiveAxis {
  std::vector<double> dy_m;         // the nodes, strictly increasing; symmetric when the plan is mirrored
  std::vector<CaseRoll> rolls;      // per node
  std::vector<CaseWheel> results;   // (side, node, load) as the sweep's: side * n_dy * n_loads + k * n_loads + load
  std::vector<double> cell_error;   // tables::Table::cell_error
  std::size_t coarse_points = 0;    // nodes of the config's (coarse) axis
  std::size_t solved_points = 0;    // lateral shifts solved: nodes and check points (each every load and side)
};

// Decides the axis from the plan's (coarse) dy axis. For a mirrored plan the right wheel is refined over the whole
// axis and the nodes are then made symmetric (the left wheel at dy is the right one at -dy).
[[nodiscard]] AdaptiveAxis decide_adaptive_axis(const TableConfig& config, const SweepSetup& setup,
                                                const SweepPlan& plan);

}  // namespace ctab::gen::detail
