// SPDX-License-Identifier: Apache-2.0
#pragma once
//! What `generate`, `batch` and `merge` share when they write tables: the progress display and the checked write.
#include <chrono>
#include <cstddef>
#include <string>

#include "ctab/tables/table.hpp"

namespace ctab::cli {

//! A progress bar on a terminal (stderr), a plain line every few seconds otherwise; nothing when quiet.
class ProgressReporter {
 public:
  //! `label` starts the plain lines ("ctab generate").
  ProgressReporter(bool quiet, std::string label);
  void operator()(std::size_t done, std::size_t total);

 private:
  bool quiet_, terminal_;
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  double last_line_ = -1e9;
};

//! Writes `table` to `output` atomically (tables::write_table: a temporary file renamed on success); a failure
//! throws IoError naming OUTPUT (not the temporary file). The chunks are compressed on `threads` OpenMP threads
//! (0: OpenMP's default, at most kMaxThreads); the file's bytes do not depend on it.
void write_table_checked(const tables::Table& table, const std::string& output, int threads = 0);
//! tables::write_table's chunks on `threads` OpenMP threads (0: OpenMP's default, at most kMaxThreads).
[[nodiscard]] tables::ParallelFor openmp_parallel_for(int threads);

}  // namespace ctab::cli
