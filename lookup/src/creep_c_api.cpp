// SPDX-License-Identifier: Apache-2.0
// The C API of the creep forces (ctab_lookup.h, "Creep forces") and ctab_struct_size for bindings.
#include <cstring>

#include "c_handle.hpp"
#include "ctab/lookup/creep.hpp"

extern "C" {

ctab_status ctab_creep_prelooked(const ctab_table* table, const ctab_location* where, int32_t wheel,
                                 const ctab_creep_input* input, ctab_creep_result* out) {
  if (out == nullptr) return CTAB_INVALID_INPUT;
  if (table == nullptr) {
    std::memset(out, 0, sizeof *out);
    out->status = CTAB_NOT_LOADED;
    return CTAB_NOT_LOADED;
  }
  if (where == nullptr || input == nullptr) {
    std::memset(out, 0, sizeof *out);
    out->status = CTAB_INVALID_INPUT;
    out->n_slots = static_cast<int32_t>(table->table.n_slots());
    return CTAB_INVALID_INPUT;
  }
  return ctab::lookup::creep_query(table->table, *where, wheel, *input, *out);
}

ctab_status ctab_creep_batch(const ctab_table* table, size_t n, const double* dy_m, const double* second,
                             const int32_t* wheel, const ctab_creep_input* inputs, ctab_creep_result* out) {
  if (n > 0 && (dy_m == nullptr || second == nullptr || wheel == nullptr || inputs == nullptr || out == nullptr))
    return CTAB_INVALID_INPUT;
  ctab_status worst = CTAB_OK;
  for (size_t i = 0; i < n; ++i) {
    ctab_location where;
    ctab_prelookup(table, dy_m[i], second[i], &where);
    const ctab_status status = ctab_creep_prelooked(table, &where, wheel[i], &inputs[i], &out[i]);
    if (status < worst || (worst == CTAB_OK && status != CTAB_OK)) worst = status;
  }
  return worst;
}

ctab_status ctab_creep_slot_prelooked(const ctab_table* table, const ctab_location* where, int32_t wheel, int32_t slot,
                                      const ctab_creep_input* input, ctab_creep_patch* out) {
  if (out == nullptr) return CTAB_INVALID_INPUT;
  std::memset(out, 0, sizeof *out);
  out->status = table == nullptr ? CTAB_NOT_LOADED : CTAB_INVALID_INPUT;
  if (table == nullptr || where == nullptr || input == nullptr) return static_cast<ctab_status>(out->status);
  return ctab::lookup::creep_slot(table->table, *where, wheel, slot, *input, *out);
}

ctab_status ctab_creep_strips(const double* s_m, const double* half_length_m, const double* peak_pressure_Pa,
                              uint32_t n, double normal_force_N, double plane_angle_rad, const ctab_creep_input* input,
                              ctab_creep_patch* out) {
  if (out == nullptr) return CTAB_INVALID_INPUT;
  if (input == nullptr) {
    std::memset(out, 0, sizeof *out);
    out->status = CTAB_INVALID_INPUT;
    return CTAB_INVALID_INPUT;
  }
  const ctab::lookup::StripPatch patch{s_m, half_length_m, peak_pressure_Pa, n, normal_force_N, plane_angle_rad};
  return ctab::lookup::creep_patch(patch, *input, *out);
}

ctab_status ctab_kalker_coefficients(double a_m, double b_m, double poisson_ratio, double* out) {
  if (out == nullptr) return CTAB_INVALID_INPUT;
  const ctab::lookup::KalkerCoefficients c = ctab::lookup::kalker_coefficients(a_m, b_m, poisson_ratio);
  const bool ok = c.c11 > 0.0 && poisson_ratio >= 0.0 && poisson_ratio <= 0.5;
  out[0] = ok ? c.c11 : 0.0;
  out[1] = ok ? c.c22 : 0.0;
  out[2] = ok ? c.c23 : 0.0;
  out[3] = ok ? c.c33 : 0.0;
  return ok ? CTAB_OK : CTAB_INVALID_INPUT;
}

size_t ctab_struct_size(const char* name) {
  if (name == nullptr) return 0;
  const struct {
    const char* name;
    size_t size;
  } sizes[] = {{"ctab_open_options", sizeof(ctab_open_options)}, {"ctab_patch", sizeof(ctab_patch)},
               {"ctab_location", sizeof(ctab_location)},         {"ctab_result", sizeof(ctab_result)},
               {"ctab_blob_info", sizeof(ctab_blob_info)},       {"ctab_creep_input", sizeof(ctab_creep_input)},
               {"ctab_creep_patch", sizeof(ctab_creep_patch)},   {"ctab_creep_result", sizeof(ctab_creep_result)}};
  for (const auto& entry : sizes)
    if (std::strcmp(entry.name, name) == 0) return entry.size;
  return 0;
}

}  // extern "C"
