// SPDX-License-Identifier: Apache-2.0
// `ctab query FILE --dy METRES [--load N | --approach M] [--wheel left|right] [--pchip] [--strips] [--json]
// [--creepage XI,ETA,PHI --friction MU]`:
// one lookup, as a HIL target would make it, printed as text or JSON.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "creep_output.hpp"
#include "ctab/core/error.hpp"
#include "ctab/lookup/hdf5_table.hpp"
#include "isolated_read.hpp"
#include "load_errors.hpp"
#include "setup_options.hpp"

namespace ctab::cli {

namespace {

struct QueryOptions {
  std::string path, wheel = "right";
  double dy_m = 0.0;
  std::optional<double> load_N, approach_m;
  bool json = false, pchip = false, strips = false;
  CreepOptions creep;
  gen::ElasticMaterial material;  //!< for the creep forces (the table's material)
};

constexpr const char* kQuantityNames[CTAB_QUANTITIES] = {"normal_force_N",    "force_lateral_N",  "force_vertical_N",
                                                         "area_m2",           "max_pressure_Pa",  "approach_m",
                                                         "contact_angle_rad", "plane_angle_rad",  "s_origin_y_rail_m",
                                                         "s_origin_z_rail_m", "y_wheel_m",        "y_rail_m",
                                                         "y_cop_rail_m",      "rolling_radius_m", "semi_axis_a_m",
                                                         "semi_axis_b_m",     "s_min_m",          "s_max_m"};

//! The second-axis value the options give for this table (its only value when it has one; a table with several
//! needs the option: no value is picked for the user).
double second_value(const lookup::Table& table, const QueryOptions& o) {
  const bool approach_axis = table.second_axis_kind() == lookup::SecondAxis::Approach;
  if (o.load_N && approach_axis) throw gen::Error(o.path + ": the second axis is approach_m; use --approach");
  if (o.approach_m && !approach_axis) throw gen::Error(o.path + ": the second axis is a load; use --load");
  const std::optional<double> given = approach_axis ? o.approach_m : o.load_N;
  if (table.n_second() == 1 && given && *given != table.second_axis().front())
    std::fprintf(stderr, "ctab query: note: the table has one %s value (%g); %g ignored\n",
                 lookup::second_axis_name(table.second_axis_kind()), table.second_axis().front(), *given);
  if (table.n_second() == 1) return table.second_axis().front();
  if (!given)
    throw gen::Error(o.path + (approach_axis ? ": the table has an approach axis: give --approach"
                                             : ": the table has a load axis: give --load"));
  return *given;
}

int query_table(const QueryOptions& o, IsolatedChild& child) {
  lookup::Table table;
  child.reading(o.path);
  const lookup::LoadResult loaded = lookup::open_file(o.path, {o.pchip ? CTAB_PCHIP : CTAB_LINEAR, false}, table);
  throw_if_failed(loaded);
  child.trusted_from_here();
  ctab_location where;
  table.prelookup(o.dy_m, second_value(table, o), where);
  ctab_result r;
  std::memset(&r, 0, sizeof r);
  const std::int32_t wheel = o.wheel == "left" ? CTAB_WHEEL_LEFT : CTAB_WHEEL_RIGHT;
  table.query(where, wheel, r);
  if (r.status < 0) throw gen::Error(std::string("query: ") + ctab_status_message(r.status));
  nlohmann::json out = {{"status", r.status == CTAB_OK ? "ok" : "clamped"},
                        {"dy_m", r.dy_m},
                        {lookup::second_axis_name(table.second_axis_kind()), r.second},
                        {"wheel", o.wheel},
                        {"interpolation", o.pchip ? "pchip" : "linear"},
                        {"roll_rad", r.roll_rad},
                        {"rolling_radius_difference_m", r.rolling_radius_difference_m},
                        {"neighbour_status", std::vector<int>(r.neighbour_status, r.neighbour_status + 4)}};
  nlohmann::json patches = nlohmann::json::array();
  for (std::int32_t s = 0; s < r.n_slots; ++s) {
    if (!r.patch[s].present) continue;
    nlohmann::json patch = {{"slot", s}};
    for (std::size_t q = 0; q < CTAB_QUANTITIES; ++q) patch[kQuantityNames[q]] = r.patch[s].q[q];
    if (o.strips && table.strip_samples() > 0) {
      std::vector<double> sv(table.strip_samples()), a(sv.size()), p0(sv.size());
      std::uint32_t count = 0;
      (void)table.strip_profile(where, wheel, s, sv.data(), a.data(), p0.data(), table.strip_samples(), &count);
      patch["strips"] = {{"s_m", sv}, {"half_length_m", a}, {"peak_pressure_Pa", p0}};
    }
    patches.push_back(patch);
  }
  if (o.creep.wanted()) {
    ctab_creep_result forces;
    (void)lookup::creep_query(table, where, wheel, o.creep.input(o.material), forces);
    for (auto& patch : patches) patch["creep"] = creep_json(forces.patch[patch["slot"].get<int>()]);
    out["creep_total"] = {{"fx_N", forces.fx_N}, {"force_lateral_N", forces.force_lateral_N},
                          {"force_vertical_N", forces.force_vertical_N}, {"mz_Nm", forces.mz_Nm}};
  }
  out["patches"] = patches;
  if (o.json) {
    std::cout << out.dump(2) << '\n';
    return 0;
  }
  std::printf("%s wheel at dy = %.4f mm, %s = %g (%s): roll %.6g rad, delta r %.6g mm\n", o.wheel.c_str(), r.dy_m * 1e3,
              lookup::second_axis_name(table.second_axis_kind()), r.second, r.status == CTAB_OK ? "ok" : "clamped",
              r.roll_rad, r.rolling_radius_difference_m * 1e3);
  for (const auto& patch : patches) {
    std::printf("slot %d:\n", patch["slot"].get<int>());
    for (const char* name : kQuantityNames) std::printf("  %-20s %.9g\n", name, patch[name].get<double>());
    if (patch.contains("creep")) print_creep("  ", patch["creep"]);
  }
  if (patches.empty()) std::printf("no contact\n");
  return 0;
}

// In a child process (isolated_read.hpp): the file may be an HDF5 table from anywhere.
int run_query(const QueryOptions& o) {
  check_creep_options(o.creep);
  return run_isolated([&](IsolatedChild& child) { return query_table(o, child); }).exit_code;
}

}  // namespace

Command add_query_command(CLI::App& parent) {
  auto o = std::make_shared<QueryOptions>();
  CLI::App* app =
      parent.add_subcommand("query", "Interpolate a table at one lateral shift (as the lookup library does)");
  app->add_option("file", o->path, "table (.h5 or blob)")->required();
  app->add_option("--dy", o->dy_m, "lateral displacement [m]")->required();
  auto* load = app->add_option("--load", o->load_N, "vertical or normal load [N] (tables with a load axis of several values: required)");
  app->add_option("--approach", o->approach_m, "approach [m] (tables with an approach axis of several values: required)")->excludes(load);
  app->add_option("--wheel", o->wheel, "left or right (default right)")->check(CLI::IsMember({"left", "right"}));
  app->add_flag("--pchip", o->pchip, "monotone cubic along dy instead of linear");
  app->add_flag("--strips", o->strips, "include the strip profiles (JSON)");
  app->add_flag("--json", o->json, "print JSON");
  add_creep_options(*app, o->creep);
  app->add_option("--youngs-modulus", o->material.youngs_modulus_Pa,
                  "Young's modulus of both bodies for --creepage [Pa] (default: steel, the generator's default)")
      ->check(finite_positive("Pa"));
  app->add_option("--poisson-ratio", o->material.poisson_ratio, "Poisson's ratio for --creepage (default 0.3)")
      ->check(CLI::Range(0.0, 0.499));
  return {app, [o] { return run_query(*o); }};
}

}  // namespace ctab::cli
