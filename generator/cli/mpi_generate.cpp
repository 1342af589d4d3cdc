// SPDX-License-Identifier: Apache-2.0
// `mpirun -n R ctab generate`: work units handed out by rank 0, packed rows gathered to it (mpi_generate.hpp).
#include "mpi_generate.hpp"

#include <mpi.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "ctab/core/error.hpp"
#include "ctab/sweep/case_partition.hpp"
#include "ctab/sweep/table_rows.hpp"

namespace ctab::cli {

namespace {

constexpr int kRoot = 0;
constexpr int kTagAssign = 1;  // rank 0 -> worker: one std::int64_t, a unit index or kStop
constexpr int kTagResult = 2;  // worker -> rank 0: ResultHeader, then the unit's packed rows (none when failed)
constexpr std::int64_t kStop = -1;
// Rank 0's main thread sleeps this long when no result is waiting (its solving thread works meanwhile).
constexpr auto kPollInterval = std::chrono::microseconds(200);

struct ResultHeader {
  std::int64_t unit = 0;
  std::int64_t failed = 0;  // 1: the worker's solve threw; no rows follow
};

bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

// Every rank says whether its set-up succeeded; true when all did.
bool all_ranks_ready(bool ready) {
  int mine = ready ? 1 : 0, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

void send_assignment(int worker, std::int64_t unit) {
  MPI_Send(&unit, 1, MPI_INT64_T, worker, kTagAssign, MPI_COMM_WORLD);
}

// The failure path under test: a worker whose rank is CTAB_MPI_TEST_FAIL_RANK throws in every unit it solves.
bool injected_failure(int rank) {
  const char* text = std::getenv("CTAB_MPI_TEST_FAIL_RANK");
  return text != nullptr && std::atoi(text) == rank;
}

// A worker: solve assigned units into a scratch table and send their rows back until told to stop. The blocking
// send returns at once: rank 0's main thread does nothing but serve messages (a message of more than a few
// kilobytes is delivered only while both ranks are inside MPI).
void run_worker(const gen::TableSweep& sweep, const std::vector<std::vector<std::size_t>>& units, int rank) {
  tables::Table scratch = sweep.empty_table();
  const bool fail = injected_failure(rank);
  for (;;) {
    std::int64_t unit = kStop;
    MPI_Recv(&unit, 1, MPI_INT64_T, kRoot, kTagAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (unit == kStop) return;
    const std::vector<std::size_t>& rows = units.at(static_cast<std::size_t>(unit));
    ResultHeader header{unit, 0};
    std::vector<unsigned char> packed;
    try {
      if (fail) throw std::runtime_error("CTAB_MPI_TEST_FAIL_RANK");
      sweep.solve_rows(rows, scratch);
      packed = gen::pack_rows(scratch, rows);
    } catch (const std::exception&) {
      header.failed = 1;  // rank 0 marks the unit's cases SolverException
      packed.clear();
    }
    const auto* header_bytes = reinterpret_cast<const unsigned char*>(&header);
    std::vector<unsigned char> message(header_bytes, header_bytes + sizeof header);
    message.insert(message.end(), packed.begin(), packed.end());
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_BYTE, kRoot, kTagResult, MPI_COMM_WORLD);
  }
}

// Rank 0: its main thread hands out units and stores results (and alone calls MPI); a second thread solves units
// too (OpenMP inside), taking them from the same queue. Both write disjoint rows of the table.
class Root {
 public:
  Root(const gen::TableSweep& sweep, const std::vector<std::vector<std::size_t>>& units, int workers,
       const gen::ProgressCallback& progress)
      : sweep_(sweep), units_(units), workers_(workers), progress_(progress), table_(sweep.empty_table()) {
    for (const auto& unit : units) total_solves_ += sweep.wheel_solves(unit.size());
  }

  tables::Table run() {
    for (int round = 0; round < kUnitsInFlight; ++round)
      for (int worker = 1; worker <= workers_; ++worker)
        if (const auto unit = take_unit()) send_assignment(worker, static_cast<std::int64_t>(*unit));
    {
      const OwnSolver own(*this);
      while (received_ + own_units_.load() < units_.size()) {
        if (!receive_result()) std::this_thread::sleep_for(kPollInterval);
        const std::size_t done = solves_done_ + own_solves_.load();
        if (progress_ && done != reported_) progress_(reported_ = done, total_solves_);
      }
    }
    for (int worker = 1; worker <= workers_; ++worker) send_assignment(worker, kStop);
    return std::move(table_);
  }

 private:
  // The solving thread of rank 0, joined on destruction (also when the message loop throws).
  class OwnSolver {
   public:
    explicit OwnSolver(Root& root) : root_(root), thread_([this] { root_.solve_own_units(); }) {}
    ~OwnSolver() {
      root_.stop_ = true;
      thread_.join();
    }
    OwnSolver(const OwnSolver&) = delete;
    OwnSolver& operator=(const OwnSolver&) = delete;

   private:
    Root& root_;
    std::thread thread_;
  };

  std::optional<std::size_t> take_unit() {
    const std::lock_guard lock(mutex_);
    if (next_ >= units_.size()) return std::nullopt;
    return next_++;
  }

  void solve_own_units() noexcept {
    while (!stop_) {
      const auto unit = take_unit();
      if (!unit) return;
      const auto& rows = units_[*unit];
      try {
        sweep_.solve_rows(rows, table_);
      } catch (const std::exception&) {
        gen::fail_rows(table_, rows, tables::CaseStatus::SolverException);
      }
      own_solves_ += sweep_.wheel_solves(rows.size());
      ++own_units_;
    }
  }

  // Stores one waiting result, if any, and gives its worker the next unit; false when none was waiting.
  bool receive_result() {
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) return false;
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    std::vector<unsigned char> message(static_cast<std::size_t>(bytes));
    MPI_Recv(message.data(), bytes, MPI_BYTE, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    ResultHeader header{};
    const bool has_header = message.size() >= sizeof header;
    if (has_header) std::memcpy(&header, message.data(), sizeof header);
    if (!has_header || header.unit < 0 || static_cast<std::size_t>(header.unit) >= units_.size())
      throw std::runtime_error("MPI rank " + std::to_string(status.MPI_SOURCE) + " sent a malformed result");
    const auto& rows = units_[static_cast<std::size_t>(header.unit)];
    const std::vector<unsigned char> packed(message.begin() + sizeof header, message.end());
    if (header.failed != 0 || !gen::unpack_rows(table_, rows, packed))
      gen::fail_rows(table_, rows, tables::CaseStatus::SolverException);
    if (const auto unit = take_unit()) send_assignment(status.MPI_SOURCE, static_cast<std::int64_t>(*unit));
    ++received_;
    solves_done_ += sweep_.wheel_solves(rows.size());
    return true;
  }

  const gen::TableSweep& sweep_;
  const std::vector<std::vector<std::size_t>>& units_;
  int workers_;
  const gen::ProgressCallback& progress_;
  tables::Table table_;
  std::mutex mutex_;  // guards next_
  std::size_t next_ = 0;
  std::size_t received_ = 0, solves_done_ = 0, total_solves_ = 0, reported_ = 0;  // main thread only
  std::atomic<std::size_t> own_units_{0}, own_solves_{0};                         // written by the solving thread
  std::atomic<bool> stop_{false};
};

}  // namespace

MpiSession::MpiSession() {
  if (!launched_by_mpi()) return;
  int provided = 0;
  // Only the thread that called MPI_Init calls MPI; the OpenMP threads of the sweep never do.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  initialised_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (initialised_) MPI_Finalize();
}

std::optional<tables::Table> generate_table_mpi(const MpiSession& session, const gen::TableConfig& config,
                                                const gen::GeneratorInfo& info,
                                                const std::function<void()>& root_checks,
                                                const gen::ProgressCallback& progress) {
  std::exception_ptr setup_error;
  std::optional<gen::TableSweep> sweep;
  try {
    if (session.rank() == kRoot && root_checks) root_checks();
    sweep.emplace(config, info);
  } catch (...) {
    setup_error = std::current_exception();
  }
  if (!all_ranks_ready(setup_error == nullptr)) {
    if (setup_error) std::rethrow_exception(setup_error);
    if (session.rank() == kRoot)
      throw gen::InputError("ctab generate", 0, "the set-up failed on another MPI rank (its message says why)");
    return std::nullopt;
  }
  const auto units = gen::sweep_units(sweep->n_dy(), sweep->mirrored());
  if (session.rank() != kRoot) {
    run_worker(*sweep, units, session.rank());
    return std::nullopt;
  }
  tables::Table table = Root(*sweep, units, session.size() - 1, progress).run();
  sweep->finish(table);
  return table;
}

}  // namespace ctab::cli
