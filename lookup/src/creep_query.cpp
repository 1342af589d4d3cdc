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

ctab_status creep_query(const Table& table, const ctab_location& where, std::int32_t wheel,
                        const ctab_creep_input& input, ctab_creep_result& out) noexcept {
  if (!table.loaded()) {
    zero(out, 0, CTAB_NOT_LOADED);
    return CTAB_NOT_LOADED;
  }
  if (!valid_creep_input(input) || table.strip_samples() > kMaxCreepStrips || table.strip_samples() < 2) {
    zero(out, table.n_slots(), CTAB_INVALID_INPUT);
    return CTAB_INVALID_INPUT;
  }
  ctab_result normal;
  table.query(where, wheel, normal);
  if (normal.status < 0) {
    zero(out, table.n_slots(), static_cast<ctab_status>(normal.status));
    return static_cast<ctab_status>(normal.status);
  }
  zero(out, table.n_slots(), static_cast<ctab_status>(normal.status));
  double s[kMaxCreepStrips], a[kMaxCreepStrips], p0[kMaxCreepStrips];
  for (std::uint32_t slot = 0; slot < table.n_slots(); ++slot) {
    const ctab_patch& patch = normal.patch[slot];
    std::uint32_t count = 0;
    if (!patch.present) continue;
    if (table.strip_profile(where, wheel, static_cast<std::int32_t>(slot), s, a, p0, kMaxCreepStrips, &count) < 0 ||
        count < 2)
      continue;
    const StripPatch strips{s, a, p0, count, patch.q[CTAB_NORMAL_FORCE_N], patch.q[CTAB_PLANE_ANGLE_RAD]};
    ctab_creep_patch& result = out.patch[slot];
    if (creep_patch(strips, input, result) < 0) continue;
    result.status = normal.status;
    out.fx_N += result.fx_N;
    out.force_lateral_N += result.force_lateral_N;
    out.force_vertical_N += result.force_vertical_N;
    out.mz_Nm += result.mz_Nm;
  }
  return static_cast<ctab_status>(out.status);
}

}  // namespace ctab::lookup
