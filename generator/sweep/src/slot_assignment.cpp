// SPDX-License-Identifier: Apache-2.0
#include "ctab/sweep/slot_assignment.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>

#include "ctab/sweep/table_rows.hpp"
#include "ctab/wheelrail/wheelrail_options.hpp"
#include "parallel_loop.hpp"

namespace ctab::gen {

namespace {

constexpr std::size_t kTreadSlot = 0, kFlangeSlot = 1, kFirstSpareSlot = 2;

// What a slot held in the last successful case.
struct Occupant {
  double y_rail_m = 0.0;
  bool flange = false;
};

// Continues the previous slots: greedy nearest pairs by rail position.
void continue_slots(const std::vector<std::optional<Occupant>>& previous, const std::vector<SlotPatch>& patches,
                    std::vector<std::size_t>& slot_of, std::vector<bool>& taken) {
  struct Pair {
    double distance_m;
    std::size_t slot, patch;
  };
  std::vector<Pair> pairs;
  for (std::size_t slot = 0; slot < previous.size(); ++slot) {
    if (!previous[slot]) continue;
    for (std::size_t i = 0; i < patches.size(); ++i) {
      const double distance = std::abs(patches[i].y_rail_m - previous[slot]->y_rail_m);
      if (patches[i].flange != previous[slot]->flange && distance > kZoneChangeMatch_m) continue;  // tread vs flange
      pairs.push_back({distance, slot, i});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return std::tie(a.distance_m, a.slot, a.patch) < std::tie(b.distance_m, b.slot, b.patch);
  });
  for (const Pair& pair : pairs) {
    if (taken[pair.slot] || slot_of[pair.patch] != previous.size()) continue;
    taken[pair.slot] = true;
    slot_of[pair.patch] = pair.slot;
  }
}

// A new contact's slot: its zone's, the spares from 2, then the other zone's; n_slots when none is free.
std::size_t free_slot(bool flange, const std::vector<bool>& taken) {
  const std::size_t n = taken.size(), own = flange ? kFlangeSlot : kTreadSlot,
                    other = flange ? kTreadSlot : kFlangeSlot;
  if (own < n && !taken[own]) return own;
  for (std::size_t slot = kFirstSpareSlot; slot < n; ++slot)
    if (!taken[slot]) return slot;
  if (other < n && !taken[other]) return other;
  return n;
}

}  // namespace

std::vector<SlotAssignment> assign_slots_along_dy(const std::vector<SlotCase>& series, std::size_t n_slots) {
  std::vector<SlotAssignment> out(series.size());
  std::vector<std::optional<Occupant>> previous(n_slots);  // the last successful case's slots
  for (std::size_t c = 0; c < series.size(); ++c) {
    if (!series[c].success) continue;  // no patch; the slots carry over
    const std::vector<SlotPatch>& patches = series[c].patches;
    std::vector<std::size_t> slot_of(patches.size(), n_slots);
    std::vector<bool> taken(n_slots, false);
    continue_slots(previous, patches, slot_of, taken);
    bool overflow = false;
    // New contacts: the lowest-y_rail first among the extras, the zone slot to the first of its zone (solver order).
    std::vector<std::size_t> born;
    for (std::size_t i = 0; i < patches.size(); ++i)
      if (slot_of[i] == n_slots) born.push_back(i);
    std::vector<std::size_t> extra;
    for (const std::size_t i : born) {
      const std::size_t own = patches[i].flange ? kFlangeSlot : kTreadSlot;
      if (own < n_slots && !taken[own]) {
        taken[own] = true;
        slot_of[i] = own;
      } else {
        extra.push_back(i);
      }
    }
    std::stable_sort(extra.begin(), extra.end(),
                     [&](std::size_t a, std::size_t b) { return patches[a].y_rail_m < patches[b].y_rail_m; });
    for (const std::size_t i : extra) {
      const std::size_t slot = free_slot(patches[i].flange, taken);
      if (slot == n_slots) {
        overflow = true;
        break;
      }
      taken[slot] = true;
      slot_of[i] = slot;
    }
    if (overflow) {
      out[c].overflow = true;
      continue;  // no patch stored; the slots carry over
    }
    out[c].slot_of = slot_of;
    std::fill(previous.begin(), previous.end(), std::nullopt);
    for (std::size_t i = 0; i < patches.size(); ++i)
      previous[slot_of[i]] = Occupant{patches[i].y_rail_m, patches[i].flange};
  }
  return out;
}

namespace {

// The patches of one wheel-case of a table in order of rail position, with the slots they are stored in.
SlotCase stored_case(const tables::Table& table, std::size_t i_dy, std::size_t i_second, std::size_t wheel,
                     std::vector<std::size_t>& stored_slot) {
  SlotCase out;
  stored_slot.clear();
  out.success = tables::is_success(table.status[table.wheel_index(i_dy, i_second, wheel)]);
  if (!out.success) return out;
  for (std::size_t slot = 0; slot < table.n_slots; ++slot)
    if (table.patch.present[table.patch_index(i_dy, i_second, wheel, slot)] != 0) stored_slot.push_back(slot);
  const auto y_rail = [&](std::size_t slot) {
    return table.patch.y_rail_m[table.patch_index(i_dy, i_second, wheel, slot)];
  };
  std::stable_sort(stored_slot.begin(), stored_slot.end(),
                   [&](std::size_t a, std::size_t b) { return y_rail(a) < y_rail(b); });
  for (const std::size_t slot : stored_slot) {
    const std::size_t k = table.patch_index(i_dy, i_second, wheel, slot);
    out.patches.push_back({table.patch.y_rail_m[k], table.patch.y_wheel_m[k] <= kFlangeRootS_m});
  }
  return out;
}

// A full permutation of the slots: stored slot -> assigned slot, empty slots to the free ones in order.
std::vector<std::size_t> slot_permutation(const std::vector<std::size_t>& stored_slot,
                                          const std::vector<std::size_t>& slot_of, std::size_t n_slots) {
  std::vector<std::size_t> new_slot(n_slots, n_slots);
  std::vector<bool> used(n_slots, false);
  for (std::size_t i = 0; i < stored_slot.size(); ++i) {
    new_slot[stored_slot[i]] = slot_of[i];
    used[slot_of[i]] = true;
  }
  std::size_t next_free = 0;
  for (std::size_t& slot : new_slot) {
    if (slot != n_slots) continue;
    while (used[next_free]) ++next_free;
    slot = next_free;
    used[next_free] = true;
  }
  return new_slot;
}

}  // namespace

void assign_table_slots_along_dy(tables::Table& table, int threads) {
  const std::size_t n_dy = table.n_dy();
  // The (second-axis value, wheel) series touch disjoint cases: one task each.
  detail::parallel_loop(table.n_second() * tables::kWheels, threads, true, [&](std::size_t index) {
    const std::size_t i_second = index / tables::kWheels, wheel = index % tables::kWheels;
    std::vector<SlotCase> series(n_dy);
    std::vector<std::vector<std::size_t>> stored(n_dy);
    for (std::size_t i_dy = 0; i_dy < n_dy; ++i_dy)
      series[i_dy] = stored_case(table, i_dy, i_second, wheel, stored[i_dy]);
    const std::vector<SlotAssignment> slots = assign_slots_along_dy(series, table.n_slots);
    for (std::size_t i_dy = 0; i_dy < n_dy; ++i_dy) {
      // A stored case never has more patches than slots, so it cannot overflow here; keep it as stored if it did.
      if (!series[i_dy].success || slots[i_dy].overflow) continue;
      const std::vector<std::size_t> new_slot = slot_permutation(stored[i_dy], slots[i_dy].slot_of, table.n_slots);
      bool moves = false;  // most cases keep their slots
      for (std::size_t slot = 0; slot < new_slot.size(); ++slot) moves = moves || new_slot[slot] != slot;
      if (moves) permute_slots(table, table.wheel_index(i_dy, i_second, wheel), new_slot);
    }
  });
}

}  // namespace ctab::gen
