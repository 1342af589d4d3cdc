// SPDX-License-Identifier: Apache-2.0
// [axes] tolerance (axis_tolerance_config.hpp): every key optional, each with its range.
#include "axis_tolerance_config.hpp"

#include <cmath>

#include "ctab/core/error.hpp"
#include "ctab/core/number_text.hpp"
#include "toml_input.hpp"

namespace ctab::gen::detail {

namespace {

struct ToleranceKey {
  const char* name;
  double AxisTolerance::*member;
  double low, high;  // low excluded, high included
  const char* expectation;
};

constexpr ToleranceKey kKeys[] = {
    {"force_rel", &AxisTolerance::force_rel, 0.0, kMaxRelativeTolerance, "a relative tolerance in (0, 0.5]"},
    {"area_rel", &AxisTolerance::area_rel, 0.0, kMaxRelativeTolerance, "a relative tolerance in (0, 0.5]"},
    {"contact_point_m", &AxisTolerance::contact_point_m, 0.0, kMaxContactPointTolerance_m,
     "a length in (0, 0.001] m"},
    {"lateral_force_rel", &AxisTolerance::lateral_force_rel, 0.0, kMaxRelativeTolerance,
     "a relative tolerance in (0, 0.5]"},
    {"min_step_m", &AxisTolerance::min_step_m, kMinAxisStep_m - 1e-22, kMaxMinAxisStep_m,
     "a length in [1e-7, 0.001] m"},
};

}  // namespace

std::optional<AxisTolerance> read_axis_tolerance(const toml::table& root, const std::string& source) {
  const toml::node* axes = root.get("axes");
  const toml::node* node = axes && axes->is_table() ? axes->as_table()->get("tolerance") : nullptr;
  if (!node) return std::nullopt;
  const toml::table* table = node->as_table();
  if (!table)
    fail_at(source, *node, "axes.tolerance",
            "expected a table { force_rel, area_rel, contact_point_m, lateral_force_rel, min_step_m } (each optional)");
  AxisTolerance tolerance;
  for (const auto& [name, value] : *table) {
    const std::string key = "axes.tolerance." + std::string(name.str());
    const ToleranceKey* known = nullptr;
    for (const ToleranceKey& k : kKeys)
      if (name.str() == k.name) known = &k;
    if (!known)
      fail_at(source, value, key, "unknown key (expected force_rel, area_rel, contact_point_m, lateral_force_rel, "
                                  "min_step_m)");
    const std::optional<double> number = value.value<double>();
    if (!number || value.is_boolean() || value.is_string()) fail_at(source, value, key, "expected a number");
    if (!(std::isfinite(*number) && *number > known->low && *number <= known->high))
      fail_at(source, value, key, std::string("expected ") + known->expectation + ", got " + number_text(*number));
    tolerance.*(known->member) = *number;
  }
  return tolerance;
}

}  // namespace ctab::gen::detail
