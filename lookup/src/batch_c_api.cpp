// SPDX-License-Identifier: Apache-2.0
// ctab_query_batch: n points of one wheel in one call, into flat caller-owned arrays (the Python wrapper's numpy
// arrays). Each point is ctab_query's answer; the batch adds no allocation.
#include <cstring>
#include <limits>

#include "c_handle.hpp"

namespace {

// The more severe of two statuses: any failure (< 0) before CTAB_CLAMPED before CTAB_OK.
ctab_status more_severe(ctab_status a, ctab_status b) {
  if (a < 0 || b < 0) return a < b ? a : b;
  return a > b ? a : b;
}

// Point i's slots into the flat outputs.
void store(const ctab_result& result, std::size_t i, uint32_t n_slots, double* quantities, int8_t* present) {
  for (uint32_t s = 0; s < n_slots; ++s) {
    const std::size_t at = i * n_slots + s;
    if (quantities != nullptr)
      std::memcpy(quantities + at * CTAB_QUANTITIES, result.patch[s].q, sizeof result.patch[s].q);
    if (present != nullptr) present[at] = static_cast<int8_t>(result.patch[s].present);
  }
}

}  // namespace

extern "C" ctab_status ctab_query_batch(const ctab_table* table, const double* dy_m, const double* second,
                                        size_t n, int32_t wheel, int32_t* status, double* quantities,
                                        int8_t* present) {
  if (n > 0 && dy_m == nullptr) return CTAB_INVALID_INPUT;
  const uint32_t n_slots = ctab_table_slot_count(table);
  const double no_second = std::numeric_limits<double>::quiet_NaN();  // refused where the table has several
  ctab_status worst = CTAB_OK;
  ctab_result result;
  for (std::size_t i = 0; i < n; ++i) {
    const ctab_status point = ctab_query(table, dy_m[i], second ? second[i] : no_second, wheel, &result);
    if (status != nullptr) status[i] = point;
    store(result, i, n_slots, quantities, present);
    worst = more_severe(worst, point);
  }
  return worst;
}
