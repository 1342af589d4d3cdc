// SPDX-License-Identifier: Apache-2.0
// `ctab inspect FILE [--json]`: validate a table and print its schema, provenance, axes, statuses, patches per
// slot and the contact jumps stored in the file.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/tables/table.hpp"
#include "isolated_read.hpp"

namespace ctab::cli {

namespace {

const char* jump_kind_name(tables::JumpKind kind) {
  switch (kind) {
    case tables::JumpKind::Appears: return "appears";
    case tables::JumpKind::Disappears: return "disappears";
    case tables::JumpKind::Moves: return "moves";
  }
  return "unknown";
}

// An adaptive axis (a table with cell_error): the tolerance, the worst error measured per quantity, the cells over
// the tolerance and not measured, and the nodes next to those of the uniform axis with the finest measured step
// (the cells around a located jump are narrower, and not measured).
nlohmann::ordered_json adaptive_axis_summary(const tables::Table& t) {
  nlohmann::ordered_json out;
  const auto& dy = t.lateral_displacement_m;
  const std::size_t q_count = tables::kCellErrorQuantities, n_second = t.n_second();
  std::vector<double> tolerance(q_count, 0.0), worst(q_count, 0.0);
  for (std::size_t q = 0; q < q_count; ++q) {
    const auto found = t.number_attributes.find(tables::kToleranceAttributes[q]);
    tolerance[q] = found != t.number_attributes.end() ? found->second : 0.0;
  }
  std::size_t over = 0, unmeasured = 0;
  double finest = dy.back() - dy.front();
  for (std::size_t i = 0; i + 1 < dy.size(); ++i) {
    for (std::size_t j = 0; j < n_second; ++j) {
      const double* e = &t.cell_error[(i * n_second + j) * q_count];
      if (e[0] == tables::kCellNotMeasured) {
        ++unmeasured;
        continue;
      }
      finest = std::min(finest, dy[i + 1] - dy[i]);
      bool cell_over = false;
      for (std::size_t q = 0; q < q_count; ++q) {
        worst[q] = std::max(worst[q], e[q]);
        cell_over = cell_over || e[q] > tolerance[q];
      }
      over += cell_over ? 1 : 0;
    }
  }
  static const char* const names[] = {"force_rel", "area_rel", "contact_point_m", "lateral_force_rel"};
  for (std::size_t q = 0; q < q_count; ++q) {
    out["tolerance"][names[q]] = tolerance[q];
    out["worst_measured"][names[q]] = worst[q];
  }
  out["cells_over_tolerance"] = over;
  out["cells_not_measured"] = unmeasured;
  out["nodes"] = dy.size();
  out["finest_step_m"] = finest;
  out["uniform_nodes_at_finest_step"] = static_cast<std::size_t>(std::ceil((dy.back() - dy.front()) / finest)) + 1;
  return out;
}

void print_adaptive_axis(const nlohmann::ordered_json& a) {
  std::printf("adaptive dy axis: %zu nodes (a uniform axis at its finest measured step, %g m: %zu)\n",
              a["nodes"].get<std::size_t>(), a["finest_step_m"].get<double>(),
              a["uniform_nodes_at_finest_step"].get<std::size_t>());
  std::printf("  %-18s %12s %14s\n", "quantity", "tolerance", "worst measured");
  for (const auto& [name, value] : a["tolerance"].items())
    std::printf("  %-18s %12.4g %14.4g\n", name.c_str(), value.get<double>(),
                a["worst_measured"][name].get<double>());
  std::printf("  cells (x second-axis values) over the tolerance: %zu; not measured (jumps, cells beside them): %zu\n",
              a["cells_over_tolerance"].get<std::size_t>(), a["cells_not_measured"].get<std::size_t>());
}

// Everything inspect reports, as JSON (the text output prints the same object).
nlohmann::ordered_json summary(const tables::Table& t) {
  nlohmann::ordered_json out;
  out["schema_version"] = tables::kSchemaVersion;
  for (const auto& [name, value] : t.text_attributes) out["provenance"][name] = value;
  for (const auto& [name, value] : t.number_attributes) out["provenance"][name] = value;
  for (const auto& [name, value] : t.integer_attributes) out["provenance"][name] = value;
  const auto& dy = t.lateral_displacement_m;
  double largest_step = 0.0, smallest_step = dy.size() > 1 ? dy[1] - dy[0] : 0.0;  // refined axes: not equal
  for (std::size_t i = 1; i < dy.size(); ++i) {
    largest_step = std::max(largest_step, dy[i] - dy[i - 1]);
    smallest_step = std::min(smallest_step, dy[i] - dy[i - 1]);
  }
  out["axes"]["lateral_displacement_m"] = {{"units", "m"},         {"count", dy.size()},
                                           {"first", dy.front()},  {"last", dy.back()},
                                           {"step", largest_step}, {"smallest_step", smallest_step}};
  out["axes"]["second"] = {{"name", t.second_axis_name}, {"units", t.second_axis_units}, {"values", t.second_axis}};
  if (!t.cell_error.empty()) out["adaptive_axis"] = adaptive_axis_summary(t);
  out["n_slots"] = t.n_slots;
  out["strip_samples"] = t.strip_samples;
  std::map<int, std::size_t> counts;
  for (const auto s : t.status) ++counts[static_cast<int>(s)];
  for (const auto& [status, count] : counts)
    out["status_counts"][tables::case_status_name(static_cast<tables::CaseStatus>(status))] = count;
  std::vector<std::size_t> per_slot(t.n_slots, 0);
  for (std::size_t k = 0; k < t.patch.present.size(); ++k) per_slot[k % t.n_slots] += t.patch.present[k];
  out["patches_per_slot"] = per_slot;
  out["jumps"] = nlohmann::ordered_json::array();
  for (const tables::Jump& j : t.jumps)
    out["jumps"].push_back({{"kind", jump_kind_name(j.kind)},
                            {"wheel", j.wheel == 0 ? "right" : "left"},
                            {"slot", j.slot},
                            {"i_second", j.i_second},
                            {"second", t.second_axis[j.i_second]},
                            {"i_dy", j.i_dy},
                            {"dy_low_m", dy[j.i_dy]},
                            {"dy_high_m", dy[j.i_dy + 1]}});
  return out;
}

void print_text(const std::string& path, const nlohmann::ordered_json& s) {
  std::printf("%s: ctab contact table, schema version %d (valid)\n", path.c_str(), tables::kSchemaVersion);
  for (const auto& [name, value] : s["provenance"].items()) {
    if (name == "config") continue;
    if (value.is_string()) std::printf("  %-22s %s\n", name.c_str(), value.get<std::string>().c_str());
    else std::printf("  %-22s %.10g\n", name.c_str(), value.get<double>());
  }
  const auto& dy = s["axes"]["lateral_displacement_m"];
  std::printf("axes: lateral_displacement_m %zu values, %g .. %g m, step %g m", dy["count"].get<std::size_t>(),
              dy["first"].get<double>(), dy["last"].get<double>(), dy["step"].get<double>());
  const double smallest = dy["smallest_step"].get<double>();
  if (smallest < dy["step"].get<double>() * (1.0 - 1e-6)) std::printf(", refined to %g m", smallest);
  std::printf("\n");
  const auto& second = s["axes"]["second"];
  std::printf("      %s %zu value(s) in %s: %s\n", second["name"].get<std::string>().c_str(), second["values"].size(),
              second["units"].get<std::string>().c_str(), second["values"].dump().c_str());
  if (s.contains("adaptive_axis")) print_adaptive_axis(s["adaptive_axis"]);
  std::printf("patch slots: %zu; strip profiles: %zu samples per patch\n", s["n_slots"].get<std::size_t>(),
              s["strip_samples"].get<std::size_t>());
  std::printf("status counts (case x wheel):");
  for (const auto& [name, count] : s["status_counts"].items())
    std::printf(" %s %zu", name.c_str(), count.get<std::size_t>());
  std::printf("\npatches present per slot:");
  for (std::size_t slot = 0; slot < s["patches_per_slot"].size(); ++slot)
    std::printf(" %zu: %zu", slot, s["patches_per_slot"][slot].get<std::size_t>());
  std::printf("\ncontact jumps: %zu\n", s["jumps"].size());
  for (const auto& j : s["jumps"])
    std::printf("  %-10s %s wheel, slot %d, %s = %g: dy %.3f -> %.3f mm\n", j["kind"].get<std::string>().c_str(),
                j["wheel"].get<std::string>().c_str(), j["slot"].get<int>(), second["name"].get<std::string>().c_str(),
                j["second"].get<double>(), j["dy_low_m"].get<double>() * 1e3, j["dy_high_m"].get<double>() * 1e3);
}

// In a child process (isolated_read.hpp). Attribute texts are the file's bytes: JSON output replaces invalid UTF-8
// with U+FFFD.
int run_inspect(const std::string& path, bool json) {
  return run_isolated([&](IsolatedChild& child) {
           tables::Table t;
           child.reading(path);
           const tables::TableResult result = tables::read_table(path, t);
           if (!result.ok()) throw gen::Error(result.message);
           child.trusted_from_here();
           const nlohmann::ordered_json s = summary(t);
           if (json) std::cout << s.dump(1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << '\n';
           else print_text(path, s);
           return 0;
         })
      .exit_code;
}

}  // namespace

Command add_inspect_command(CLI::App& parent) {
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  CLI::App* app =
      parent.add_subcommand("inspect",
                            "Validate a contact table and print its schema, provenance, axes, statuses and jumps");
  app->add_option("file", *path, "table (.h5)")->required();
  app->add_flag("--json", *json,
                "print one JSON object (schema, provenance, axes, status counts, patches per slot, jumps)");
  return {app, [path, json] { return run_inspect(*path, *json); }};
}

}  // namespace ctab::cli
