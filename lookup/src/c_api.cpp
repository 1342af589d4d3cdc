// SPDX-License-Identifier: Apache-2.0
// The C API over ctab::lookup::Table (ctab_lookup.h).
#include <cmath>
#include <limits>

#include "c_handle.hpp"
#include "ctab/lookup/open.hpp"

using ctab::lookup::Table;
using ctab::lookup::detail::load_options;
using ctab::lookup::detail::make_handle;

extern "C" {

ctab_status ctab_table_open(const char* path, const ctab_open_options* options, ctab_table** table) {
  if (path == nullptr) return table ? (*table = nullptr, CTAB_INVALID_INPUT) : CTAB_INVALID_INPUT;
  return make_handle(table, [&](Table& t) { return ctab::lookup::open_blob_file(path, load_options(options), t); });
}

ctab_status ctab_table_open_memory(const void* data, size_t size, const ctab_open_options* options,
                                   ctab_table** table) {
  return make_handle(table, [&](Table& t) { return ctab::lookup::open_memory(data, size, load_options(options), t); });
}

void ctab_table_close(ctab_table* table) { delete table; }

uint32_t ctab_table_dy_count(const ctab_table* table) { return table ? table->table.n_dy() : 0; }
uint32_t ctab_table_second_count(const ctab_table* table) { return table ? table->table.n_second() : 0; }
uint32_t ctab_table_slot_count(const ctab_table* table) { return table ? table->table.n_slots() : 0; }
uint32_t ctab_table_strip_samples(const ctab_table* table) { return table ? table->table.strip_samples() : 0; }
double ctab_table_dy_min(const ctab_table* table) {
  return table ? table->table.dy_min() : std::numeric_limits<double>::quiet_NaN();
}
double ctab_table_dy_max(const ctab_table* table) {
  return table ? table->table.dy_max() : std::numeric_limits<double>::quiet_NaN();
}
double ctab_table_second_value(const ctab_table* table, uint32_t i) {
  if (table == nullptr || i >= table->table.n_second()) return std::numeric_limits<double>::quiet_NaN();
  return table->table.second_axis()[i];
}
const char* ctab_table_second_axis_name(const ctab_table* table) {
  return table ? ctab::lookup::second_axis_name(table->table.second_axis_kind()) : "";
}
size_t ctab_table_memory_bytes(const ctab_table* table) { return table ? table->table.memory_bytes() : 0; }

ctab_status ctab_prelookup(const ctab_table* table, double dy_m, double second, ctab_location* out) {
  if (out == nullptr) return CTAB_INVALID_INPUT;
  if (table == nullptr) {
    *out = ctab_location{};
    out->status = CTAB_NOT_LOADED;
    return CTAB_NOT_LOADED;
  }
  table->table.prelookup(dy_m, second, *out);
  return static_cast<ctab_status>(out->status);
}

ctab_status ctab_query_prelooked(const ctab_table* table, const ctab_location* where, int32_t wheel, ctab_result* out) {
  if (out == nullptr) return CTAB_INVALID_INPUT;
  if (table == nullptr) {
    ctab::lookup::fill_not_loaded(*out);
    return CTAB_NOT_LOADED;
  }
  ctab_location invalid{};
  invalid.status = CTAB_INVALID_INPUT;
  table->table.query(where ? *where : invalid, wheel, *out);
  return static_cast<ctab_status>(out->status);
}

ctab_status ctab_query(const ctab_table* table, double dy_m, double second, int32_t wheel, ctab_result* out) {
  ctab_location where;
  ctab_prelookup(table, dy_m, second, &where);
  return ctab_query_prelooked(table, &where, wheel, out);
}

ctab_status ctab_strip_profile(const ctab_table* table, const ctab_location* where, int32_t wheel, int32_t slot,
                               double* s_m, double* half_length_m, double* peak_pressure_Pa, uint32_t capacity,
                               uint32_t* count) {
  if (count) *count = 0;
  if (table == nullptr) return CTAB_NOT_LOADED;
  if (where == nullptr) return CTAB_INVALID_INPUT;
  return table->table.strip_profile(*where, wheel, slot, s_m, half_length_m, peak_pressure_Pa, capacity, count);
}

const char* ctab_version(void) { return CTAB_VERSION_STRING; }

void ctab_version_numbers(int32_t* major, int32_t* minor, int32_t* patch) {
  if (major) *major = CTAB_VERSION_MAJOR;
  if (minor) *minor = CTAB_VERSION_MINOR;
  if (patch) *patch = CTAB_VERSION_PATCH;
}

const char* ctab_status_message(int32_t status) {
  switch (status) {
    case CTAB_OK: return "ok";
    case CTAB_CLAMPED: return "query outside the table range: answered at the nearest edge";
    case CTAB_INVALID_INPUT: return "invalid input (NaN or infinite value, wheel or slot out of range, null pointer)";
    case CTAB_NOT_LOADED: return "no table loaded";
    case CTAB_ERR_CANNOT_OPEN: return "cannot open or read the file";
    case CTAB_ERR_NOT_A_TABLE: return "not a ctab table (neither a ctab blob nor an HDF5 table), or truncated";
    case CTAB_ERR_VERSION: return "unsupported blob format or table schema version";
    case CTAB_ERR_CHECKSUM: return "blob checksum mismatch (corrupted)";
    case CTAB_ERR_AXES:
      return "bad axes (fewer than 2 dy values, not finite, not increasing, a step too small to divide by, or dy "
             "refined below 1/64 of its mean step)";
    case CTAB_ERR_SHAPE: return "array sizes do not match the axes, slots or strip samples, or beyond the size limit";
    case CTAB_ERR_CONTENT:
      return "bad content (non-finite value or beyond 1e300, beyond the float range in single precision, PCHIP slopes "
             "that overflow, unknown case status, presence not 0/1, bad jump)";
    case CTAB_ERR_OUT_OF_MEMORY: return "out of memory";
    case CTAB_ERR_HDF5_UNAVAILABLE: return "an HDF5 table, but this build loads blobs only (use ctab export)";
    default: return "unknown status";
  }
}

}  // extern "C"
