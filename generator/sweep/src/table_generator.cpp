// SPDX-License-Identifier: Apache-2.0
// The table sweep (table_generator.hpp): every selected row's rolls and wheel solves in one OpenMP region, the
// results stored in the table, the slots, jumps and provenance added; TableSweep for a sweep in parts and
// generate_table for the whole one.
#include "ctab/sweep/table_generator.hpp"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "adaptive_axis.hpp"
#include "ctab/sweep/slot_assignment.hpp"
#include "parallel_loop.hpp"
#include "sweep_plan.hpp"
#include "sweep_schedule.hpp"
#include "table_provenance.hpp"

namespace ctab::gen {

using detail::SweepPlan;

namespace {

// Runs `work` on this thread, whose OpenMP threads (started once, generate_table) also serve the table's write,
// while a reporter thread calls `progress` every 0.1 s (no I/O in the parallel region); no reporter without
// `progress`.
void run_with_progress(const std::function<void()>& work, const std::atomic<std::size_t>& done, std::size_t total,
                       const ProgressCallback& progress) {
  if (!progress) return work();
  std::mutex mutex;
  std::condition_variable finished_signal;
  bool finished = false;
  std::thread reporter([&] {
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished) {
      lock.unlock();
      progress(done.load(std::memory_order_relaxed), total);
      lock.lock();
      finished_signal.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; });
    }
  });
  const auto stop_reporter = [&] {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      finished = true;
    }
    finished_signal.notify_one();
    reporter.join();
  };
  try {
    work();
  } catch (...) {
    stop_reporter();
    throw;
  }
  stop_reporter();
  progress(total, total);
}

// Rolls (one per selected lateral shift) and every solved wheel of every selected case, in one parallel region:
// items are handed out in order from one counter, first the roll runs, then the wheel tasks (one warm-start chain
// of one side and one load each, writing only its own slots). A wheel task waits for its rows' rolls, which are
// then either done or being solved by a thread that waits for nothing (every roll run was handed out before any
// wheel task), so the region cannot stall; no barrier between the rolls and the solves. `rows` are lateral-shift
// indices; results are indexed (side, k, i_second) with k the position in `rows`, rolls by k. A case's solve
// depends on nothing but its own inputs and its chain, so any subset of whole chains gives the same values at any
// thread count, in any order.
std::vector<CaseWheel> sweep(const SweepSetup& setup, const SweepPlan& plan, const std::vector<std::size_t>& rows,
                             std::vector<CaseRoll>& rolls, const ProgressCallback& progress) {
  const std::size_t n_rows = rows.size(), n_second = plan.load_values.size(), row_cases = n_rows * n_second;
  const std::size_t total = row_cases * plan.sides;
  const std::vector<std::vector<std::size_t>> chains = detail::warm_start_chains(setup, plan, rows);
  const std::vector<std::size_t> order = detail::chain_order(plan, rows, chains);
  const std::size_t side_tasks = chains.size() * n_second, tasks = side_tasks * plan.sides;
  const detail::RollSchedule schedule = detail::roll_schedule(setup, plan, rows);
  const std::vector<std::vector<std::size_t>>& runs = schedule.runs;
  std::vector<std::atomic<bool>> roll_ready(n_rows);  // value-initialised: false
  rolls = std::vector<CaseRoll>(n_rows);
  std::vector<CaseWheel> results(total);
  std::vector<WheelContactWorkspace> workspaces(static_cast<std::size_t>(plan.threads));  // one per thread
  std::atomic<std::size_t> done{0}, next_item{0};
  const std::size_t items = runs.size() + tasks;
  auto work = [&] {
#pragma omp parallel num_threads(plan.threads)
    {
      WheelContactWorkspace& workspace = workspaces[static_cast<std::size_t>(omp_get_thread_num())];
      for (std::size_t item = next_item.fetch_add(1); item < items; item = next_item.fetch_add(1)) {
        if (item < runs.size()) {
          const std::vector<std::size_t>& run = runs[item];
          detail::solve_roll_run(setup, plan, rows, run, schedule.mirrors, rolls);
          for (const std::size_t k : run) {
            roll_ready[k].store(true, std::memory_order_release);
            for (const std::size_t m : schedule.mirrors[k]) roll_ready[m].store(true, std::memory_order_release);
          }
          continue;
        }
        const std::size_t task = item - runs.size(), side = task / side_tasks, rest = task % side_tasks;
        const std::vector<std::size_t>& chain = chains[order[rest / n_second]];
        const std::size_t i_second = rest % n_second;
        Mim1dWarmStart warm;  // the chain's first row starts cold
        for (const std::size_t k : chain) {
          while (!roll_ready[k].load(std::memory_order_acquire)) std::this_thread::yield();
          results[side * row_cases + k * n_second + i_second] =
              solve_case_wheel(setup, side, plan.dy_m[rows[k]], rolls[k], plan.load_values[i_second], workspace, &warm);
          done.fetch_add(1, std::memory_order_relaxed);
        }
      }
    }
  };
  run_with_progress(work, done, total, progress);
  return results;
}

tables::Table empty_table(const TableConfig& config, const SweepPlan& plan) {
  tables::Table table;
  table.lateral_displacement_m = plan.dy_m;
  table.second_axis = plan.load_values;
  table.second_axis_name = load_axis_name(config.load_kind);
  table.second_axis_units =
      std::string(1, config.load_kind == LoadKind::Approach ? 'm'
                                                            : 'N');  // not a literal: GCC 12 -Wrestrict false positive
  table.strip_samples = config.strip_samples;
  table.n_slots = config.patch_slots;
  table.allocate();
  return table;
}

// Stores the rows `rows` of the sweep's results (see sweep) in `table`.
void assemble(tables::Table& table, const SweepSetup& setup, const SweepPlan& plan,
              const std::vector<std::size_t>& rows, const std::vector<CaseRoll>& rolls,
              const std::vector<CaseWheel>& results) {
  const std::size_t n_dy = plan.dy_m.size(), n_second = plan.load_values.size(), row_cases = rows.size() * n_second;
  std::vector<std::size_t> position(n_dy, n_dy);  // k of each selected row, n_dy elsewhere
  for (std::size_t k = 0; k < rows.size(); ++k) position[rows[k]] = k;
  // Each row's cases write only that row's entries (and read the results): the rows in parallel.
  detail::parallel_loop(rows.size(), plan.threads, false, [&](std::size_t k) {
    for (std::size_t i_second = 0; i_second < n_second; ++i_second) {
      const std::size_t i_dy = rows[k];
      const CaseWheel& right = results[k * n_second + i_second];
      // Mirrored: the left wheel at dy is the right wheel at -dy (index n_dy - 1 - i_dy of a symmetric axis).
      const CaseWheel& left = plan.mirrored ? results[position[n_dy - 1 - i_dy] * n_second + i_second]
                                            : results[row_cases + k * n_second + i_second];
      store_case_wheel(table, setup, i_dy, i_second, 0, right);
      store_case_wheel(table, setup, i_dy, i_second, 1, left);
      const std::size_t c = i_dy * n_second + i_second;
      table.roll_rad[c] = rolls[k].roll_rad;
      table.rolling_radius_difference_m[c] =
          right.contact.rigid_contact.rolling_radius_m - left.contact.rigid_contact.rolling_radius_m;
    }
  });
}

}  // namespace

// ---- a sweep in parts ----

// The set-up and plan of a config; with [axes] tolerance the axis is decided here (every node solved).
struct TableSweep::Impl {
  Impl(const TableConfig& c, const GeneratorInfo& i)
      : config(c), setup(make_sweep_setup(c)), plan(detail::make_plan(c, i)), info(i) {
    if (!config.axis_tolerance) return;
    adaptive = detail::decide_adaptive_axis(config, setup, plan);
    plan.dy_m = adaptive->dy_m;
  }
  TableConfig config;
  SweepSetup setup;
  SweepPlan plan;
  GeneratorInfo info;
  std::optional<detail::AdaptiveAxis> adaptive;  // [axes] tolerance: the decided axis and its solutions
};

namespace {

// The adaptive axis's solutions of `rows`, in the layout of sweep().
std::vector<CaseWheel> adaptive_results(const detail::AdaptiveAxis& axis, const SweepPlan& plan,
                                        const std::vector<std::size_t>& rows, std::vector<CaseRoll>& rolls) {
  const std::size_t n = axis.dy_m.size(), loads = plan.load_values.size();
  std::vector<CaseWheel> results(plan.sides * rows.size() * loads);
  rolls.clear();
  for (std::size_t k = 0; k < rows.size(); ++k) {
    rolls.push_back(axis.rolls[rows[k]]);
    for (std::size_t side = 0; side < plan.sides; ++side)
      for (std::size_t l = 0; l < loads; ++l)
        results[(side * rows.size() + k) * loads + l] = axis.results[(side * n + rows[k]) * loads + l];
  }
  return results;
}

// The tolerance, the cell errors and the located jumps of an adaptive axis (after the slots are assigned).
void add_adaptive_axis(tables::Table& table, const TableConfig& config, const detail::AdaptiveAxis& axis) {
  const AxisTolerance& tolerance = *config.axis_tolerance;
  const double values[tables::kCellErrorQuantities] = {tolerance.force_rel, tolerance.area_rel,
                                                       tolerance.contact_point_m, tolerance.lateral_force_rel};
  for (std::size_t q = 0; q < tables::kCellErrorQuantities; ++q)
    table.number_attributes[tables::kToleranceAttributes[q]] = values[q];
  table.number_attributes["tolerance_min_step_m"] = tolerance.min_step_m;
  table.integer_attributes["axis_coarse_points"] = static_cast<std::int64_t>(axis.coarse_points);
  table.integer_attributes["axis_solved_points"] = static_cast<std::int64_t>(axis.solved_points);
  table.cell_error = axis.cell_error;
  table.jumps = tables::table_jumps(table);
}

}  // namespace

TableSweep::TableSweep(const TableConfig& config, const GeneratorInfo& info)
    : impl_(std::make_unique<Impl>(config, info)) {}
TableSweep::~TableSweep() = default;
TableSweep::TableSweep(TableSweep&&) noexcept = default;

std::size_t TableSweep::n_dy() const noexcept { return impl_->plan.dy_m.size(); }
bool TableSweep::mirrored() const noexcept { return impl_->plan.mirrored; }
std::size_t TableSweep::wheel_solves(std::size_t rows) const noexcept {
  return rows * impl_->plan.load_values.size() * impl_->plan.sides;
}
tables::Table TableSweep::empty_table() const { return gen::empty_table(impl_->config, impl_->plan); }

void TableSweep::solve_rows(const std::vector<std::size_t>& rows, tables::Table& table,
                            const ProgressCallback& progress) const {
  const std::size_t n = n_dy();
  std::vector<bool> selected(n, false);
  for (const std::size_t i : rows) {
    if (i >= n || selected[i]) throw std::invalid_argument("TableSweep::solve_rows: a row out of range or repeated");
    selected[i] = true;
  }
  if (mirrored())
    for (const std::size_t i : rows)
      if (!selected[n - 1 - i])
        throw std::invalid_argument("TableSweep::solve_rows: rows of a mirrored sweep must be mirror-closed");
  std::vector<CaseRoll> rolls;
  const std::vector<CaseWheel> results = impl_->adaptive
                                             ? adaptive_results(*impl_->adaptive, impl_->plan, rows, rolls)
                                             : sweep(impl_->setup, impl_->plan, rows, rolls, progress);
  assemble(table, impl_->setup, impl_->plan, rows, rolls, results);
}

void TableSweep::finish(tables::Table& table) const {
  assign_table_slots_along_dy(table, impl_->plan.threads);  // on all rows: slots follow the contacts along dy
  table.jumps = tables::detect_jumps(table);
  detail::add_provenance(table, impl_->config, impl_->setup, impl_->plan, impl_->info);
  if (impl_->adaptive) add_adaptive_axis(table, impl_->config, *impl_->adaptive);
}

namespace {

// Starts the calling thread's OpenMP team of `threads` (nothing for 1): a team's first region waits until every
// thread runs, which later regions of the same thread do not.
void start_openmp_threads(int threads) noexcept {
  if (threads <= 1) return;
  std::atomic<int> started{0};  // a region with a body: GCC drops an empty one
#pragma omp parallel num_threads(threads)
  started.fetch_add(1, std::memory_order_relaxed);
}

// The first parallel region of a thread creates its OpenMP threads and waits until every one of them runs: on a
// loaded or virtual machine up to a scheduler tick, with every thread of the team idle. So the
// calling thread starts its team (and the HDF5 library) while a helper thread loads the profiles and builds the
// set-up; the sweep and the table's write then run on the started team. Without threads to start, the set-up runs
// here.
TableSweep make_sweep_starting_threads(const TableConfig& config, const GeneratorInfo& info) {
  if (info.threads <= 1) return TableSweep(config, info);
  std::optional<TableSweep> sweep;
  std::exception_ptr error;
  std::thread setup([&] {
    try {
      sweep.emplace(config, info);
    } catch (...) {
      error = std::current_exception();
    }
  });
  start_openmp_threads(info.threads);
  tables::start_hdf5();  // for the write, here rather than after the sweep (the set-up never calls HDF5)
  setup.join();
  if (error) std::rethrow_exception(error);
  return std::move(*sweep);
}

}  // namespace

tables::Table generate_table(const TableConfig& config, const GeneratorInfo& info, const ProgressCallback& progress) {
  const TableSweep sweep = make_sweep_starting_threads(config, info);
  std::vector<std::size_t> rows(sweep.n_dy());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  tables::Table table = sweep.empty_table();
  sweep.solve_rows(rows, table, progress);
  sweep.finish(table);
  return table;
}

}  // namespace ctab::gen
