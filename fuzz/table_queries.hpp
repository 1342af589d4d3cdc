// SPDX-License-Identifier: Apache-2.0
#pragma once
// Queries of a loaded table for the fuzz targets of the blob and HDF5 loaders: whatever a table that loads holds,
// no query may crash or read out of bounds.
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "ctab/lookup/ctab_lookup.h"

namespace ctab::fuzz {

// The points of one axis worth querying: ends, middle, just outside, far outside, non-finite.
inline std::vector<double> probe_points(double low, double high) {
  const double inf = std::numeric_limits<double>::infinity();
  return {low, high, 0.5 * (low + high), low - 1e-3, high + 1e-3, -1e300, 1e300, inf, -inf,
          std::numeric_limits<double>::quiet_NaN(), std::nextafter(high, low), 0.0};
}

inline void strip_profiles(const ctab_table* table, const ctab_location& where, std::int32_t wheel) {
  const std::uint32_t capacity = ctab_table_strip_samples(table);
  std::vector<double> s(capacity), a(capacity), p0(capacity);
  for (std::int32_t slot = -1; slot <= static_cast<std::int32_t>(ctab_table_slot_count(table)); ++slot) {
    std::uint32_t count = 0;
    static_cast<void>(ctab_strip_profile(table, &where, wheel, slot, s.data(), a.data(), p0.data(), capacity, &count));
  }
}

//! Every wheel (and -1, 2) and every slot's strip profile at each axis's ends, inside, outside and non-finite points.
inline void query_everywhere(const ctab_table* table) {
  const std::uint32_t n_second = ctab_table_second_count(table);
  const double second_low = ctab_table_second_value(table, 0);
  const double second_high = ctab_table_second_value(table, n_second - 1);
  for (const double dy : probe_points(ctab_table_dy_min(table), ctab_table_dy_max(table)))
    for (const double second : probe_points(second_low, second_high)) {
      ctab_location where;
      static_cast<void>(ctab_prelookup(table, dy, second, &where));
      for (std::int32_t wheel = -1; wheel <= 2; ++wheel) {
        ctab_result result;
        static_cast<void>(ctab_query_prelooked(table, &where, wheel, &result));
        static_cast<void>(ctab_query(table, dy, second, wheel, &result));
        if (wheel == 0 || wheel == 1) strip_profiles(table, where, wheel);
      }
    }
  static_cast<void>(ctab_table_second_axis_name(table));
  static_cast<void>(ctab_table_memory_bytes(table));
}

}  // namespace ctab::fuzz
