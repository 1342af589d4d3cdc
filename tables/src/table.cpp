// SPDX-License-Identifier: Apache-2.0
// Table sizing and the names of the case statuses.
#include "ctab/tables/table.hpp"

#include "schema_fields.hpp"

namespace ctab::tables {

const char* case_status_name(CaseStatus status) noexcept {
  switch (status) {
    case CaseStatus::Converged: return "converged";
    case CaseStatus::NoContact: return "no-contact";
    case CaseStatus::UnderResolved: return "under-resolved";
    case CaseStatus::MaxIterations: return "max-iterations";
    case CaseStatus::InvalidInput: return "invalid-input";
    case CaseStatus::ZoneTruncated: return "zone-truncated";
    case CaseStatus::NumericalFailure: return "numerical-failure";
    case CaseStatus::SlotOverflow: return "slot-overflow";
    case CaseStatus::SolverException: return "solver-exception";
  }
  return "unknown";
}

void Table::allocate() {
  const auto n_dy_ = static_cast<hsize_t>(n_dy()), n_second_ = static_cast<hsize_t>(n_second());
  for (const detail::Field& field : detail::schema_fields(*this)) {
    if (field.extent == detail::Extent::DyAxis || field.extent == detail::Extent::SecondAxis) continue;
    if (field.empty_when_missing) {  // set by its producer only (the adaptive axis)
      field.resize(0);
      continue;
    }
    std::size_t count = 1;
    for (const hsize_t d : detail::shape_of(field.extent, n_dy_, n_second_, n_slots, strip_samples)) count *= d;
    field.resize(count);
  }
}

}  // namespace ctab::tables
