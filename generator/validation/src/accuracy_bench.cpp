// SPDX-License-Identifier: Apache-2.0
// The accuracy bench (accuracy_bench.hpp): its settings, scenes and references.
#include "ctab/validation/accuracy_bench.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "bench_text.hpp"
#include "ctab/contact/bem2d.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/normal_contact.hpp"
#include "ctab/fixtures/paper_cases.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "ctab/validation/reference_csv.hpp"

namespace ctab::gen {

namespace {

//! Adds CONTACT's wheel-rail rows of one file (columns dy_mm, area_mm2, pmax_MPa, FN_N, y_cop_rail_mm).
void add_contact_csv(const std::string& path, ContactCases& cases) {
  const CsvTable table = read_csv(path);
  const std::vector<double> dy = table.numbers("dy_mm"), area = table.numbers("area_mm2"),
                            pmax = table.numbers("pmax_MPa"), force = table.numbers("FN_N"),
                            cop = table.numbers("y_cop_rail_mm");
  std::map<long, double> weighted;
  for (std::size_t i = 0; i < dy.size(); ++i) {
    const long key = std::lround(dy[i] * 1e3);
    ContactFigures& f = cases[key];
    if (!weighted.count(key)) f.centre_of_pressure_m = 0.0;
    f.area_m2 += area[i] * 1e-6;
    f.max_pressure_Pa = std::max(f.max_pressure_Pa, pmax[i] * 1e6);
    weighted[key] += force[i];
    f.centre_of_pressure_m += force[i] * cop[i] * 1e-3;
  }
  for (auto& [key, sum] : weighted) cases[key].centre_of_pressure_m /= sum;
}

}  // namespace

ContactCases read_contact_wheelrail(const std::string& dir) {
  ContactCases cases;
  const std::filesystem::path root(dir);
  add_contact_csv((root / "wheelrail" / "summary.csv").string(), cases);
  add_contact_csv((root / "wheelrail" / "flange" / "planar_normal_force.csv").string(), cases);
  return cases;
}

namespace {

using Clock = std::chrono::steady_clock;

constexpr double kWheelRailNormalForce_N = 78.5e3;  // paper section 3.2 and CONTACT's wheel-rail cases

//! One rung at one discretisation (strip width, or element size of bem2d) [m].
struct Rung {
  ContactMethod method;
  double width_m;
  double tolerance = 0.0;  //!< > 0: the least model (`--method auto --tolerance`), MIM-1D at widths of its choice [-]
};

//! The least model's tolerance in the wheel-rail scene (the example, docs/validation.md "The least model") [-].
constexpr double kLeastModelTolerance = 0.02;

std::vector<Rung> rungs(bool quick) {
  std::vector<Rung> r;
  r.push_back({ContactMethod::Hertz, 0.1e-3});  // one ellipse; the width only samples its p0 profile
  for (const ContactMethod m : {ContactMethod::Kp, ContactMethod::Analyn, ContactMethod::Mim1d})
    for (const double w : {0.4e-3, 0.2e-3, 0.1e-3}) r.push_back({m, w});
  r.push_back({ContactMethod::Bem2d, 0.2e-3});
  if (!quick) r.push_back({ContactMethod::Bem2d, 0.1e-3});
  return r;
}

//! Settings of a run: quick is the test's (fewer shifts, a coarser reference, fewer repeats).
struct Settings {
  bool quick = false;
  double reference_width_m = 0.05e-3;  //!< bem2d element size of the reference [m]
  std::vector<double> shifts_m;        //!< wheel-rail lateral shifts [m]
  int max_repeats = 5;                 //!< repeats of a timed case (time = minimum) [-]
  double repeat_budget_s = 0.3;        //!< no further repeat once a case has taken this long in all [s]
};

Settings make_settings(bool quick) {
  Settings s;
  s.quick = quick;
  if (quick) {
    s.reference_width_m = 0.1e-3;
    s.shifts_m = {-1e-3, 2e-3, 5e-3, 5.5e-3, 6.5e-3, 6.8e-3, 7.5e-3};  // the CONTACT cases and the knee
    s.max_repeats = 2;
    s.repeat_budget_s = 0.02;
  } else {
    for (int i = -12; i <= 16; ++i) s.shifts_m.push_back(0.5e-3 * i);  // -6 ... +8 mm in 0.5 mm
    for (const double dy : {5.25e-3, 6.6e-3, 6.7e-3, 6.8e-3, 6.9e-3, 7.25e-3}) s.shifts_m.push_back(dy);
    std::sort(s.shifts_m.begin(), s.shifts_m.end());
  }
  return s;
}

//! Contact region of a lateral shift: tread below 4.5 mm, two-point to 5.75 mm, flange root to 6.55 mm, the knee
//! (the contact climbing from the root onto the flank, where MIM-1D's strip model is off most: least_model.hpp; no
//! CONTACT case) to 7.1 mm, flange flank beyond.
const char* wheelrail_region(double dy_m) {
  if (dy_m < 4.5e-3) return "tread";
  if (dy_m < 5.75e-3) return "two_point";
  if (dy_m < 6.55e-3) return "flange_root";
  if (dy_m < 7.1e-3) return "knee";
  return "flange_flank";
}

//! A result and the times of its repeats [s] (the case's time is their minimum).
template <class Solve>
auto timed(const Settings& settings, Solve&& solve, std::vector<double>& times_s) {
  times_s.clear();
  const auto start = Clock::now();
  auto result = solve();
  times_s.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  double total = times_s.back();
  for (int r = 1; r < settings.max_repeats && total < settings.repeat_budget_s; ++r) {
    const auto again = Clock::now();
    result = solve();
    times_s.push_back(std::chrono::duration<double>(Clock::now() - again).count());
    total += times_s.back();
  }
  return result;
}

//! Rows by key: scene, region, method, discretisation (the CSV's order).
using Rows = std::map<std::string, AccuracyRow>;

//! The CSV's method of a rung: "auto" for the least model.
std::string rung_name(const Rung& rung) { return rung.tolerance > 0.0 ? "auto" : method_name(rung.method); }

AccuracyRow& row_of(Rows& rows, const std::string& scene, const std::string& region, const Rung& rung,
                    const std::string& reference) {
  char key[200];
  std::snprintf(key, sizeof key, "%s/%s/%d/%.6e/%.6e", scene.c_str(), region.c_str(), static_cast<int>(rung.method),
                rung.width_m, rung.tolerance);
  AccuracyRow& row = rows[key];
  if (row.scene.empty()) {
    row.scene = scene;
    row.region = region;
    row.method = rung_name(rung);
    row.reference = reference;
    row.width_m = rung.tolerance > 0.0 ? std::numeric_limits<double>::quiet_NaN() : rung.width_m;
    row.tolerance = rung.tolerance;
  }
  return row;
}

std::string reference_name(const Settings& s) { return detail::bem2d_reference_name(s.reference_width_m); }

//! Analytic Hertz for a sphere of radius R on a flat at approach delta: a = sqrt(R delta), p_max = 2 E* a / (pi R),
//! p0(y) = p_max sqrt(1 - y^2/a^2) (Johnson 1985, section 4.2), sampled every 10 um.
ContactSummary hertz_sphere_reference(double radius_m, double approach_m, double E_star_Pa) {
  const double a = std::sqrt(radius_m * approach_m), p_max = 2.0 * E_star_Pa * a / (M_PI * radius_m);
  ContactSummary s;
  s.area_m2 = M_PI * a * a;
  s.max_pressure_Pa = p_max;
  s.normal_force_N = 2.0 / 3.0 * p_max * s.area_m2;
  auto& profile = s.profiles.emplace_back();
  for (double y = -a + 5e-6; y < a; y += 10e-6) profile.push_back({y, p_max * std::sqrt(1.0 - y * y / (a * a))});
  return s;
}

//! One strip-problem scene: every rung at a prescribed approach against `reference`.
void run_gap_scene(const Settings& settings, const std::string& scene, const GapProfile& gap, double approach_m,
                   const ContactSummary& reference, const std::string& reference_label,
                   const std::optional<ContactFigures>& contact, Rows& rows) {
  const double E_star = effective_modulus(kSteel, kSteel);
  for (const Rung& rung : rungs(settings.quick)) {
    MethodOptions options;
    options.method = rung.method;
    options.E_star_Pa = E_star;
    options.strip_width_m = rung.width_m;
    std::vector<double> times_s;
    const NormalSolution solution = timed(
        settings, [&] { return solve_normal_contact(gap, options, Loading::approach(approach_m)); }, times_s);
    row_of(rows, scene, "all", rung, reference_label)
        .add(summarise(solution), reference, is_success(solution.status), times_s, contact);
    std::fprintf(stderr, "  %s %s %.2f mm: %.2e s\n", scene.c_str(), method_name(rung.method), rung.width_m * 1e3,
                 *std::min_element(times_s.begin(), times_s.end()));
  }
}

//! bem2d reference of a strip problem: elements dy = reference width across, dx = at least 0.1 mm along the rolling
//! direction (the non-Hertzian body's potential contact, 56 x 47 mm, exceeds kBem2dMaxElementsPerSide at 0.05 mm
//! squares). Says so on stderr when the reference did not converge.
NormalSolution bem2d_reference(const GapProfile& gap, const Settings& settings, double approach_m) {
  Bem2dGrid grid;
  grid.dy_m = settings.reference_width_m;
  grid.dx_m = std::max(settings.reference_width_m, 0.1e-3);
  NormalSolution solution = solve_bem2d_for_approach(gap, effective_modulus(kSteel, kSteel), grid, approach_m);
  if (!is_success(solution.status))
    std::fprintf(stderr, "warning: the bem2d reference of %s failed (%s): its errors are left empty\n",
                 gap.source.c_str(), status_name(solution.status));
  return solution;
}

std::string gap_reference_name(const Settings& s) {
  char name[64];
  std::snprintf(name, sizeof name, "bem2d_%gx%gmm", std::max(s.reference_width_m, 0.1e-3) * 1e3,
                s.reference_width_m * 1e3);
  return name;
}

//! The sweep set-up of one rung: the bench's profiles as a single wheel at 78.5 kN normal force.
SweepSetup wheelrail_setup(const TableConfig& profiles, const Rung& rung) {
  TableConfig config = profiles;
  config.mode = ContactMode::SingleWheel;
  config.load_kind = LoadKind::NormalForce;
  config.load_values = {kWheelRailNormalForce_N};
  config.method = rung.method;
  config.strip_width_m = rung.width_m;
  config.least_model = rung.tolerance > 0.0;
  if (config.least_model) config.tolerance = rung.tolerance;
  SweepSetup setup = make_sweep_setup(config);
  setup.refine_under_resolved = false;  // each rung at its own strip width
  return setup;
}

WheelContact solve_right_wheel(const SweepSetup& setup, double dy_m) {
  return solve_table_case(setup, dy_m, kWheelRailNormalForce_N, {true, false}).wheels[0].contact;
}

//! The bem2d reference of every shift of the wheel-rail scene.
std::vector<ContactSummary> wheelrail_reference(const Settings& settings, const TableConfig& profiles) {
  const SweepSetup setup = wheelrail_setup(profiles, Rung{ContactMethod::Bem2d, settings.reference_width_m});
  std::vector<ContactSummary> reference;
  for (const double dy : settings.shifts_m) {
    const WheelContact solved = solve_right_wheel(setup, dy);
    if (!is_success(solved.status))
      std::fprintf(stderr, "warning: the bem2d reference at dy = %g mm failed (%s): %s\n", dy * 1e3,
                   status_name(solved.status), solved.detail.c_str());
    reference.push_back(summarise(solved));
  }
  std::fprintf(stderr, "  wheelrail reference (%s) done\n", reference_name(settings).c_str());
  return reference;
}

void run_wheelrail_scene(const Settings& settings, const TableConfig& profiles, const ContactCases& contact,
                         Rows& rows) {
  const std::vector<ContactSummary> reference = wheelrail_reference(settings, profiles);
  std::vector<Rung> wheelrail_rungs = rungs(settings.quick);
  // The least model, wheel-rail only (least_model.hpp); its width is the config's unused default.
  wheelrail_rungs.push_back({ContactMethod::Mim1d, 0.2e-3, kLeastModelTolerance});
  for (const Rung& rung : wheelrail_rungs) {
    const SweepSetup setup = wheelrail_setup(profiles, rung);
    double total_s = 0.0;
    for (std::size_t i = 0; i < settings.shifts_m.size(); ++i) {
      const double dy = settings.shifts_m[i];
      std::vector<double> times_s;
      const WheelContact result = timed(
          settings, [&] { return solve_right_wheel(setup, dy); }, times_s);
      const auto found = contact.find(std::lround(dy * 1e6));
      const std::optional<ContactFigures> figures =
          found == contact.end() ? std::nullopt : std::optional<ContactFigures>(found->second);
      row_of(rows, "wheelrail", wheelrail_region(dy), rung, reference_name(settings))
          .add(summarise(result), reference[i], is_success(result.status), times_s, figures);
      total_s += *std::min_element(times_s.begin(), times_s.end());
    }
    char discretisation[32];  // the least model chooses its width per case: its tolerance instead
    if (rung.tolerance > 0.0) std::snprintf(discretisation, sizeof discretisation, "T %g %%", rung.tolerance * 100);
    else std::snprintf(discretisation, sizeof discretisation, "%.2f mm", rung.width_m * 1e3);
    std::fprintf(stderr, "  wheelrail %s %s: %.2e s per case\n", rung_name(rung).c_str(), discretisation,
                 total_s / static_cast<double>(settings.shifts_m.size()));
  }
}

}  // namespace

bool contact_profiles(const TableConfig& profiles) {
  const auto file_name = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
  return file_name(profiles.wheel) == "MBench_S1002_v3.prw" && file_name(profiles.rail) == "MBench_UIC60_v3.prr" &&
         profiles.inclination == 0.0;
}

std::vector<AccuracyRow> run_accuracy_bench(const AccuracyBenchOptions& options) {
  const Settings settings = make_settings(options.quick);
  const TableConfig& profiles = options.profiles;
  const bool compare_wheelrail = options.contact && contact_profiles(profiles);
  if (options.contact && !compare_wheelrail)
    std::fprintf(stderr,
                 "note: CONTACT's wheel-rail cases use the Manchester files (--wheel .../MBench_S1002_v3.prw --rail "
                 ".../MBench_UIC60_v3.prr --inclination 0); with these profiles the wheel-rail scene is compared "
                 "with bem2d only\n");
  Rows rows;
  const double E_star = effective_modulus(kSteel, kSteel);
  std::fprintf(stderr, "Hertz sphere (reference: analytic Hertz)\n");
  run_gap_scene(settings, "hertz_sphere", paper::hertz_sphere_gap(), paper::kApproach_m,
                hertz_sphere_reference(paper::kSphereRadius_m, paper::kApproach_m, E_star), "hertz_analytic",
                std::nullopt, rows);
  std::fprintf(stderr, "Non-Hertzian body (reference: %s)\n", gap_reference_name(settings).c_str());
  const GapProfile nonhertz = paper::nonhertz_gap();
  const ContactFigures nonhertz_contact{paper::kNonHertzContactArea_m2, paper::kNonHertzContactMaxPressure_Pa};
  run_gap_scene(settings, "nonhertz", nonhertz, paper::kApproach_m,
                summarise(bem2d_reference(nonhertz, settings, paper::kApproach_m)), gap_reference_name(settings),
                nonhertz_contact, rows);
  std::fprintf(stderr, "%s on %s, single wheel, 78.5 kN, %zu shifts (reference: %s)\n", profiles.wheel.c_str(),
               profiles.rail.c_str(), settings.shifts_m.size(), reference_name(settings).c_str());
  run_wheelrail_scene(settings, profiles, compare_wheelrail ? *options.contact : ContactCases{}, rows);
  std::vector<AccuracyRow> ordered;
  for (auto& [key, row] : rows) ordered.push_back(std::move(row));
  return ordered;
}

}  // namespace ctab::gen
