// SPDX-License-Identifier: Apache-2.0
#pragma once
// A parallel loop whose body may throw (only on failures such as memory: the bodies here compute no statuses from
// exceptions): nothing escapes an OpenMP loop, so the first exception is kept and rethrown after it.
#include <algorithm>
#include <cstddef>
#include <exception>

namespace ctab::gen::detail {

//! body(i) for i in [0, count) on `threads` OpenMP threads (static schedule when `dynamic` is false).
template <class Body>
void parallel_loop(std::size_t count, int threads, bool dynamic, const Body& body) {
  const auto n = static_cast<std::ptrdiff_t>(count);
  std::exception_ptr failure;
  const auto guarded = [&](std::ptrdiff_t i) {
    try {
      body(static_cast<std::size_t>(i));
    } catch (...) {
#pragma omp critical(ctab_parallel_loop_failure)
      if (!failure) failure = std::current_exception();
    }
  };
  if (dynamic) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(std::max(threads, 1))
    for (std::ptrdiff_t i = 0; i < n; ++i) guarded(i);
  } else {
#pragma omp parallel for schedule(static) num_threads(std::max(threads, 1))
    for (std::ptrdiff_t i = 0; i < n; ++i) guarded(i);
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace ctab::gen::detail
