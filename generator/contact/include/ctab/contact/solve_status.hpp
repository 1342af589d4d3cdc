// SPDX-License-Identifier: Apache-2.0
#pragma once
//! Per-case outcome of a contact solve. Explicit values: 0 ok, > 0 usable with a caveat, < 0 failure.
//! Stored per case in tables; never an exception.
#include <cstdint>

namespace ctab::gen {

enum class SolveStatus : std::int8_t {
  Converged = 0,          //!< solved to tolerance
  NoContact = 1,          //!< the bodies do not touch (zero load); a valid outcome
  UnderResolved = 2,      //!< solved, < 8 strips across the smallest loaded patch (resolution.hpp): usable, unbounded
  MaxIterations = -1,     //!< iteration limit reached; results are the last iterate, not to be trusted
  InvalidInput = -2,      //!< inputs out of the solver's domain (non-finite, non-positive curvature, ...)
  ZoneTruncated = -3,     //!< the contact reaches the end of the supplied gap data
  NumericalFailure = -4,  //!< singular system or non-finite intermediate result
};

//! Short lower-case name ("converged", "no-contact", ...), never null.
[[nodiscard]] const char* status_name(SolveStatus status) noexcept;

//! True for the usable outcomes Converged, NoContact and UnderResolved (values >= 0).
[[nodiscard]] constexpr bool is_success(SolveStatus status) noexcept { return static_cast<int>(status) >= 0; }

}  // namespace ctab::gen
