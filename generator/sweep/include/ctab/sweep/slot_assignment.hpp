// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Patch slots of one wheel along the lateral axis, so that a slot follows one contact (tables/README.md, `slot`).
//!
//! The cases of one (second-axis value, wheel) series are taken in increasing dy, serially (after the parallel
//! solve, so the result does not depend on the thread count). Each patch of a case continues the slot of the
//! nearest patch of the previous successful case by rail position y_rail (greedy over all pairs, nearest pair
//! first; ties by slot, then by patch order), except that a tread patch and a flange patch more than
//! kZoneChangeMatch_m apart are different contacts. Patches left over are new contacts: in the solver's patch order,
//! each takes its zone's slot (tread 0, flange 1) if free, else the lowest free slot from 2, else the other zone's
//! slot. The first case of a series (or one after a contact-free case) is thus the plain zone rule. A case whose
//! new patches find no free slot overflows (tables::CaseStatus::SlotOverflow) and, like a failed case, leaves
//! the slots of the previous case in place for the next one.
//!
//! Consequence for the jumps (tables/src/jumps.cpp): where the number of patches changes, the contacts that
//! start or end make `appears` / `disappears` jumps in their own slots; a slot moves by more than the threshold
//! only when its contact really jumps (a lone patch, or more patches than slots), and that is a `moves` jump.
#include <cstddef>
#include <vector>

#include "ctab/tables/table.hpp"

namespace ctab::gen {

//! One patch as slot assignment sees it.
struct SlotPatch {
  double y_rail_m = 0.0;  //!< contact point on the rail profile [m]
  bool flange = false;    //!< zone: flange (S <= -26 mm) or tread
};

//! One wheel of one case.
struct SlotCase {
  bool success = false;            //!< the case succeeded (status >= 0); a failed case holds no patch
  std::vector<SlotPatch> patches;  //!< in the solver's order
};

//! Slots of one case's patches: slot_of[i] for patch i (all empty when the case failed or overflowed).
struct SlotAssignment {
  std::vector<std::size_t> slot_of;
  bool overflow = false;  //!< more patches than free slots: the case keeps no patch
};

//! Largest rail-position change [m] at which a tread patch and a flange patch (or the reverse) are taken as one
//! contact crossing the zone boundary (S = -26 mm): the 1 mm floor of the jump threshold of tables/src/jumps.cpp,
//! independent of the dy step, so that a coarse table never hands the tread slot to a flange contact.
inline constexpr double kZoneChangeMatch_m = 1e-3;

//! Slots for a series of cases in increasing dy (see the file comment).
[[nodiscard]] std::vector<SlotAssignment> assign_slots_along_dy(const std::vector<SlotCase>& series,
                                                                std::size_t n_slots);

//! The same on a whole table whose cases were stored one by one (each in the zone rule): for every (second-axis
//! value, wheel) series, the patches of each case, taken in order of rail position (so that the result depends
//! only on the patches, not on how they were stored), are moved to the slots assign_slots_along_dy gives them.
//! A patch is a flange patch when its wheel contact point y_wheel_m <= kFlangeRootS_m. Runs on complete tables
//! (a single run, merged shards), so that the slots never depend on how the rows were solved. The series on
//! `threads` OpenMP threads (each series alone: the same result at any count).
void assign_table_slots_along_dy(tables::Table& table, int threads = 1);

}  // namespace ctab::gen
