// SPDX-License-Identifier: Apache-2.0
#pragma once
// The provenance attributes of a generated table: generator, build, config, profiles (with their SHA-256 and
// smoothing), solver settings and material. Private to the sweep library.
#include "ctab/sweep/table_generator.hpp"
#include "sweep_plan.hpp"

namespace ctab::gen::detail {

// Sets the table's text, number and integer provenance attributes; created_utc is the time now, or
// SOURCE_DATE_EPOCH when set (reproducible builds).
void add_provenance(tables::Table& table, const TableConfig& config, const SweepSetup& setup, const SweepPlan& plan,
                    const GeneratorInfo& info);

}  // namespace ctab::gen::detail
