// `ctab inspect FILE`: validate a table and print its schema, provenance, axes, statuses and contact jumps.
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "commands.hpp"
#include "ctab/contact/error.hpp"
#include "ctab/contact/solve_status.hpp"
#include "ctab/tables/table.hpp"

namespace ctab::cli {

namespace {

int run_inspect(const std::string& path) {
  tables::Table t;
  const tables::TableResult result = tables::read_table(path, t);
  if (!result.ok()) throw gen::Error(result.message);
  std::printf("%s: ctab contact table, schema version %d (valid)\n", path.c_str(), tables::kSchemaVersion);
  for (const auto& [name, value] : t.text_attributes)
    if (name != "config") std::printf("  %-22s %s\n", name.c_str(), value.c_str());
  for (const auto& [name, value] : t.number_attributes) std::printf("  %-22s %g\n", name.c_str(), value);
  const auto& dy = t.lateral_displacement_m;
  std::printf("axes: lateral_displacement_m %zu values, %g .. %g m, step %g m\n", dy.size(), dy.front(), dy.back(),
              dy.size() > 1 ? dy[1] - dy[0] : 0.0);
  std::printf("      %s %zu value(s), %g .. %g\n", t.second_axis_name.c_str(), t.n_second(), t.second_axis.front(), t.second_axis.back());
  std::printf("strip profiles: %zu samples per patch\n", t.strip_samples);
  std::map<int, std::size_t> counts;
  for (const auto s : t.status) ++counts[s];
  std::printf("status counts (case x wheel):");
  for (const auto& [status, count] : counts) std::printf(" %s %zu", gen::status_name(static_cast<gen::SolveStatus>(status)), count);
  std::printf("\n");
  std::size_t slots[tables::kSlots] = {};
  for (std::size_t k = 0; k < t.patch.present.size(); ++k) slots[k % tables::kSlots] += t.patch.present[k];
  std::printf("patches present: tread %zu, flange %zu, spare %zu\n", slots[0], slots[1], slots[2]);
  // Contact jumps: the wheel contact point of the strongest patch moves by more than 1 mm or 10 steps.
  const double threshold = std::max(1e-3, 10.0 * (dy.size() > 1 ? dy[1] - dy[0] : 0.0));
  for (std::size_t i_second = 0; i_second < t.n_second(); ++i_second)
    for (std::size_t wheel = 0; wheel < tables::kWheels; ++wheel) {
      double previous = NAN;
      for (std::size_t i = 0; i < t.n_dy(); ++i) {
        double best = -1, position = NAN;
        for (std::size_t slot = 0; slot < tables::kSlots; ++slot) {
          const std::size_t k = t.patch_index(i, i_second, wheel, slot);
          if (t.patch.present[k] && t.patch.normal_force_N[k] > best) {
            best = t.patch.normal_force_N[k];
            position = t.patch.y_wheel_m[k];
          }
        }
        if (std::isfinite(previous) && std::isfinite(position) && std::abs(position - previous) > threshold)
          std::printf("contact jump, %s wheel, %s = %g: between dy = %.2f and %.2f mm, wheel y %.2f -> %.2f mm\n",
                      wheel == 0 ? "right" : "left", t.second_axis_name.c_str(), t.second_axis[i_second], dy[i - 1] * 1e3,
                      dy[i] * 1e3, previous * 1e3, position * 1e3);
        previous = position;
      }
    }
  return 0;
}

}  // namespace

Command add_inspect_command(CLI::App& parent) {
  auto path = std::make_shared<std::string>();
  CLI::App* app = parent.add_subcommand("inspect", "Validate a contact table and print its schema, provenance, axes, statuses and jumps");
  app->add_option("file", *path, "table (.h5)")->required();
  return {app, [path] { return run_inspect(*path); }};
}

}  // namespace ctab::cli
