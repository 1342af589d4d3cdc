// SPDX-License-Identifier: Apache-2.0
#pragma once
//! The creep part of `ctab bench lookup`: time of one patch's creep forces from its strip samples (median,
//! p99.99, max) per method, and of an 8-wheel HIL step (4 prelookups, 8 normal queries, 8 creep calls; mean, worst).
#include <cstddef>

#include "ctab/lookup/table.hpp"

namespace ctab::cli {

//! Prints the creep timings over `points` random points of `table`; `overhead_ns` is the clock's own cost.
void bench_creep(const lookup::Table& table, std::size_t points, double overhead_ns);

}  // namespace ctab::cli
