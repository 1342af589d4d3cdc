// `ctab bench accuracy [--out DIR] [--quick] [--reference DIR] [--wheel F --rail F --inclination I]`: every rung of the
// method ladder at several discretisations against a reference, on the Hertz sphere (analytic Hertz), the non-Hertzian
// body (bem2d at a fine mesh; CONTACT's row of the paper) and the S1002/UIC60 single wheel at 78.5 kN normal force from
// dy -6 to +8 mm (bem2d at a fine mesh on every patch, through the sweep API; CONTACT's summary where --reference has
// it and the profiles are CONTACT's: its wheel-rail cases are the Manchester files, inclination 0). Writes
// DIR/accuracy.csv (one row per scene x region x method x discretisation) and charts it with scripts/accuracy_chart.py
// into DIR/accuracy.png and .svg (exit 3 when the chart fails; the CSV stays).
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ctab/contact/bem2d.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/normal_contact.hpp"
#include "ctab/fixtures/paper_cases.hpp"
#include "ctab/sweep/accuracy_metrics.hpp"
#include "ctab/sweep/table_generator.hpp"
#include "exit_codes.hpp"
#include "setup_options.hpp"

extern char** environ;

namespace ctab::cli {

namespace {

using gen::ContactMethod;
using gen::ContactSummary;
using Clock = std::chrono::steady_clock;

constexpr double kWheelRailNormalForce_N = 78.5e3;  // paper section 3.2 and CONTACT's wheel-rail cases

//! One rung at one discretisation (strip width, or element size of bem2d) [m].
struct Rung {
  ContactMethod method;
  double width_m;
  double tolerance = 0.0;  //!< > 0: the least model (`--method auto --tolerance`), MIM-1D at widths of its choice [-]
};

//! The least model's tolerance in the wheel-rail scene (the example, README "The least model") [-].
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
    s.shifts_m = {-1e-3, 2e-3, 5e-3, 5.5e-3, 6.5e-3, 7.5e-3};  // the CONTACT cases, every region
    s.max_repeats = 2;
    s.repeat_budget_s = 0.02;
  } else {
    for (int i = -12; i <= 16; ++i) s.shifts_m.push_back(0.5e-3 * i);  // -6 ... +8 mm in 0.5 mm
    s.shifts_m.push_back(5.25e-3);
    s.shifts_m.push_back(7.25e-3);
    std::sort(s.shifts_m.begin(), s.shifts_m.end());
  }
  return s;
}

//! Contact region of a lateral shift (issue 8's ranges): tread below 4.5 mm, two-point to 5.75 mm, flange root
//! to 6.75 mm, flange flank beyond.
const char* wheelrail_region(double dy_m) {
  if (dy_m < 4.5e-3) return "tread";
  if (dy_m < 5.75e-3) return "two_point";
  if (dy_m < 6.75e-3) return "flange_root";
  return "flange_flank";
}

//! A result and its time: the minimum over repeats [s].
template <class Solve>
auto timed(const Settings& settings, Solve&& solve, double& time_s) {
  const auto start = Clock::now();
  auto result = solve();
  double total = std::chrono::duration<double>(Clock::now() - start).count();
  time_s = total;
  for (int r = 1; r < settings.max_repeats && total < settings.repeat_budget_s; ++r) {
    const auto again = Clock::now();
    result = solve();
    const double t = std::chrono::duration<double>(Clock::now() - again).count();
    time_s = std::min(time_s, t);
    total += t;
  }
  return result;
}

//! CONTACT's figures of one case: area [m^2], max pressure [Pa], centre of pressure [m] (NaN: not given).
struct ContactFigures {
  double area_m2 = 0.0, max_pressure_Pa = 0.0;
  double centre_of_pressure_m = std::numeric_limits<double>::quiet_NaN();
};

//! Worst errors of one row over its cases.
struct Row {
  std::string scene, region, method, reference;
  double width_m = 0.0;    //!< strip width / element size [m]; NaN for the least model (it chooses per case)
  double tolerance = 0.0;  //!< the least model's tolerance [-]; 0 for a fixed rung
  int cases = 0, failed = 0, contact_cases = 0;
  double time_sum_s = 0.0;
  gen::AccuracyErrors worst;
  double contact_area = 0.0, contact_pressure = 0.0, contact_point = std::numeric_limits<double>::quiet_NaN();

  void add(const ContactSummary& candidate, const ContactSummary& reference_summary, bool ok, double time_s,
           const std::optional<ContactFigures>& contact) {
    const gen::AccuracyErrors e = gen::accuracy_errors(candidate, reference_summary);
    ++cases;
    failed += ok ? 0 : 1;
    time_sum_s += time_s;
    worst.area_rel = std::max(worst.area_rel, e.area_rel);
    worst.max_pressure_rel = std::max(worst.max_pressure_rel, e.max_pressure_rel);
    worst.p0_profile_rms_rel = std::max(worst.p0_profile_rms_rel, e.p0_profile_rms_rel);
    worst.contact_point_m = std::max(worst.contact_point_m, e.contact_point_m);
    if (!contact) return;
    ++contact_cases;
    contact_area = std::max(contact_area, std::fabs(candidate.area_m2 - contact->area_m2) / contact->area_m2);
    contact_pressure = std::max(contact_pressure, std::fabs(candidate.max_pressure_Pa - contact->max_pressure_Pa) /
                                                      contact->max_pressure_Pa);
    if (std::isfinite(contact->centre_of_pressure_m)) {
      const double d = std::fabs(candidate.centre_of_pressure_m - contact->centre_of_pressure_m);
      contact_point = std::isfinite(contact_point) ? std::max(contact_point, d) : d;
    }
  }
};

using Rows = std::map<std::string, Row>;

//! The CSV's method of a rung: "auto" for the least model.
std::string rung_name(const Rung& rung) { return rung.tolerance > 0.0 ? "auto" : gen::method_name(rung.method); }

Row& row_of(Rows& rows, const std::string& scene, const std::string& region, const Rung& rung,
            const std::string& reference) {
  char key[200];
  std::snprintf(key, sizeof key, "%s/%s/%d/%.6e/%.6e", scene.c_str(), region.c_str(), static_cast<int>(rung.method),
                rung.width_m, rung.tolerance);
  Row& row = rows[key];
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

std::string reference_name(const Settings& s) {
  char name[64];
  std::snprintf(name, sizeof name, "bem2d_%gmm", s.reference_width_m * 1e3);
  return name;
}

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
void run_gap_scene(const Settings& settings, const std::string& scene, const gen::GapProfile& gap, double approach_m,
                   const ContactSummary& reference, const std::string& reference_label,
                   const std::optional<ContactFigures>& contact, Rows& rows) {
  const double E_star = gen::effective_modulus(gen::kSteel, gen::kSteel);
  for (const Rung& rung : rungs(settings.quick)) {
    gen::MethodOptions options;
    options.method = rung.method;
    options.E_star_Pa = E_star;
    options.strip_width_m = rung.width_m;
    double time_s = 0.0;
    const gen::NormalSolution solution = timed(
        settings, [&] { return gen::solve_normal_contact(gap, options, gen::Loading::approach(approach_m)); }, time_s);
    row_of(rows, scene, "all", rung, reference_label)
        .add(gen::summarise(solution), reference, gen::is_success(solution.status), time_s, contact);
    std::fprintf(stderr, "  %s %s %.2f mm: %.2e s\n", scene.c_str(), gen::method_name(rung.method), rung.width_m * 1e3,
                 time_s);
  }
}

//! bem2d reference of a strip problem: elements dy = reference width across, dx = at least 0.1 mm along the rolling
//! direction (the non-Hertzian body's potential contact, 56 x 47 mm, exceeds kBem2dMaxElementsPerSide at 0.05 mm
//! squares). Says so on stderr when the reference did not converge.
gen::NormalSolution bem2d_reference(const gen::GapProfile& gap, const Settings& settings, double approach_m) {
  gen::Bem2dGrid grid;
  grid.dy_m = settings.reference_width_m;
  grid.dx_m = std::max(settings.reference_width_m, 0.1e-3);
  gen::NormalSolution solution =
      gen::solve_bem2d_for_approach(gap, gen::effective_modulus(gen::kSteel, gen::kSteel), grid, approach_m);
  if (!gen::is_success(solution.status))
    std::fprintf(stderr, "warning: the bem2d reference of %s failed (%s): its errors are left empty\n",
                 gap.source.c_str(), gen::status_name(solution.status));
  return solution;
}

std::string gap_reference_name(const Settings& s) {
  char name[64];
  std::snprintf(name, sizeof name, "bem2d_%gx%gmm", std::max(s.reference_width_m, 0.1e-3) * 1e3,
                s.reference_width_m * 1e3);
  return name;
}

//! The sweep set-up of one rung: the default config with the bench's profiles as a single wheel at 78.5 kN normal
//! force.
gen::SweepSetup wheelrail_setup(const gen::TableConfig& profiles, const Rung& rung) {
  gen::TableConfig config = profiles;
  config.mode = gen::ContactMode::SingleWheel;
  config.load_kind = gen::LoadKind::NormalForce;
  config.load_values = {kWheelRailNormalForce_N};
  config.method = rung.method;
  config.strip_width_m = rung.width_m;
  config.least_model = rung.tolerance > 0.0;
  if (config.least_model) config.tolerance = rung.tolerance;
  return gen::make_sweep_setup(config);
}

gen::WheelContact solve_right_wheel(const gen::SweepSetup& setup, double dy_m) {
  return gen::solve_table_case(setup, dy_m, kWheelRailNormalForce_N, {true, false}).wheels[0].contact;
}

//! CONTACT's wheel-rail rows (one per patch; columns dy_mm, area_mm2, pmax_MPa, FN_N, y_cop_rail_mm) summed per
//! lateral shift [mm, rounded to um]. Throws InputError naming the file and line.
void read_contact_csv(const std::filesystem::path& path, std::map<long, ContactFigures>& cases) {
  std::ifstream file(path);
  if (!file) throw gen::InputError(path.string(), 0, "cannot be read (expected CONTACT's wheel-rail summary CSV)");
  std::string line;
  std::getline(file, line);
  std::vector<std::string> header;
  for (std::stringstream ss(line); std::getline(ss, line, ',');) header.push_back(line);
  const auto column = [&](const char* name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw gen::InputError(path.string(), 1, std::string("expected a column '") + name + "'");
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t c_dy = column("dy_mm"), c_area = column("area_mm2"), c_p = column("pmax_MPa"),
                    c_fn = column("FN_N"), c_cop = column("y_cop_rail_mm");
  std::map<long, double> weighted;
  for (std::size_t number = 2; std::getline(file, line); ++number) {
    if (line.empty()) continue;
    std::vector<double> v;
    try {
      for (std::stringstream ss(line); std::getline(ss, line, ',');) v.push_back(std::stod(line));
    } catch (const std::exception&) {
      throw gen::InputError(path.string(), number, "expected numbers separated by commas");
    }
    if (v.size() < header.size())
      throw gen::InputError(path.string(), number, "expected " + std::to_string(header.size()) + " columns");
    const long key = std::lround(v[c_dy] * 1e3);
    ContactFigures& f = cases[key];
    if (!weighted.count(key)) f.centre_of_pressure_m = 0.0;
    f.area_m2 += v[c_area] * 1e-6;
    f.max_pressure_Pa = std::max(f.max_pressure_Pa, v[c_p] * 1e6);
    weighted[key] += v[c_fn];
    f.centre_of_pressure_m += v[c_fn] * v[c_cop] * 1e-3;
  }
  for (auto& [key, force] : weighted) cases[key].centre_of_pressure_m /= force;
}

std::map<long, ContactFigures> read_contact_reference(const std::optional<std::string>& dir) {
  std::map<long, ContactFigures> cases;
  if (!dir) return cases;
  const std::filesystem::path root(*dir);
  read_contact_csv(root / "wheelrail" / "summary.csv", cases);
  read_contact_csv(root / "wheelrail" / "flange" / "planar_normal_force.csv", cases);
  return cases;
}

void run_wheelrail_scene(const Settings& settings, const gen::TableConfig& profiles,
                         const std::map<long, ContactFigures>& contact, Rows& rows) {
  const gen::SweepSetup reference_setup =
      wheelrail_setup(profiles, Rung{ContactMethod::Bem2d, settings.reference_width_m});
  std::vector<ContactSummary> reference;
  for (const double dy : settings.shifts_m) {
    const gen::WheelContact solved = solve_right_wheel(reference_setup, dy);
    if (!gen::is_success(solved.status))
      std::fprintf(stderr, "warning: the bem2d reference at dy = %g mm failed (%s): %s\n", dy * 1e3,
                   gen::status_name(solved.status), solved.detail.c_str());
    reference.push_back(gen::summarise(solved));
  }
  std::fprintf(stderr, "  wheelrail reference (%s) done\n", reference_name(settings).c_str());
  std::vector<Rung> wheelrail_rungs = rungs(settings.quick);
  // The least model, wheel-rail only (least_model.hpp); its width is the config's unused default.
  wheelrail_rungs.push_back({ContactMethod::Mim1d, 0.2e-3, kLeastModelTolerance});
  for (const Rung& rung : wheelrail_rungs) {
    const gen::SweepSetup setup = wheelrail_setup(profiles, rung);
    double total_s = 0.0;
    for (std::size_t i = 0; i < settings.shifts_m.size(); ++i) {
      const double dy = settings.shifts_m[i];
      double time_s = 0.0;
      const gen::WheelContact result = timed(
          settings, [&] { return solve_right_wheel(setup, dy); }, time_s);
      const auto found = contact.find(std::lround(dy * 1e6));
      const std::optional<ContactFigures> figures =
          found == contact.end() ? std::nullopt : std::optional<ContactFigures>(found->second);
      row_of(rows, "wheelrail", wheelrail_region(dy), rung, reference_name(settings))
          .add(gen::summarise(result), reference[i], gen::is_success(result.status), time_s, figures);
      total_s += time_s;
    }
    char discretisation[32];  // the least model chooses its width per case: its tolerance instead
    if (rung.tolerance > 0.0) std::snprintf(discretisation, sizeof discretisation, "T %g %%", rung.tolerance * 100);
    else std::snprintf(discretisation, sizeof discretisation, "%.2f mm", rung.width_m * 1e3);
    std::fprintf(stderr, "  wheelrail %s %s: %.2e s per case\n", rung_name(rung).c_str(), discretisation,
                 total_s / static_cast<double>(settings.shifts_m.size()));
  }
}

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v);
  return text;
}

void write_csv(const std::filesystem::path& path, const Rows& rows) {
  std::ofstream out(path);
  out << "scene,region,method,discretisation_m,reference,cases,failed_cases,time_per_case_s,area_error_rel,"
         "max_pressure_error_rel,p0_profile_rms_error_rel,contact_point_error_m,error_rel,contact_cases,"
         "vs_contact_area_error_rel,vs_contact_max_pressure_error_rel,vs_contact_point_error_m,tolerance\n";
  for (const auto& [key, r] : rows) {
    const double worst = std::max({r.worst.area_rel, r.worst.max_pressure_rel, r.worst.p0_profile_rms_rel});
    const bool has_contact = r.contact_cases > 0;
    out << r.scene << ',' << r.region << ',' << r.method << ',' << number(r.width_m) << ',' << r.reference << ','
        << r.cases << ',' << r.failed << ',' << number(r.time_sum_s / r.cases) << ',' << number(r.worst.area_rel) << ','
        << number(r.worst.max_pressure_rel) << ',' << number(r.worst.p0_profile_rms_rel) << ','
        << number(r.worst.contact_point_m) << ',' << number(worst) << ',' << r.contact_cases << ','
        << (has_contact ? number(r.contact_area) : "") << ',' << (has_contact ? number(r.contact_pressure) : "") << ','
        << (has_contact ? number(r.contact_point) : "") << ',' << (r.tolerance > 0.0 ? number(r.tolerance) : "")
        << '\n';
  }
  out.flush();
  if (!out) throw IoError(path.string() + ": cannot be written");
}

//! The chart script: the source tree's scripts/ (CTAB_SCRIPTS_DIR), else the working directory's.
std::filesystem::path chart_script() {
  const std::filesystem::path built = std::filesystem::path(CTAB_SCRIPTS_DIR) / "accuracy_chart.py";
  if (std::filesystem::exists(built)) return built;
  return std::filesystem::path("scripts") / "accuracy_chart.py";
}

//! Runs /usr/bin/python3 SCRIPT CSV PREFIX; its exit code (-1 when it could not start or was killed).
int run_chart(const std::filesystem::path& csv, const std::filesystem::path& prefix) {
  std::vector<std::string> args = {"/usr/bin/python3", chart_script().string(), csv.string(), prefix.string()};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

//! CONTACT's wheel-rail cases (`../shared/reference/contact/wheelrail/`) are the Manchester files (MBench_S1002_v3.prw
//! on MBench_UIC60_v3.prr, already inclined): compared with other profiles (the built-in S1002/UIC60 1:40 place the
//! two-point contact differently: 22 % in area at dy 5 mm) they would measure the profiles, not the methods.
bool contact_profiles(const gen::TableConfig& profiles) {
  const auto file_name = [](const std::string& path) { return std::filesystem::path(path).filename().string(); };
  return file_name(profiles.wheel) == "MBench_S1002_v3.prw" && file_name(profiles.rail) == "MBench_UIC60_v3.prr" &&
         profiles.inclination == 0.0;
}

int run_bench_accuracy(const std::string& out_dir, bool quick, const std::optional<std::string>& reference_dir,
                       const gen::TableConfig& profiles) {
  const Settings settings = make_settings(quick);
  const std::map<long, ContactFigures> contact = read_contact_reference(reference_dir);
  const bool compare_wheelrail = contact_profiles(profiles);
  if (reference_dir && !compare_wheelrail)
    std::fprintf(stderr,
                 "note: CONTACT's wheel-rail cases use the Manchester files (--wheel .../MBench_S1002_v3.prw --rail "
                 ".../MBench_UIC60_v3.prr --inclination 0); with these profiles the wheel-rail scene is compared "
                 "with bem2d only\n");
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) throw IoError(out_dir + ": cannot create the output directory (" + error.message() + ")");
  Rows rows;
  const double E_star = gen::effective_modulus(gen::kSteel, gen::kSteel);
  std::fprintf(stderr, "Hertz sphere (reference: analytic Hertz)\n");
  run_gap_scene(settings, "hertz_sphere", gen::paper::hertz_sphere_gap(), gen::paper::kApproach_m,
                hertz_sphere_reference(gen::paper::kSphereRadius_m, gen::paper::kApproach_m, E_star), "hertz_analytic",
                std::nullopt, rows);
  std::fprintf(stderr, "Non-Hertzian body (reference: %s)\n", gap_reference_name(settings).c_str());
  const gen::GapProfile nonhertz = gen::paper::nonhertz_gap();
  const ContactFigures nonhertz_contact{gen::paper::kNonHertzContactArea_m2,
                                        gen::paper::kNonHertzContactMaxPressure_Pa};
  run_gap_scene(settings, "nonhertz", nonhertz, gen::paper::kApproach_m,
                gen::summarise(bem2d_reference(nonhertz, settings, gen::paper::kApproach_m)),
                gap_reference_name(settings), nonhertz_contact, rows);
  std::fprintf(stderr, "%s on %s, single wheel, 78.5 kN, %zu shifts (reference: %s)\n", profiles.wheel.c_str(),
               profiles.rail.c_str(), settings.shifts_m.size(), reference_name(settings).c_str());
  run_wheelrail_scene(settings, profiles, compare_wheelrail ? contact : std::map<long, ContactFigures>{}, rows);
  const std::filesystem::path csv = std::filesystem::path(out_dir) / "accuracy.csv";
  write_csv(csv, rows);
  std::printf("wrote %s (%zu rows)\n", csv.c_str(), rows.size());
  const std::filesystem::path prefix = std::filesystem::path(out_dir) / "accuracy";
  const int chart = run_chart(csv, prefix);
  if (chart != 0) {
    std::fprintf(stderr, "error: the chart failed (/usr/bin/python3 %s exited %d); %s is kept\n",
                 chart_script().c_str(), chart, csv.c_str());
    return kExitIo;
  }
  std::printf("wrote %s.png and %s.svg\n", prefix.c_str(), prefix.c_str());
  return kExitSuccess;
}

}  // namespace

Command add_bench_accuracy_subcommand(CLI::App& bench) {
  auto out = std::make_shared<std::string>("accuracy");
  auto quick = std::make_shared<bool>(false);
  auto reference = std::make_shared<std::string>();
  auto profiles = std::make_shared<gen::TableConfig>(default_table_config());
  CLI::App* app =
      bench.add_subcommand("accuracy",
                           "Every method at several discretisations against a reference: error against time per case");
  app->add_option("--out", *out, "output directory for accuracy.csv, .png, .svg (default ./accuracy)");
  app->add_flag("--quick", *quick, "fewer shifts, a coarser reference (about a minute; what the tests run)");
  app->add_option(
      "--reference", *reference,
      "CONTACT reference directory (wheelrail/summary.csv, wheelrail/flange/planar_normal_force.csv); its "
      "wheel-rail cases are compared when the profiles are CONTACT's (the Manchester files, inclination 0)");
  (void)add_setup_options(*app, *profiles, kProfiles);
  return {app, [out, quick, reference, profiles] {
            finish_setup_options(*profiles);
            return run_bench_accuracy(*out, *quick,
                                      reference->empty() ? std::nullopt : std::optional<std::string>(*reference),
                                      *profiles);
          }};
}

}  // namespace ctab::cli
