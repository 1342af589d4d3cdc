// SPDX-License-Identifier: Apache-2.0
#pragma once
//! `mpirun -n R ctab generate ...` (and `batch`): the sweep across MPI ranks (hybrid MPI x OpenMP), built with CTAB_WITH_MPI.
//!
//! Rank 0 hands out work units (case_partition.hpp: mirror-closed blocks of rows_per_unit lateral-shift rows)
//! dynamically: each worker holds up to kUnitsInFlight assigned units, sends every solved unit back as packed rows
//! (table_rows.hpp) and gets the next one; rank 0 solves units too, on a second thread, while its main thread
//! serves the messages (and alone calls MPI: MPI_THREAD_FUNNELED). Every rank solves with
//! TableSweep::solve_rows (OpenMP inside the rank), a case does not depend on which rows are solved with it, and
//! slots and jumps are assigned by TableSweep::finish on rank 0 over the whole table, so the table is bit-identical
//! to a single-process run. A worker whose unit throws reports the unit as failed (its cases SolverException); a
//! set-up error on any rank (a profile missing on one machine, a bad output path on rank 0) stops every rank.
//! Rank 0's main thread polls (MPI_Iprobe) and sleeps briefly, so it answers every worker within a fraction of a
//! millisecond; workers block only for their next assignment, which rank 0 always sends (a unit or stop). A rank
//! that dies ends the job through mpirun. `mpirun -n R ctab batch` runs each pair this way (batch_command.cpp).
//! For the tests only: the environment variable CTAB_MPI_TEST_FAIL_RANK=K makes worker rank K throw in each unit.
#include <functional>
#include <optional>

#include "ctab/sweep/table_config.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/tables/table.hpp"

namespace ctab::cli {

//! MPI_Init on construction when this process was started by an MPI launcher (mpirun sets OMPI_COMM_WORLD_SIZE,
//! PMI_SIZE or PMIX_RANK), MPI_Finalize on destruction; a plain run touches no MPI.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  [[nodiscard]] int rank() const noexcept { return rank_; }
  [[nodiscard]] int size() const noexcept { return size_; }  //!< 1 when not started by a launcher

 private:
  bool initialised_ = false;
  int rank_ = 0, size_ = 1;
};

//! Units each worker holds at once: one being solved, one waiting, so that a worker never waits for rank 0.
inline constexpr int kUnitsInFlight = 2;

//! The table of `config` solved by every rank of `session` (size >= 2). `root_checks` runs on rank 0 before any
//! solving (the output path check); its exception, or a set-up exception on any rank, is rethrown on the rank that
//! threw after every rank has stopped (the others return nullopt). Returns the finished table on rank 0 and nullopt
//! on the workers. `progress` is called on rank 0 with wheel solves done and total.
[[nodiscard]] std::optional<tables::Table> generate_table_mpi(const MpiSession& session, const gen::TableConfig& config,
                                                              const gen::GeneratorInfo& info,
                                                              const std::function<void()>& root_checks,
                                                              const gen::ProgressCallback& progress);

}  // namespace ctab::cli
