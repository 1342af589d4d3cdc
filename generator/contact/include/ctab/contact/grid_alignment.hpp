// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Where a grid of strips (MIM-1D and the other strip methods) or boundary elements (bem2d) sits relative to the
//! origin of the gap's lateral coordinate. CONTACT puts element edges there for a gap of its own (the Hertz sphere
//! and the non-Hertzian body of the paper: rows at y = (j + 1/2) dy), and centres its wheel-rail grid on the contact
//! reference point (its strip files: rows at s = j ds, element edges at odd multiples of ds/2).
#include <cstdint>

namespace ctab::gen {

enum class GridAlignment : std::uint8_t {
  EdgesAtOrigin = 0,    //!< edges at integer multiples of the cell size (gap files; ctab's default reference point)
  CentresAtOrigin = 1,  //!< centres at integer multiples (wheel-rail patches with CONTACT's reference rule)
};

//! Cell j's centre is (j + grid_centre_offset) times the cell size.
[[nodiscard]] constexpr double grid_centre_offset(GridAlignment alignment) noexcept {
  return alignment == GridAlignment::CentresAtOrigin ? 0.0 : 0.5;
}

}  // namespace ctab::gen
