#include "table_output.hpp"

#include <unistd.h>

#include <cstdio>
#include <utility>

#include "exit_codes.hpp"
#include "output_guard.hpp"

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

void write_table_checked(const tables::Table& table, const std::string& output) {
  const tables::TableResult written = tables::write_table(table, output);
  if (written.ok()) return;
  // The writer names its temporary file in some messages; the user gave OUTPUT, so messages name OUTPUT.
  std::string message = written.message;
  const std::string temporary = temporary_table_path(output);
  for (auto at = message.find(temporary); at != std::string::npos; at = message.find(temporary, at + output.size()))
    message.replace(at, temporary.size(), output);
  throw IoError(message);
}

}  // namespace ctab::cli
