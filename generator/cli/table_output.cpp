// SPDX-License-Identifier: Apache-2.0
#include "table_output.hpp"

#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <utility>

#include "exit_codes.hpp"
#include "output_guard.hpp"
#include "setup_options.hpp"

namespace ctab::cli {

ProgressReporter::ProgressReporter(bool quiet, std::string label)
    : quiet_(quiet), terminal_(::isatty(STDERR_FILENO) != 0), label_(std::move(label)),
      start_(std::chrono::steady_clock::now()) {}

void ProgressReporter::operator()(std::size_t done, std::size_t total) {
  if (quiet_ || total == 0) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0.0;
  const double left = rate > 0 ? static_cast<double>(total - done) / rate : 0.0;
  if (terminal_) {
    const int width = 40, filled = static_cast<int>(width * static_cast<double>(done) / static_cast<double>(total));
    std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu cases, %.0f/s, %.1f s left ", filled,
                 "########################################", width - filled, "", done, total, rate, left);
    if (done == total) std::fputc('\n', stderr);
  } else if (done == total || elapsed - last_line_ >= 5.0) {
    last_line_ = elapsed;
    std::fprintf(stderr, "%s: %zu/%zu cases, %.0f cases/s, %.1f s left\n", label_.c_str(), done, total, rate, left);
  }
}

tables::ParallelFor openmp_parallel_for(int threads) {
  if (threads <= 0) threads = std::min(omp_get_max_threads(), kMaxThreads);
  return [threads](std::size_t count, const std::function<void(std::size_t)>& task) {
    const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (std::ptrdiff_t i = 0; i < n; ++i) task(static_cast<std::size_t>(i));
  };
}

void write_table_checked(const tables::Table& table, const std::string& output, int threads) {
  const tables::TableResult written = tables::write_table(table, output, openmp_parallel_for(threads));
  if (written.ok()) return;
  // The writer names its temporary file in some messages; the user gave OUTPUT, so messages name OUTPUT.
  std::string message = written.message;
  const std::string temporary = temporary_table_path(output);
  for (auto at = message.find(temporary); at != std::string::npos; at = message.find(temporary, at + output.size()))
    message.replace(at, temporary.size(), output);
  throw IoError(message);
}

}  // namespace ctab::cli
