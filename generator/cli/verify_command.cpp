// SPDX-License-Identifier: Apache-2.0
// `ctab verify TABLE [--samples N] [--seed S] [--threads T] [--json]`: the table's linear lookup against direct
// solves at random off-grid points in every class of cell (verify_cells.hpp), solved from the table's own config
// text as `ctab solve --config` solves it; exit 4 when a point exceeds the table's stated tolerance.
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ctab/core/error.hpp"
#include "ctab/io/sha256.hpp"
#include "ctab/lookup/hdf5_table.hpp"
#include "exit_codes.hpp"
#include "isolated_read.hpp"
#include "load_errors.hpp"
#include "setup_options.hpp"
#include "verify_cells.hpp"
#include "verify_errors.hpp"

namespace ctab::cli {

namespace {

struct VerifyOptions {
  std::string path;
  std::size_t samples = 1000;
  std::uint64_t seed = 1;
  int threads = 0;
  bool json = false;
};

// The solver set-up the table was made with: its config text, its profiles (checked against their samples' hashes).
gen::SweepSetup table_setup(const std::string& path, const tables::Table& t) {
  const auto& text = t.text_attributes;
  const auto config_text = text.find("config");
  if (config_text == text.end())
    throw gen::Error(path + ": the table holds no config text (attribute config): verify solves from it");
  gen::TableConfig config = gen::parse_table_config(config_text->second, path + " (its config attribute)");
  for (auto [name, spec] : {std::pair{"wheel_profile", &config.wheel}, std::pair{"rail_profile", &config.rail}})
    if (const auto found = text.find(name); found != text.end()) *spec = found->second;
  gen::SweepSetup setup = gen::make_sweep_setup(config);
  for (auto [name, profile] :
       {std::pair{"wheel_profile_sha256", setup.wheel.get()}, std::pair{"rail_profile_sha256", setup.rail.get()}}) {
    const auto stored = text.find(name);
    const std::string now = gen::sha256_hex(profile->z_samples().data(), profile->z_samples().size() * sizeof(double));
    if (stored != text.end() && stored->second != now)
      throw gen::Error(path + ": the profile behind " + name + " has changed since the table was made");
  }
  return setup;
}

struct PointResult {
  PointErrors errors;
  bool solved = false;  // the direct solve succeeded
};

std::vector<PointResult> check_points(const lookup::Table& table, const gen::SweepSetup& setup,
                                      const std::vector<SamplePoint>& points, int threads) {
  std::vector<PointResult> results(points.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::size_t k = 0; k < points.size(); ++k) {
    const SamplePoint& p = points[k];
    ctab_location where;
    table.prelookup(p.dy_m, p.second, where);
    ctab_result r{};
    table.query(where, static_cast<std::int32_t>(p.wheel), r);
    const gen::CaseSolution solution =
        gen::solve_table_case(setup, p.dy_m, p.second, gen::WheelSelection{p.wheel == 0, p.wheel == 1});
    const gen::WheelContact& direct = solution.wheels[p.wheel].contact;
    results[k].solved = !solution.wheels[p.wheel].exception && gen::is_success(direct.status) && r.status >= 0;
    if (results[k].solved) results[k].errors = compare_point(r, direct);
  }
  return results;
}

nlohmann::ordered_json point_json(const SamplePoint& p, const tables::Table& t) {
  return {{"class", cell_class_name(p.cell_class)},
          {"wheel", p.wheel == 0 ? "right" : "left"},
          {"dy_m", p.dy_m},
          {t.second_axis_name, p.second},
          {"point", p.index}};
}

// Everything verify reports (the text output prints the same object).
nlohmann::ordered_json report(const VerifyOptions& o, const tables::Table& t, const CellClasses& classes,
                              const std::vector<SamplePoint>& points, const std::vector<PointResult>& results) {
  const std::array<double, kQuantities> tolerance = table_tolerances(t);
  nlohmann::ordered_json out{{"table", o.path},
                             {"samples", points.size()},
                             {"seed", o.seed},
                             {"interpolation", "linear"}};
  for (std::size_t q = 0; q < kQuantities; ++q)
    out["tolerance"][quantity_name(static_cast<Quantity>(q))] = tolerance[q];
  std::size_t exceeding = 0, failed = 0;
  double worst_ratio = 0.0;
  out["classes"] = nlohmann::ordered_json::array();
  for (std::size_t c = 0; c < kCellClasses; ++c) {
    nlohmann::ordered_json entry{{"class", cell_class_name(static_cast<CellClass>(c))}, {"cells", classes[c].size()}};
    std::vector<std::size_t> members;
    for (const SamplePoint& p : points)
      if (static_cast<std::size_t>(p.cell_class) == c) members.push_back(p.index);
    entry["points"] = members.size();
    for (std::size_t q = 0; q < kQuantities; ++q) {
      std::vector<double> errors;
      for (std::size_t k : members) errors.push_back(results[k].solved ? results[k].errors.error[q] : std::nan(""));
      const ErrorStats s = error_stats(errors, members);
      nlohmann::ordered_json stats{{"count", s.count}, {"median", s.median}, {"p95", s.p95}, {"max", s.max}};
      if (s.count > 0) stats["worst"] = point_json(points[s.worst], t);
      entry["quantities"][quantity_name(static_cast<Quantity>(q))] = stats;
    }
    out["classes"].push_back(entry);
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (!results[k].solved) {
      ++failed;
      continue;
    }
    bool exceeds = false;
    for (std::size_t q = 0; q < kQuantities; ++q) {
      const double ratio = results[k].errors.error[q] / tolerance[q];
      exceeds = exceeds || ratio > 1.0;
      if (ratio > worst_ratio) {
        worst_ratio = ratio;
        out["worst"] = point_json(points[k], t);
        out["worst"]["quantity"] = quantity_name(static_cast<Quantity>(q));
        out["worst"]["error"] = results[k].errors.error[q];
      }
    }
    exceeding += exceeds;
  }
  out["exceeding"] = exceeding;
  out["failed_solves"] = failed;
  out["pass"] = exceeding == 0 && failed == 0;
  return out;
}

// A quantity's error as printed: percent, or mm for the contact point.
double shown(const std::string& quantity, double error) {
  return quantity == "contact_point" ? error * 1e3 : 100.0 * error;
}
const char* unit(const std::string& quantity) { return quantity == "contact_point" ? "mm" : "%"; }

std::string point_text(const nlohmann::ordered_json& p, const std::string& second_name, std::uint64_t seed) {
  char text[200];
  std::snprintf(text, sizeof text, "%s wheel, dy %.6f mm, %s %g (seed %llu, point %zu)",
                p["wheel"].get<std::string>().c_str(), p["dy_m"].get<double>() * 1e3, second_name.c_str(),
                p[second_name].get<double>(), static_cast<unsigned long long>(seed), p["point"].get<std::size_t>());
  return text;
}

void print_text(const nlohmann::ordered_json& r, const tables::Table& t, std::uint64_t seed) {
  std::printf("%s: %zu points (seed %llu), linear lookup against direct solves\n",
              r["table"].get<std::string>().c_str(), r["samples"].get<std::size_t>(),
              static_cast<unsigned long long>(seed));
  std::printf("tolerance:");
  for (const auto& [name, value] : r["tolerance"].items())
    std::printf(" %s %g %s", name.c_str(), shown(name, value.get<double>()), unit(name));
  std::printf("\n%-10s %6s %-14s %6s %11s %11s %11s  worst at\n", "class", "cells", "quantity", "count", "median",
              "p95", "max");
  for (const auto& c : r["classes"]) {
    if (c["points"].get<std::size_t>() == 0) {
      std::printf("%-10s %6zu (no points)\n", c["class"].get<std::string>().c_str(), c["cells"].get<std::size_t>());
      continue;
    }
    for (const auto& [name, s] : c["quantities"].items()) {
      std::printf("%-10s %6zu %-14s %6zu", c["class"].get<std::string>().c_str(), c["cells"].get<std::size_t>(),
                  name.c_str(), s["count"].get<std::size_t>());
      for (const char* k : {"median", "p95", "max"})
        std::printf(" %8.4g %-2s", shown(name, s[k].get<double>()), unit(name));
      std::printf("  %s\n", s.contains("worst") ? point_text(s["worst"], t.second_axis_name, seed).c_str() : "-");
    }
  }
  std::printf("points beyond the tolerance: %zu; failed direct solves: %zu\n", r["exceeding"].get<std::size_t>(),
              r["failed_solves"].get<std::size_t>());
  if (r.contains("worst")) {
    const auto& w = r["worst"];
    const std::string q = w["quantity"].get<std::string>();
    std::printf("worst against its tolerance: %s %.4g %s in class %s at %s\n", q.c_str(),
                shown(q, w["error"].get<double>()), unit(q), w["class"].get<std::string>().c_str(),
                point_text(w, t.second_axis_name, seed).c_str());
  }
  std::printf("%s\n", r["pass"].get<bool>() ? "pass" : "FAIL");
}

// In a child process (isolated_read.hpp): the table may come from anywhere; the solves run once it is checked.
int run_verify(const VerifyOptions& o) {
  return run_isolated([&](IsolatedChild& child) {
           tables::Table t;
           child.reading(o.path);
           const tables::TableResult read = tables::read_table(o.path, t);
           if (!read.ok()) throw gen::Error(read.message);
           lookup::TableData data;
           throw_if_failed(lookup::from_tables(t, data));
           lookup::Table table;
           throw_if_failed(table.load(std::move(data), {CTAB_LINEAR, false}));
           child.trusted_from_here();
           const gen::SweepSetup setup = table_setup(o.path, t);
           const CellClasses classes = classify_cells(t);
           const std::vector<SamplePoint> points = draw_samples(classes, o.samples, o.seed);
           const std::vector<PointResult> results = check_points(table, setup, points, sweep_threads(o.threads));
           const nlohmann::ordered_json r = report(o, t, classes, points, results);
           if (o.json) std::cout << r.dump(1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << '\n';
           else print_text(r, t, o.seed);
           return r["pass"].get<bool>() ? kExitSuccess : kExitCaseFailed;
         })
      .exit_code;
}

}  // namespace

Command add_verify_command(CLI::App& parent) {
  auto o = std::make_shared<VerifyOptions>();
  CLI::App* app = parent.add_subcommand(
      "verify", "Check a table's lookup against direct solves at random off-grid points in every class of cell");
  app->add_option("file", o->path, "table (.h5)")->required();
  app->add_option("--samples", o->samples, "points to check, shared between the classes of cell")
      ->capture_default_str()
      ->check(CLI::Range(std::size_t{1}, std::size_t{10'000'000}));
  app->add_option("--seed", o->seed, "seed of the random points (the same seed draws the same points)")
      ->capture_default_str();
  add_threads_option(*app, o->threads);
  app->add_flag("--json", o->json, "print one JSON object");
  return {app, [o] { return run_verify(*o); }};
}

}  // namespace ctab::cli
