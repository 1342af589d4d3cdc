// SPDX-License-Identifier: Apache-2.0
#include "ctab/contact/solve_status.hpp"

namespace ctab::gen {

const char* status_name(SolveStatus status) noexcept {
  switch (status) {
    case SolveStatus::Converged: return "converged";
    case SolveStatus::NoContact: return "no-contact";
    case SolveStatus::UnderResolved: return "under-resolved";
    case SolveStatus::MaxIterations: return "max-iterations";
    case SolveStatus::InvalidInput: return "invalid-input";
    case SolveStatus::ZoneTruncated: return "zone-truncated";
    case SolveStatus::NumericalFailure: return "numerical-failure";
  }
  return "unknown";
}

}  // namespace ctab::gen
