// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Per-case outcome stored in a table (`/wheels/status`, an HDF5 enum type carrying these names).
//! Explicit values: 0 ok, > 0 usable with a caveat, < 0 failure. The generator's SolveStatus maps onto the
//! values it shares with this enum (checked at compile time in the generator); readers need no generator code.
#include <cstdint>

namespace ctab::tables {

enum class CaseStatus : std::int8_t {
  Converged = 0,          //!< solved to tolerance
  NoContact = 1,          //!< the bodies do not touch (zero load); a valid outcome
  UnderResolved = 2,      //!< solved, but fewer than 8 strips across the smallest loaded patch: usable, error unbounded
  MaxIterations = -1,     //!< iteration limit reached; the case holds no patches
  InvalidInput = -2,      //!< inputs out of the solver's domain
  ZoneTruncated = -3,     //!< the contact reaches the end of the profile data
  NumericalFailure = -4,  //!< singular system or non-finite intermediate result
  SlotOverflow = -5,      //!< more patches than the table has slots: force would be lost, so the case is failed
  SolverException = -6,   //!< the solver threw (caught in the sweep); the case holds no patches
};

inline constexpr int kCaseStatusMin = -6;  //!< smallest value defined above
inline constexpr int kCaseStatusMax = 2;   //!< largest value defined above

//! Short lower-case name ("converged", "no-contact", "slot-overflow", ...); "unknown" for other values.
[[nodiscard]] const char* case_status_name(CaseStatus status) noexcept;
//! True if `value` is one of the enumerators above.
[[nodiscard]] constexpr bool is_case_status(int value) noexcept {
  return value >= kCaseStatusMin && value <= kCaseStatusMax;
}
//! True for the usable outcomes Converged, NoContact and UnderResolved (values >= 0; the lookup's rule too).
[[nodiscard]] constexpr bool is_success(CaseStatus status) noexcept { return static_cast<int>(status) >= 0; }

}  // namespace ctab::tables
