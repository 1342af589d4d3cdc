// SPDX-License-Identifier: Apache-2.0
#pragma once
//! A progress line on stderr for the long benchmarks (`ctab bench lookup`, `bench generate`): "label: k/n runs",
//! redrawn in place on a terminal (the cursor left at its start, so that the figures overwrite it); with
//! --progress also where stderr is not one (a line per step). Silent otherwise: piped output is the figures alone.
#include <unistd.h>

#include <cstdio>

namespace ctab::cli {

class BenchProgress {
 public:
  BenchProgress(bool asked, int total) noexcept
      : terminal_(::isatty(STDERR_FILENO) != 0), on_(asked || terminal_), total_(total) {}
  BenchProgress(const BenchProgress&) = delete;
  BenchProgress& operator=(const BenchProgress&) = delete;
  ~BenchProgress() {
    if (on_ && terminal_ && done_ > 0) std::fputs("\r\033[K", stderr);  // the figures follow on a clean line
  }
  //! One run of `total` is about to start; `label` names it.
  void step(const char* label) noexcept {
    if (!on_) return;
    ++done_;
    std::fprintf(stderr, terminal_ ? "\r\033[K%s: %d/%d runs\r" : "%s: %d/%d runs\n", label, done_, total_);
    std::fflush(stderr);
  }

 private:
  bool terminal_;
  bool on_;
  int total_;
  int done_ = 0;
};

}  // namespace ctab::cli
