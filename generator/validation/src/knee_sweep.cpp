// SPDX-License-Identifier: Apache-2.0
// The knee sweep (knee_sweep.hpp): the cases, in parallel.
#include "ctab/validation/knee_sweep.hpp"

#include <omp.h>

#include <chrono>
#include <cstdio>

#include "ctab/sweep/table_generator.hpp"

namespace ctab::gen {

namespace {

SweepSetup knee_setup(const KneeSweepOptions& options, bool reference) {
  TableConfig config = options.profiles;
  config.mode = ContactMode::SingleWheel;
  config.load_kind = LoadKind::VerticalForce;
  config.load_values = options.vertical_loads_N;
  config.warm_start = false;
  config.least_model = !reference && options.candidate_tolerance > 0.0;
  config.method = reference ? ContactMethod::Bem2d : options.candidate_method;
  config.strip_width_m = reference ? options.reference_width_m : options.candidate_width_m;
  if (config.least_model) config.tolerance = options.candidate_tolerance;
  SweepSetup setup = make_sweep_setup(config);
  if (reference) setup.options.bem2d_element_length_m = options.reference_length_m;
  return setup;
}

// The right wheel of one case and its solve time [s].
CaseWheel solve_timed(const SweepSetup& setup, double dy_m, double load_N, double& time_s) {
  const auto start = std::chrono::steady_clock::now();
  CaseWheel wheel = solve_table_case(setup, dy_m, load_N, {true, false}).wheels[0];
  time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return wheel;
}

}  // namespace

std::vector<KneeRow> run_knee_sweep(const KneeSweepOptions& options) {
  const SweepSetup candidate = knee_setup(options, false), reference = knee_setup(options, true);
  const std::size_t shifts = options.shifts_m.size(), cases = shifts * options.vertical_loads_N.size();
  std::vector<std::vector<KneeRow>> per_case(cases);
  int done = 0;
#pragma omp parallel for schedule(dynamic)
  for (std::size_t k = 0; k < cases; ++k) {
    const double dy = options.shifts_m[k % shifts], load = options.vertical_loads_N[k / shifts];
    double candidate_s = 0.0, reference_s = 0.0;
    const CaseWheel c = solve_timed(candidate, dy, load, candidate_s);
    const CaseWheel r = solve_timed(reference, dy, load, reference_s);
    per_case[k] = compare_patches(c.contact, r.contact);
    for (KneeRow& row : per_case[k]) {
      row.dy_m = dy;
      row.vertical_load_N = load;
      row.choice = c.choice;
      row.candidate_time_s = candidate_s;
      row.reference_time_s = reference_s;
    }
#pragma omp critical
    if (++done % 50 == 0) std::fprintf(stderr, "  %d of %zu cases\n", done, cases);
  }
  std::vector<KneeRow> rows;
  for (auto& c : per_case) rows.insert(rows.end(), c.begin(), c.end());
  return rows;
}

}  // namespace ctab::gen
