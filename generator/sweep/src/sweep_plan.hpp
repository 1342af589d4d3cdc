// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a table sweep solves (axes, mirroring, sides, threads), shared by the set-up, the schedule, the sweep and
// the provenance of table_generator.hpp; private to the sweep library.
#include <cstddef>
#include <vector>

#include "ctab/sweep/table_generator.hpp"

namespace ctab::gen::detail {

struct SweepPlan {
  std::vector<double> dy_m;
  std::vector<double> load_values;
  bool mirrored = false;  // one wheel and one rail profile for both sides and a symmetric dy axis
  std::size_t sides = 2;  // wheels solved: 1 when mirrored
  int threads = 1;
  [[nodiscard]] std::size_t cases() const { return dy_m.size() * load_values.size(); }
};

[[nodiscard]] SweepPlan make_plan(const TableConfig& config, const GeneratorInfo& info);

// One wheel and one rail profile for both sides and a symmetric dy axis: the left wheel at dy is the right at -dy.
// Every node has its mirror image -dy (to kMirrorTolerance of the span): a refined zone on one side only breaks the
// symmetry.
[[nodiscard]] bool symmetric_axis(const std::vector<double>& dy_m);

}  // namespace ctab::gen::detail
