// SPDX-License-Identifier: Apache-2.0
#pragma once
// The schedule of a table sweep: which rolls are solved and in which runs, which rolls mirror them, and the
// warm-start chains of the wheel solves in the order they are handed out. Private to the sweep library.
#include <cstddef>
#include <vector>

#include "ctab/sweep/table_generator.hpp"
#include "sweep_plan.hpp"

namespace ctab::gen::detail {

// The roll runs of a sweep over `rows` (lateral-shift indices): runs of consecutive rows (positions k in `rows`)
// whose rolls are solved, each one task; for each position, the positions whose roll mirrors its roll.
struct RollSchedule {
  std::vector<std::vector<std::size_t>> runs;
  std::vector<std::vector<std::size_t>> mirrors;
};
[[nodiscard]] RollSchedule roll_schedule(const SweepSetup& setup, const SweepPlan& plan,
                                         const std::vector<std::size_t>& rows);

// The rolls of one run (positions in `rows`, consecutive rows), each after the first searched from its
// predecessors'; then the rolls that mirror them, a failed source's mirror solved directly, so that its detail
// names its own dy.
void solve_roll_run(const SweepSetup& setup, const SweepPlan& plan, const std::vector<std::size_t>& rows,
                    const std::vector<std::size_t>& run, const std::vector<std::vector<std::size_t>>& mirrors,
                    std::vector<CaseRoll>& rolls);

// The warm-start chains among `rows` (lateral-shift indices): positions k in `rows`, each chain in solve order. A row
// continues the chain of its warm_start_previous_rows row when that row is selected too (shards hold whole units,
// so their chains are those of the full sweep); without warm start every row is a chain of its own.
[[nodiscard]] std::vector<std::vector<std::size_t>> warm_start_chains(const SweepSetup& setup, const SweepPlan& plan,
                                                                      const std::vector<std::size_t>& rows);

// The order the chains are solved in: by the smallest |dy| of their rows, so that the first chains need the rolls
// of the first roll runs (those of the smallest |dy| >= 0, and their mirrors), and the dearer flange chains come
// before the last, cheap ones far out.
[[nodiscard]] std::vector<std::size_t> chain_order(const SweepPlan& plan, const std::vector<std::size_t>& rows,
                                                   const std::vector<std::vector<std::size_t>>& chains);

}  // namespace ctab::gen::detail
