// SPDX-License-Identifier: Apache-2.0
#pragma once
// The blending rules of docs/method.md "Tables: sweep, slots, jumps, refined axis", branch-free: weights of the two dy neighbours of one slot from its cell
// rule, and of the two second-axis rows from the rows' presence.
#include <cstdint>

namespace ctab::lookup::detail {

// A record's rule field holds CellRule + kBandFactor x the jump band of its slot in the row pair above it
// (Table::JumpBand; 0: none). Exact in float up to 2^24, so bands are numbered below 2^22.
inline constexpr std::uint32_t kBandFactor = 4;
inline constexpr std::uint32_t kMaxBands = std::uint32_t{1} << 22;
template <typename T>
inline std::uint8_t rule_of(T code) noexcept {
  return static_cast<std::uint8_t>(static_cast<std::uint32_t>(code) % kBandFactor);
}
template <typename T>
inline std::uint32_t band_of(T code) noexcept {
  return static_cast<std::uint32_t>(code) / kBandFactor;
}

// Weight of the upper neighbour = kF[rule] * f + kStep[rule] * (f >= 0.5) + kConst[rule], per CellRule value
// (Interpolate, Nearest, LowerOnly, UpperOnly).
inline constexpr double kF[4] = {1.0, 0.0, 0.0, 0.0};
inline constexpr double kStep[4] = {0.0, 1.0, 0.0, 0.0};
inline constexpr double kConst[4] = {0.0, 0.0, 0.0, 1.0};

//! Weight of the upper dy neighbour for a slot with cell rule `rule` at fraction f; `step` = (f >= 0.5).
inline double upper_weight(std::uint8_t rule, double f, double step) noexcept {
  return kF[rule] * f + kStep[rule] * step + kConst[rule];
}

//! Weight of the upper second-axis row: g where both rows give the patch, else the nearer row (upper if g >= 0.5).
inline double row_weight(double present_lo, double present_hi, double g) noexcept {
  const double both = present_lo * present_hi;
  const double nearer_hi = g >= 0.5 ? 1.0 : 0.0;
  return both * g + (1.0 - both) * nearer_hi;
}

}  // namespace ctab::lookup::detail
