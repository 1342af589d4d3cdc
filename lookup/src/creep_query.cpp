// SPDX-License-Identifier: Apache-2.0
// Creep forces of one wheel at a prelooked point: each present slot's strip profile and normal force from the
// table, then creep_patch; totals in the side frame.
#include <cstring>

#include "ctab/lookup/creep.hpp"
#include "ctab/lookup/table.hpp"

namespace ctab::lookup {

namespace {

void zero(ctab_creep_result& out, std::uint32_t slots, ctab_status status) noexcept {
  std::memset(&out, 0, sizeof out);
  out.status = status;
  out.n_slots = static_cast<std::int32_t>(slots);
}

}  // namespace

namespace {

// One present slot's creep forces from its strip profile and normal force (status as the normal query's).
ctab_status slot_creep(const Table& table, const ctab_location& where, std::int32_t wheel, std::uint32_t slot,
                       const ctab_patch& patch, ctab_status normal_status, const ctab_creep_input& input,
                       ctab_creep_patch& out) noexcept {
  double s[kMaxCreepStrips], a[kMaxCreepStrips], p0[kMaxCreepStrips];
  std::uint32_t count = 0;
  std::memset(&out, 0, sizeof out);
  out.status = normal_status;
  if (!patch.present) return normal_status;
  if (table.strip_profile(where, wheel, static_cast<std::int32_t>(slot), s, a, p0, kMaxCreepStrips, &count) < 0 ||
      count < 2)
    return normal_status;
  const StripPatch strips{s, a, p0, count, patch.q[CTAB_NORMAL_FORCE_N], patch.q[CTAB_PLANE_ANGLE_RAD]};
  const ctab_status status = creep_patch(strips, input, out);
  if (status >= 0) out.status = normal_status;
  return status < 0 ? status : normal_status;
}

// Checks shared by the wheel and the slot call; CTAB_OK when the creep call may go on.
ctab_status check(const Table& table, const ctab_creep_input& input) noexcept {
  if (!table.loaded()) return CTAB_NOT_LOADED;
  if (!valid_creep_input(input) || table.strip_samples() > kMaxCreepStrips || table.strip_samples() < 2)
    return CTAB_INVALID_INPUT;
  return CTAB_OK;
}

}  // namespace

ctab_status creep_query(const Table& table, const ctab_location& where, std::int32_t wheel,
                        const ctab_creep_input& input, ctab_creep_result& out) noexcept {
  const ctab_status checked = check(table, input);
  if (checked != CTAB_OK) {
    zero(out, table.loaded() ? table.n_slots() : 0, checked);
    return checked;
  }
  ctab_result normal;
  table.query(where, wheel, normal);
  const auto status = static_cast<ctab_status>(normal.status);
  zero(out, table.n_slots(), status);
  if (status < 0) return status;
  for (std::uint32_t slot = 0; slot < table.n_slots(); ++slot) {
    ctab_creep_patch& result = out.patch[slot];
    if (slot_creep(table, where, wheel, slot, normal.patch[slot], status, input, result) < 0) {
      std::memset(&result, 0, sizeof result);
      continue;
    }
    out.fx_N += result.fx_N;
    out.force_lateral_N += result.force_lateral_N;
    out.force_vertical_N += result.force_vertical_N;
    out.mz_Nm += result.mz_Nm;
  }
  return status;
}

ctab_status creep_slot(const Table& table, const ctab_location& where, std::int32_t wheel, std::int32_t slot,
                       const ctab_creep_input& input, ctab_creep_patch& out) noexcept {
  std::memset(&out, 0, sizeof out);
  ctab_status status = check(table, input);
  if (status == CTAB_OK && (slot < 0 || static_cast<std::uint32_t>(slot) >= table.n_slots()))
    status = CTAB_INVALID_INPUT;
  if (status != CTAB_OK) {
    out.status = status;
    return status;
  }
  ctab_result normal;
  table.query(where, wheel, normal);
  if (normal.status < 0) {
    out.status = normal.status;
    return static_cast<ctab_status>(normal.status);
  }
  const auto s = static_cast<std::uint32_t>(slot);
  status = slot_creep(table, where, wheel, s, normal.patch[s], static_cast<ctab_status>(normal.status), input, out);
  if (status < 0) {
    std::memset(&out, 0, sizeof out);
    out.status = status;
  }
  return status;
}

}  // namespace ctab::lookup
